// Feature line colour with an antialiased rim one pixel wide. SKETCHY strokes taper over
// their first and last few pixels and press harder or lighter along their length. DASHED
// leaves gaps along the stroke: dashes uDash.x pixels long every uDash.x + uDash.y (hidden
// lines: 6 in 10 by default). TAPERED narrows the stroke to points over uTaper pixels at its
// ends. TEXTURED multiplies the ink by a texture stretched along the stroke (a brush, or the
// user's image). uInk lightens (the hidden lines of the base style). OCCLUSION_LIMIT (hidden
// parts, a set's occlusion=LEVEL) leaves out what lines.vert found behind the limit layer.
#ifdef TONE_COLOUR
// colour=tone: the average colour of the palette entry the lit tone matches.
#include "palette.glsl"
uniform vec3 uEntryColour[PALETTE_SIZE];
in vec3 vLit;
#endif
in vec3 vColour;
flat in float vInk;
noperspective in vec2 vJoint, vJointAlong, vJointAcross, vJointInside;
flat in vec2 vNeighbourLength;
flat in float vDot;
noperspective in float vDotAlong;
in float vAcross;
flat in float vHalfWidth;
#ifdef DASHED
in float vDash;
#endif
#if defined(TAPERED) || defined(TEXTURED)
in float vArc;
flat in float vChain;   // negative: a closed loop, with no ends
#endif
#ifdef TAPERED
uniform float uTaper;  // pixels at each end
#endif
#ifdef TEXTURED
flat in float vWay;
uniform sampler2D uStrokeTexture;  // coverage: columns along the stroke, rows across it
#endif
#ifdef SKETCHY
in float vAlong;
flat in float vLength;
flat in vec2 vPressure;
#endif
uniform float uInk;
#ifdef OCCLUSION_LIMIT
in float vBeyondLimit;  // 1 at an end behind the limit layer (lines.vert), interpolated between
#endif
#ifdef DASHED
uniform vec2 uDash;
#endif
out vec4 fragColor;
// At one joint: a cap's pixel (past this segment's end, inside < 0) on the neighbour's side of
// the joint's cut (side < 0), where the neighbour's quad (as wide as this one) covers it, is
// the neighbour's to draw (lines.vert). Only caps: where the neighbour fails the depth test
// (the line goes behind a surface) a cut into this segment's own length would open a gap.
bool neighbourDraws(float side, float inside, float along, float across, float neighbourLength) {
  return side < 0.0 && inside < 0.0 && abs(across) < vHalfWidth && along > 0.5 - vHalfWidth && along < neighbourLength + vHalfWidth - 0.5;
}
void main() {
  float halfWidth = vHalfWidth;
  float ink = uInk * vInk;
#ifdef SKETCHY
  float t = clamp(vAlong / max(vLength, 1e-3), 0.0, 1.0);
  float pressure = mix(vPressure.x, vPressure.y, t);
  // Tapers over up to 6 pixels (a third of a short stroke) at each end.
  float taperPixels = min(6.0, vLength / 3.0);
  float taper = smoothstep(0.0, 1.0, min(vAlong, vLength - vAlong) / max(taperPixels, 1e-3));
  halfWidth = 0.5 + (vHalfWidth - 0.5) * mix(0.35, 1.0, pressure) * taper;
  ink = pressure * vInk;
#endif
#ifdef DASHED
  if (mod(vDash, uDash.x + uDash.y) > uDash.x) discard;
#endif
#ifdef TAPERED
  // To a point at both ends of the stroke; a stroke shorter than two tapers is a spindle.
  if (vChain > 0.0) {
    float taperPixels = max(min(uTaper, 0.5 * vChain), 1e-3);
    halfWidth *= clamp(min(vArc, vChain - vArc) / taperPixels, 0.0, 1.0);
  }
#endif
#ifdef TEXTURED
  // Stretched once along the chain from end to end, as a brush drawn along it (a loop's ends
  // meet at its seam); the rows span the line's width.
  float along = clamp(vArc / max(abs(vChain), 1e-3), 0.0, 1.0);
  // Across: the same side of the chain for every segment, whichever way it was stored.
  ink *= texture(uStrokeTexture, vec2(along, 0.5 + 0.5 * vWay * vAcross / max(halfWidth, 1e-3))).r;
#endif
#ifdef OCCLUSION_LIMIT
  if (vBeyondLimit > 0.5) discard;
#endif
  if (neighbourDraws(vJoint.x, vJointInside.x, vJointAlong.x, vJointAcross.x, vNeighbourLength.x) ||
      neighbourDraws(vJoint.y, vJointInside.y, vJointAlong.y, vJointAcross.y, vNeighbourLength.y))
    discard;
  float across = vDot > 0.5 ? length(vec2(vAcross, vDotAlong)) : abs(vAcross);
  float alpha = clamp(halfWidth - across, 0.0, 1.0) * ink;
  if (alpha <= 0.0) discard;
#ifdef TONE_COLOUR
  fragColor = vec4(uEntryColour[matchEntry(vLit)], alpha);
#else
  fragColor = vec4(vColour, alpha);
#endif
}
