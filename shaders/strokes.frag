// Painterly brush strokes: the brush texture's coverage times the stroke's alpha, in the
// average colour of the palette entry the lit colour matches (palette.glsl), so the palette
// still decides the style: a palette of paint colours paints in them.
#include "palette.glsl"

uniform sampler2D uBrush;  // coverage: along x, across y
uniform vec3 uEntryColour[PALETTE_SIZE];

in vec2 vUv;
flat in vec3 vLit;
flat in float vAlpha;
flat in float vSeed;
out vec4 fragColor;

void main() {
  // Four brushes side by side in the texture; the seed picks one.
  float brush = floor(vSeed * 4.0);
  float coverage = texture(uBrush, vec2((brush + vUv.x) * 0.25, vUv.y)).r;
  float alpha = coverage * vAlpha;
  if (alpha <= 0.004) discard;
  // Each stroke a little lighter or darker than the next, its bristles darker where they load
  // more paint: the strokes read as strokes over an underpainting of the same colours.
  float value = 0.8 + 0.4 * fract(vSeed * 13.7);
  vec3 colour = uEntryColour[matchEntry(vLit)] * value * mix(0.8, 1.05, coverage);
  fragColor = vec4(clamp(colour, 0.0, 1.0), alpha);
}
