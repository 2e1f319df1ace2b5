// Where a pixel reads the palette when the pattern is mapped (palette.glsl and the stencil
// path's layer quad): PATTERN_OBJECT, the surface's own position (below); PATTERN_ANCHORED, the
// anchored pattern's frame that follows the object while a zoom dissolves two octaves so marks
// keep their size on screen; PATTERN_SCALED, a fixed pattern scale (texels of S pixels), which
// is also the anchored frame while one octave shows alone (most frames: GpuPalette::bindPattern).
// uPatternMatrix and uPatternOffset map window pixels to pattern texels of the coarser octave,
// whose marks are S 2^fract(log2 scale) pixels wide; the finer octave is twice as dense and
// read one mip level down, so a palette with its own levels (a tonal art map) keeps its
// strokes' width and its tone. Both octaves' levels come from the CPU (uPatternLod):
// a similarity has one scale over the whole frame, so no per-pixel derivative is needed.
#ifndef PATTERN_GLSL
#define PATTERN_GLSL

#if defined(PATTERN_ANCHORED) || defined(PATTERN_SCALED) || defined(PATTERN_OBJECT)
#define PATTERN_MAPPED
#endif

// This pixel in the whole frame: a poster drawn in tiles offsets each tile's pixels, so the
// pattern continues across tile seams.
uniform vec2 uFrameOffset;
vec2 framePixel() { return gl_FragCoord.xy + uFrameOffset; }

uniform vec4 uPatternMatrix;  // column-major 2x2: (m00, m10, m01, m11)
uniform vec2 uPatternOffset;  // uPatternMatrix (uFrameOffset - the frame's origin), from the CPU
uniform float uPatternFade;   // how far the dissolve to the fine octave has gone, 0..1
uniform vec2 uPatternLod;     // the mip level of the coarse and the fine octave

// M (framePixel() - origin), its constant part folded on the CPU: four multiply-adds a pixel
// instead of ten operations. In a shader as short as a path that reads one texel per pixel each
// operation shows (bunny, 1920x1080, anchored / screen, vertex path: 1.08-1.10x -> 1.05-1.07x).
// Stages whose vertex stage interpolates it (PATTERN_FROM_VERTEX: pattern_vertex.glsl) read it
// instead: far cheaper per pixel.
#ifdef PATTERN_FROM_VERTEX
in vec2 vPatternCoordinate;
vec2 patternCoordinate() { return vPatternCoordinate * gl_FragCoord.w; }
#else
vec2 patternCoordinate() {
  vec2 p = gl_FragCoord.xy;
  return vec2(uPatternMatrix.x * p.x + (uPatternMatrix.z * p.y + uPatternOffset.x), uPatternMatrix.y * p.x + (uPatternMatrix.w * p.y + uPatternOffset.y));
}
#endif

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

#ifdef PATTERN_OBJECT
// PATTERN_OBJECT: the pattern glued to the surface without texture coordinates. Triplanar: the
// object-space position projected along the axis the normal is nearest; where another axis is
// within 0.15 of it, the projections are dissolved by their share of that margin (a threshold
// hashed from the surface point's cell of 8 fine texels, so each patch shows one projection's
// marks at full contrast and the choice stays on the surface; a weighted average would wash
// the hatching out where axes meet, as it does between two octaves). Octaves by
// the screen scale (Bénard et al. 2009): from each pixel's depth, the power of two of texels
// per object unit whose texels are 1 to 2 pattern-scale pixels wide on screen, and the next one
// up read one mip level down, dissolved by where the depth falls in the octave (as anchored).
// The stencil path's quads read the result from a buffer its mask pass drew
// (PATTERN_OBJECT_BUFFER).
// The buffer holds (u, v) in two floats, and which octave the pixel shows in the lowest bit of
// u's mantissa (one unit in the last place: about a ten-millionth of the coordinate, far below
// a texel): 8 bytes a pixel instead of 16, which the masks write for every fragment that
// passes the depth test and the quads read for every pixel (bunny, object / screen, stencil,
// six alternated runs: median 1.37x -> 1.35x; the machine's noise is about as large).
#ifdef PATTERN_OBJECT_BUFFER
uniform sampler2D uPatternCoordinates;  // packed (u, v) per pixel of the viewport
uniform ivec2 uViewportOrigin;
vec3 mappedCoordinate() {
  vec2 c = texelFetch(uPatternCoordinates, ivec2(gl_FragCoord.xy) - uViewportOrigin, 0).xy;
  return vec3(c, (floatBitsToUint(c.x) & 1u) != 0u ? uPatternLod.y : uPatternLod.x);
}
#else
// From the eye-space position and normal every mesh pass interpolates (mesh.frag declares
// them): no varyings of its own, which on the 871K mesh cost vertex work.
uniform mat4 uEyeToObject;    // the view's inverse: rigid, so object units are eye units
#ifdef PATTERN_REST
in vec3 vRestPosition;        // a deforming mesh's rest pose (mesh.vert)
in vec3 vRestNormal;
#endif
uniform float uPixelSize;     // object units per pixel at eye depth 1
uniform float uPatternScale;  // pixels per texel
// The coordinate in texels of level 0 and whether it is the fine octave's.
vec2 objectCoordinate(out bool fine) {
  // Only axes within 0.15 of the nearest share: elsewhere one projection, unbroken.
#if defined(PATTERN_REST)
  // A deforming mesh: the rest pose's surface point and normal (mesh.vert passes them on), so
  // the pattern stays on the surface as it bends.
  vec3 n = abs(vRestNormal);
#elif defined(PATTERN_FACE_NORMAL)
  // Passes that light per triangle or per vertex have no other use for the normal: the face's
  // own, from the position's screen derivatives, spares interpolating three values per vertex
  // (on the 871K mesh, most of what the object pattern cost them).
  vec3 n = abs(mat3(uEyeToObject) * cross(dFdx(vPosition), dFdy(vPosition)));
#else
  vec3 n = abs(mat3(uEyeToObject) * vNormal);
#endif
  // Every operation here runs for each fragment of the stencil path's masks, which otherwise
  // only test depth; so no normalising, no division, no log2 or exp2 (torus 871K, object /
  // screen, three alternated runs: stencil 1.11-1.16x -> 1.03-1.08x, pixel 1.05-1.08x ->
  // 1.02-1.03x; bunny: triangle 1.27-1.33x -> 1.22-1.25x).
  // Axes within 0.15 of the nearest, in units of |n|.
  vec3 w = max(n - (max(n.x, max(n.y, n.z)) - 0.15 * length(n)), 0.0);
  // The octave from the bits of x, the object-space width of S pixels at this depth (S the
  // pattern scale; x = m 2^e, m in [1, 2)): texels 2^(e+1) units wide show 1 to 2 S wide, and
  // 2 - m, how far x is from the octave above, is how far the dissolve to the fine texels has
  // gone (linear in x where it was in log2 x: the same at both ends, and the tone holds:
  // bench_patterns, bunny zoom 8x, worst 0.19 palette steps from the screen's against 0.21).
  // Any depth stays finite: x is clamped to where both bit fields stay normal.
  int bits = floatBitsToInt(clamp(-vPosition.z * uPixelSize * uPatternScale, 1e-30, 1e30));
  float texels = intBitsToFloat(0x7E800000 - (bits & 0x7F800000));  // coarse texels per object unit
  float through = 2.0 - intBitsToFloat((bits & 0x007FFFFF) | 0x3F800000);
#ifdef PATTERN_REST
  vec3 p = vRestPosition;
#else
  vec3 p = (uEyeToObject * vec4(vPosition, 1.0)).xyz;
#endif
  // Dissolved in blocks of 8 fine texels: a stroke is broken at most every few pixels.
  ivec3 cell = ivec3(floor(p * (2.0 * texels / 8.0)));
  uint h = patternHash(cell.xy ^ ivec2(cell.z * 7919, cell.z * 104729));
  float pick = float(h >> 16) * ((w.x + w.y + w.z) / 65536.0), fade = (float(h & 0xffffu) + 0.5) / 65536.0;
  vec2 q = pick < w.x ? p.yz : (pick < w.x + w.y ? p.zx : p.xy);
  fine = through > fade;
  return q * (fine ? 2.0 * texels : texels);
}
vec3 mappedCoordinate() {
  bool fine;
  vec2 c = objectCoordinate(fine);
  return vec3(c, fine ? uPatternLod.y : uPatternLod.x);
}
// For the stencil path's buffer (above).
vec2 packedObjectCoordinate() {
  bool fine;
  vec2 c = objectCoordinate(fine);
  return vec2(uintBitsToFloat((floatBitsToUint(c.x) & ~1u) | (fine ? 1u : 0u)), c.y);
}
#endif
#else
// This pixel's palette coordinate: (texel at level 0 of the octave it shows, mip level).
vec3 mappedCoordinate() {
  vec2 u = patternCoordinate();
#ifdef PATTERN_ANCHORED
  float threshold = (float(patternHash(ivec2(floor(2.0 * u))) & 0xffffu) + 0.5) / 65536.0;
  return uPatternFade > threshold ? vec3(2.0 * u, uPatternLod.y) : vec3(u, uPatternLod.x);
#else
  return vec3(u, uPatternLod.x);
#endif
}
#endif

// A layer's colour at a mapped coordinate: by default the nearest texel of the level (one
// fetch, as at scale 1). PATTERN_FILTERED (--pattern-filter linear, layers of one size) filters
// bilinearly within the level, so a turned or non-integer scaled pattern has no stair-steps:
// `s` is then the palette's sRGB view, filtered in linear light (an average of encoded values
// is darker than the light it stands for) and encoded again here, as everything else in the
// shaders is; the sampler wraps (REPEAT). It costs llvmpipe about 15% of a bunny frame.
#ifdef PATTERN_FILTERED
vec3 encodeSrgb(vec3 c) {
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
#endif
vec4 mappedTexel(sampler2DArray s, vec3 c, int layer, ivec2 size) {
#ifdef PATTERN_FILTERED
  vec4 t = textureLod(s, vec3(c.xy / vec2(size), float(layer)), c.z);
  return vec4(encodeSrgb(t.rgb), t.a);
#else
  int l = int(c.z);
  return texelFetch(s, ivec3(wrapTexel(c.xy / float(1 << l), max(size >> l, ivec2(1))), layer), l);
#endif
}

#endif
