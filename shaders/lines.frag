// Feature line colour with an antialiased rim one pixel wide. SKETCHY strokes taper over
// their first and last few pixels and press harder or lighter along their length. DASHED
// (hidden lines) leaves gaps: dashes 6 pixels long every 10, lighter than the visible lines.
in vec3 vColour;
in float vAcross;
flat in float vHalfWidth;
#ifdef DASHED
in float vDash;
#endif
#ifdef SKETCHY
in float vAlong;
flat in float vLength;
flat in vec2 vPressure;
#endif
out vec4 fragColor;
void main() {
  float halfWidth = vHalfWidth;
  float ink = 1.0;
#ifdef SKETCHY
  float t = clamp(vAlong / max(vLength, 1e-3), 0.0, 1.0);
  float pressure = mix(vPressure.x, vPressure.y, t);
  // Tapers over up to 6 pixels (a third of a short stroke) at each end.
  float taperPixels = min(6.0, vLength / 3.0);
  float taper = smoothstep(0.0, 1.0, min(vAlong, vLength - vAlong) / max(taperPixels, 1e-3));
  halfWidth = 0.5 + (vHalfWidth - 0.5) * mix(0.35, 1.0, pressure) * taper;
  ink = pressure;
#endif
#ifdef DASHED
  if (mod(vDash, 10.0) > 6.0) discard;
  ink *= 0.6;
#endif
  float alpha = clamp(halfWidth - abs(vAcross), 0.0, 1.0) * ink;
  if (alpha <= 0.0) discard;
  fragColor = vec4(vColour, alpha);
}
