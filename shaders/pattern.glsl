// The anchored pattern's frame in the shaders (palette.glsl and the stencil path's layer
// quad): pattern coordinates of this pixel, tiling, and the cross-fade of two octaves.
// uPatternMatrix maps window pixels (relative to uPatternOrigin) to pattern texels of the
// coarser octave, whose marks are 2^uPatternOctave pixels wide (in [1, 2)); the finer octave
// is twice as dense. As the object comes closer the coarse octave fades out and the fine one
// grows into its place: at octave 1 the fine layer is exactly the next coarse one.
#ifndef PATTERN_GLSL
#define PATTERN_GLSL

uniform vec4 uPatternMatrix;  // column-major 2x2: (m00, m10, m01, m11)
uniform vec2 uPatternOrigin;
uniform float uPatternOctave;  // fract(log2 scale)

vec2 patternCoordinate() {
  vec2 d = gl_FragCoord.xy - uPatternOrigin;
  return vec2(uPatternMatrix.x * d.x + uPatternMatrix.z * d.y, uPatternMatrix.y * d.x + uPatternMatrix.w * d.y);
}

// Tiling in float (llvmpipe divides integers one lane at a time); min() guards the rounding
// at the tile's far edge.
ivec2 wrapTexel(vec2 u, ivec2 size) {
  vec2 s = vec2(size);
  return min(ivec2(u - s * floor(u / s)), size - 1);
}

// The two octaves are dissolved, not averaged: each pixel shows one or the other, the fine
// one where the fade has passed a threshold fixed to the pattern (a hash of the fine texel, so
// it moves with the pattern). A plain average washes hatching out (where one octave has a
// stroke and the other paper it gives grey: contrast 0.318 against the screen's 0.405 at the
// end of an 8x zoom on the bunny); Bénard et al. 2009's variance-preserving blend keeps
// contrast but clips, which shifts the tone (0.31 palette steps). The dissolve keeps both
// (0.04 steps, contrast 0.397), and needs one fetch per pixel, not two.
uint patternHash(ivec2 p) {
  uint h = uint(p.x) * 0x8da6b343u ^ uint(p.y) * 0xd8163841u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  return h ^ (h >> 15);
}

// The pattern coordinate of this pixel in the octave it shows (u: the coarse coordinate).
vec2 dissolvedCoordinate(vec2 u) {
  float threshold = (float(patternHash(ivec2(floor(2.0 * u))) & 0xffffu) + 0.5) / 65536.0;
  return uPatternOctave > threshold ? 2.0 * u : u;
}

#endif
