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

ivec2 wrapTexel(vec2 u, ivec2 size) {
  ivec2 p = ivec2(floor(u)) % size;
  return p + size * ivec2(lessThan(p, ivec2(0)));
}

// A plain average of two hatchings washes out (half the contrast where their strokes do not
// line up); dividing the deviation from the mean by the weights' norm keeps the mean and,
// for uncorrelated patterns, the variance (Bénard et al. 2009's blend).
vec3 crossFadeOctaves(vec3 coarse, vec3 fine, vec3 mean) {
  float wf = uPatternOctave, wc = 1.0 - wf;
  vec3 c = mean + (wc * (coarse - mean) + wf * (fine - mean)) / sqrt(wc * wc + wf * wf);
  return clamp(c, 0.0, 1.0);
}

#endif
