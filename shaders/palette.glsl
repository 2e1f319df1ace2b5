// Screen-space palette sampling and matching. A palette texel maps to a pixel and tiles
// from the window's corner, so patterns stay flat to the camera whatever the depth. With
// PATTERN_ANCHORED the pixel is first mapped through the pattern's frame, which follows the
// object (renderer/patterns/pattern_tracker.h), and two octaves of the pattern are
// cross-faded so marks keep their size on screen under zoom; with PATTERN_SCALED through a
// fixed scale (--pattern-scale). Mapped patterns read the palette's mip levels (pattern.glsl).
// Layers are stored precomposited over the background where that is exact
// (PALETTE_PRECOMPOSITED), so the common case is one fetch per pixel.
// With ORIENTED each entry's lookup is turned so its strokes follow the pixel's stroke angle
// (orientation.glsl; the pass sets the angle before matching).
// Defines: PALETTE_SIZE, LAYER_SIZES_DIFFER, BACKGROUND_IMAGE, MATCH_COLORS | MATCH_INTENSITY |
// MATCH_ORDER, LUT1D_SIZE, LUT3D_SIZE, PATTERN_ANCHORED, PATTERN_SCALED, ORIENTED, ORIENT_BINS,
// ENTRY_ANGLE_SHARED and TONE_THRESHOLD (precomposited layers whose alpha holds each texel's
// threshold: the smooth path shows one level or the other instead of their blend).
// PALETTE_AXIS (with PALETTE_ROWS, PALETTE_COLUMNS and AXIS_DEPTH | AXIS_FACING | AXIS_DETAIL): a
// two-dimensional palette, layers stored row after row; matching picks the column and the pass
// sets the row from the surface (setPaletteRow) before it shows an entry.

uniform sampler2DArray uPalette;
#ifdef LAYER_SIZES_DIFFER
uniform ivec2 uLayerSize[PALETTE_SIZE];
#define LAYER_SIZE(i) uLayerSize[i]
#else
uniform ivec2 uLayerSize0;
#define LAYER_SIZE(i) uLayerSize0
#endif

#include "pattern.glsl"

#ifndef PALETTE_PRECOMPOSITED
#ifdef BACKGROUND_IMAGE
uniform sampler2D uBackground;
uniform ivec2 uBackgroundSize;
uniform float uBackgroundScale;  // texels per pixel: 1 / pattern scale
vec3 backgroundColour() { return texelFetch(uBackground, wrapTexel(framePixel() * uBackgroundScale, uBackgroundSize), 0).rgb; }
#else
uniform vec3 uBackgroundColour;
vec3 backgroundColour() { return uBackgroundColour; }
#endif
#endif

vec3 composite(vec4 t) {
#ifdef PALETTE_PRECOMPOSITED
  return t.rgb;
#else
  return mix(backgroundColour(), t.rgb, t.a);
#endif
}

#ifdef PATTERN_MAPPED
vec3 paletteCoordinate() { return mappedCoordinate(); }
vec4 layerTexel(vec3 c, int entry) { return mappedTexel(uPalette, c, entry, LAYER_SIZE(entry)); }
#else
vec3 paletteCoordinate() { return vec3(framePixel(), 0.0); }
vec4 layerTexel(vec3 c, int entry) { return texelFetch(uPalette, ivec3(wrapTexel(c.xy, LAYER_SIZE(entry)), entry), 0); }
#endif

#ifdef ORIENTED
#include "orientation.glsl"
uniform float uFrameTurn;  // the anchored pattern's rotation on screen
// Branch-free: llvmpipe runs both sides of a branch that differs across its pixels, and an
// unturned lookup is the turned one with step 0 (no turn) and weight 0.
#ifdef ENTRY_ANGLE_SHARED
// Every turned entry's strokes run at one angle, so the turn and the two turned coordinates
// do not depend on which entry the pixel matched: found once per pixel (once for both of the
// smooth path's entries), and an entry with no stroke direction takes the unturned coordinate.
uniform float uSharedEntryAngle;
uniform int uTurnedEntries[(PALETTE_SIZE + 31) / 32];  // bit k % 32 of word k / 32: entry k is turned
bool entryTurned(int entry) { return ((uTurnedEntries[entry >> 5] >> (entry & 31)) & 1) != 0; }
vec4 paletteTexel(int entry) {
  vec3 c = paletteCoordinate();
  int b0, b1;
  float w;
  orientSteps(uSharedEntryAngle, uFrameTurn, b0, b1, w);
  vec2 c0 = turnedCoordinate(c.xy, b0), c1 = turnedCoordinate(c.xy, b1);
  if (!entryTurned(entry)) {
    c0 = c1 = c.xy;
    w = 0.0;
  }
  return mix(layerTexel(vec3(c0, c.z), entry), layerTexel(vec3(c1, c.z), entry), w);
}
#else
uniform float uEntryAngle[PALETTE_SIZE];  // each entry's stroke direction (radians; < -10: none)
vec4 paletteTexel(int entry) {
  vec3 c = paletteCoordinate();
  int b0, b1;
  float w;
  orientSteps(uEntryAngle[entry], uFrameTurn, b0, b1, w);
  return mix(layerTexel(vec3(turnedCoordinate(c.xy, b0), c.z), entry), layerTexel(vec3(turnedCoordinate(c.xy, b1), c.z), entry), w);
}
#endif
#elif defined(PATTERN_MAPPED)
vec4 paletteTexel(int entry) { return layerTexel(paletteCoordinate(), entry); }
#else
vec4 paletteTexel(int entry) {
  ivec2 p = wrapTexel(framePixel(), LAYER_SIZE(entry));
  return texelFetch(uPalette, ivec3(p, entry), 0);
}
#endif
vec3 paletteColour(int entry) { return composite(paletteTexel(entry)); }

#ifdef PALETTE_AXIS
uniform vec2 uAxisMap;    // row position = axis value x map.x + map.y (GpuPalette::setAxisScale)
float paletteRow = 0.0;  // this pixel's row position, in [0, PALETTE_ROWS - 1]
#ifdef AXIS_DETAIL
uniform float uAxisDetail;  // the model's detail (Renderer::setModelDetail)
#endif
void setPaletteRow(vec3 eyePosition, vec3 eyeNormal) {
#if defined(AXIS_DETAIL)
  float value = uAxisDetail;
#elif defined(AXIS_DEPTH)
  float value = length(eyePosition);
#else
  float value = 1.0 - abs(dot(normalize(eyeNormal), normalize(eyePosition)));
#endif
  paletteRow = clamp(value * uAxisMap.x + uAxisMap.y, 0.0, float(PALETTE_ROWS - 1));
}
// The layer showing column `entry` in the nearest row (the paths that show whole entries).
int paletteLayer(int entry) { return entry + PALETTE_COLUMNS * int(paletteRow + 0.5); }
#else
void setPaletteRow(vec3 eyePosition, vec3 eyeNormal) {}
int paletteLayer(int entry) { return entry; }
#endif

// Between entries a and b at weight w of b. TONE_THRESHOLD (Webb et al. 2002; intensity
// matching, where a is the darker level): whole texels of one level or the other, the darker
// where its weight 1 - w passes the texel's threshold (the share of the way from the lighter
// level at which the texel turns; both layers store it), so strokes stay crisp at every tone.
// The same two fetches as the blend, branch-free.
vec3 toneBetween(int a, int b, float w) {
#ifdef TONE_THRESHOLD
  vec4 ta = paletteTexel(a), tb = paletteTexel(b);
  return 1.0 - w > ta.a ? ta.rgb : tb.rgb;
#else
  return mix(paletteColour(a), paletteColour(b), w);
#endif
}

#ifdef MATCH_COLORS
uniform usampler3D uLut3D;  // nearest and second-nearest entry at each grid point
uniform vec3 uAverages[PALETTE_SIZE];  // scaled average colours, for the smooth weights
uvec2 lutColour(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return texelFetch(uLut3D, ivec3(c * float(LUT3D_SIZE - 1) + 0.5), 0).rg;
}
int matchEntry(vec3 lit) { return int(lutColour(lit).r); }
#else
float matchQuery(vec3 c) {
  c = clamp(c, 0.0, 1.0);
#ifdef MATCH_INTENSITY
  return 3.0 * max(c.r, max(c.g, c.b));
#else
  return c.r + c.g + c.b;
#endif
}
int lutBin(vec3 lit) { return int(matchQuery(lit) * (float(LUT1D_SIZE - 1) / 3.0) + 0.5); }
uniform usampler2D uLutIndex;  // nearest entry per query bin
uniform sampler2D uLutBlend;   // (entry a, entry b, weight of b) per query bin
int matchEntry(vec3 lit) { return int(texelFetch(uLutIndex, ivec2(lutBin(lit), 0), 0).r); }
#endif

// The smooth path: the two entries that bracket the lit colour, as (entry a, entry b,
// weight of b), and their blend.
vec3 blendSelection(vec3 lit) {
#ifdef MATCH_COLORS
  uvec2 ab = lutColour(lit);
  vec3 c = clamp(lit, 0.0, 1.0);
  float da = distance(uAverages[ab.x], c), db = distance(uAverages[ab.y], c);
  return vec3(float(ab.x), float(ab.y), (da + db) > 0.0 ? da / (da + db) : 0.0);
#else
  return texelFetch(uLutBlend, ivec2(lutBin(lit), 0), 0).rgb;
#endif
}

vec3 paletteBlend(vec3 lit) {
  vec3 b = blendSelection(lit);
#ifdef PALETTE_AXIS
  // Between rows too: the two rows around the pixel's position, blended (the second skipped
  // where the position is on a row: most of the surface, past the axis' ends).
  int r0 = int(paletteRow);
  float f = paletteRow - float(r0);
  vec3 c = toneBetween(int(b.x) + r0 * PALETTE_COLUMNS, int(b.y) + r0 * PALETTE_COLUMNS, b.z);
  if (f > 0.0) {
    int r1 = min(r0 + 1, PALETTE_ROWS - 1) * PALETTE_COLUMNS;
    c = mix(c, toneBetween(int(b.x) + r1, int(b.y) + r1, b.z), f);
  }
  return c;
#else
  return toneBetween(int(b.x), int(b.y), b.z);
#endif
}
