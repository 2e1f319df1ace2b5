// Feature line colour with an antialiased rim one pixel wide.
in vec3 vColour;
in float vAcross;
flat in float vHalfWidth;
out vec4 fragColor;
void main() {
  float alpha = clamp(vHalfWidth - abs(vAcross), 0.0, 1.0);
  if (alpha <= 0.0) discard;
  fragColor = vec4(vColour, alpha);
}
