// Fragment stage of every mesh pass; one PATH_* define selects what it does:
//  PATH_MASK       stencil path: depth and stencil, and with MASK_STROKE_ANGLE or
//                  MASK_PATTERN_COORDINATE what PATH_STROKE_ANGLE or PATH_PATTERN_COORDINATE
//                  write, at outputs 1 and 2 (passes/surface_buffer_pass.h)
//  PATH_TRIANGLE   the CPU's per-triangle choice, one draw per palette entry
//  PATH_VERTEX     lit per vertex, matched per pixel
//  PATH_PIXEL      lit and matched per pixel
//  PATH_SMOOTH     lit per pixel, two bracketing entries blended
//  PATH_PHONG      reference: the lit colour, per pixel
//  PATH_GOURAUD    reference: the lit colour, per vertex
//  PATH_LIT_TEXTURED  benchmark floor: per-pixel lighting times one screen-space fetch
//  PATH_EYE_POSITION, PATH_EYE_NORMAL  interpolated geometry, for accuracy references
//  PATH_STROKE_ANGLE  the pixel's hatching angle on screen (radians, valid) for the stencil path
// ORIENT_FIELD, ORIENT_LIGHT or ORIENT_FIXED: where the hatching angle comes from (orientation.glsl).
// SCREEN_OCCLUSION reads this frame's screen-space occlusion where OCCLUSION reads the bake (occlusion.glsl).
// MATERIALS lights with the mesh's own material, vertex colour and diffuse map (per pixel;
// the per-vertex paths light in mesh.vert with the map's average around each vertex).
// OUTPUT_ENTRY writes the chosen palette entry (entry / 255 in red; with a two-dimensional
// palette its layer, the row included) instead of its texel;
// OUTPUT_BLEND writes (entry a, entry b, weight of b) as floats (one entry: a = b, weight 0).
// DEFER_TURN (turned lookups on dense meshes) writes the pixel's stroke angle and entry for
// turn_resolve.frag instead.
// TONE_EDGES (pixel and vertex paths' colour): the match taken at four points of the pixel and
// their entries' texels averaged, so tone edges are anti-aliased and the pattern is not.
// PEEL_BEHIND (with PATH_MASK): only what lies behind the layer in front (depth peeling for the
// hidden lines' occlusion levels, renderer/lines/occlusion_layers.h).
// ALPHA_COVERAGE discards what a see-through material leaves out (coverage.glsl), in every pass.
// CONTROL_SHADOW / CONTROL_OCCLUSION: a control-image palette's pass, blended over the frame
// with its parameter as alpha (passes/control_palette_pass.h): the share of diffuse light
// shadows block, or 1 - the occlusion factor; pixels where it is 0 are left alone.

in vec3 vPosition;  // eye space (the object-space pattern reads them too: pattern.glsl)
in vec3 vNormal;

#if defined(PATH_PIXEL) || defined(PATH_SMOOTH) || defined(PATH_PHONG) || defined(PATH_LIT_TEXTURED)
#include "lighting.glsl"
#endif
#if (!defined(PATH_MASK) && !defined(PATH_PHONG) && !defined(PATH_GOURAUD) && !defined(PATH_EYE_POSITION) && !defined(PATH_EYE_NORMAL) && \
     !defined(PATH_STROKE_ANGLE)) || defined(MASK_PATTERN_COORDINATE)
#include "palette.glsl"
#endif

#if defined(ORIENT_FIELD) || defined(ORIENT_LIGHT) || defined(ORIENT_FIXED)
#define STROKE_SOURCE
#include "orientation.glsl"
#endif

#if defined(ORIENT_FIELD) || defined(ORIENT_LIGHT)
in vec2 vStrokeDirection;
#endif
#include "occlusion.glsl"
#if defined(PATH_VERTEX) || defined(PATH_GOURAUD)
in vec3 vColorFront;
in vec3 vColorBack;
#endif
#if defined(CONTROL_SHADOW) || defined(CONTROL_OCCLUSION)
#define CONTROL
#ifdef PATH_VERTEX
in float vControl;
#endif
#endif
#ifdef PATH_TRIANGLE
uniform int uEntry;  // drawn bucket by bucket
#endif
#if defined(MATERIALS) && !defined(PATH_VERTEX) && !defined(PATH_GOURAUD) && defined(VERTEX_COLOURS)
in vec3 vColour;
#endif
#if (defined(MATERIALS) && !defined(PATH_VERTEX) && !defined(PATH_GOURAUD)) || defined(ALPHA_COVERAGE)
#include "material.glsl"
#ifdef MATERIAL_UNIFORM
#define vMaterial 0u
#else
flat in uint vMaterial;
#endif
#ifdef MATERIAL_MAPS
in vec2 vTexcoord;
#endif
#endif
#ifdef ALPHA_COVERAGE
#include "coverage.glsl"
#endif

layout(location = 0) out vec4 fragColor;
#ifdef MASK_STROKE_ANGLE
layout(location = 1) out vec4 maskStrokeAngle;
#endif
#ifdef MASK_PATTERN_COORDINATE
layout(location = 2) out vec4 maskPatternCoordinate;
#endif

#if defined(DEFER_TURN)
// The turned lookup left to one pass per pixel (turn_resolve.frag): this pixel's stroke
// angle and entry at output 1 (output 0 goes nowhere); the smooth path's writes its two
// entries and weight.
layout(location = 1) out vec4 deferredTurn;
vec4 deferTurn(int e) {
  deferredTurn = vec4(strokeAngle, strokeValid ? float(e + 1) : -float(e + 1), 0.0, 1.0);
  return vec4(0.0);
}
#define SHOW_ENTRY(e) deferTurn(e)
#elif defined(OUTPUT_ENTRY)
#define SHOW_ENTRY(e) vec4(float(e) / 255.0, 0.0, 0.0, 1.0)
#elif defined(OUTPUT_BLEND)
#define SHOW_ENTRY(e) vec4(float(e), float(e), 0.0, 1.0)
#else
#define SHOW_ENTRY(e) vec4(paletteColour(e), 1.0)
#endif

#if defined(TONE_EDGES) && (defined(PATH_PIXEL) || defined(PATH_VERTEX))
// The tone is supersampled, not the frame: the lit colour is carried to four points of a
// rotated grid inside the pixel along its screen derivatives (exact where it is linear across
// the pixel, as in the vertex path) and matched at each. Each point's entry is shown at this
// pixel's own texel, so the pattern is sampled once per pixel and never shimmers. Inside a band
// (the four agree) it is one fetch; at an edge, the entry of the first point and the other one
// (a third, in a band thinner than a pixel, counts as the other), weighted by their points.
vec3 toneEdgeColour(vec3 lit) {
  vec3 dx = dFdx(lit), dy = dFdy(lit);
  int e0 = matchEntry(lit - 0.125 * dx - 0.375 * dy);
  int e1 = matchEntry(lit + 0.375 * dx - 0.125 * dy);
  int e2 = matchEntry(lit + 0.125 * dx + 0.375 * dy);
  int e3 = matchEntry(lit - 0.375 * dx + 0.125 * dy);
  vec3 c0 = paletteColour(paletteLayer(e0));
  if (e1 == e0 && e2 == e0 && e3 == e0) return c0;
  int other = e1 != e0 ? e1 : (e2 != e0 ? e2 : e3);
  float own = 1.0 + float(e1 == e0) + float(e2 == e0) + float(e3 == e0);
  return mix(paletteColour(paletteLayer(other)), c0, own * 0.25);
}
#define SHOW_MATCHED(lit) vec4(toneEdgeColour(lit), 1.0)
#else
#define SHOW_MATCHED(lit) SHOW_ENTRY(paletteLayer(matchEntry(lit)))
#endif

#ifdef PEEL_BEHIND
uniform sampler2D uPeelFront;  // window depth of the layer in front, texel for pixel
uniform vec3 uPeelDepthMap;    // view_distance.glsl's map for this camera
uniform float uPeelTolerance;  // eye units: a surface this near the layer is the layer itself
#include "view_distance.glsl"
#endif

void main() {
#ifdef PEEL_BEHIND
  float layer = texelFetch(uPeelFront, ivec2(gl_FragCoord.xy), 0).r;
  if (layer >= 1.0 || viewDistance(gl_FragCoord.z, uPeelDepthMap) <= viewDistance(layer, uPeelDepthMap) + uPeelTolerance) discard;
#endif
#if defined(ALPHA_COVERAGE) && defined(MATERIAL_MAPS)
  if (!covered(vMaterial, vTexcoord)) discard;
#elif defined(ALPHA_COVERAGE)
  if (!covered(vMaterial, vec2(0.0))) discard;
#endif
#ifdef CONTROL
  // The parameter first: where it is 0 (most of the frame) nothing needs lighting or a lookup
  // (a GPU skips them; llvmpipe's quads pay anyway: measured). Below 1/512 a blend moves no
  // 8-bit channel by half a step: skipped too.
#if defined(PATH_VERTEX)
  float control = vControl;
#elif defined(CONTROL_SHADOW)
  float control = shadowShareAt(vPosition, vNormal, !gl_FrontFacing);
#else
  float control = 1.0 - OCCLUSION_FACTOR;
#endif
  if (!(control > 1.0 / 512.0)) discard;
#endif
#if defined(ORIENT_FIELD) || defined(ORIENT_LIGHT)
  setStrokeFromDirection(vStrokeDirection);
#elif defined(ORIENT_FIXED)
  strokeAngle = uOrientFixed;
  strokeValid = true;
#endif
#if defined(PATH_STROKE_ANGLE)
  fragColor = vec4(strokeAngle, strokeValid ? 1.0 : 0.0, 0.0, 1.0);
#elif defined(PATH_PATTERN_COORDINATE)
  fragColor = vec4(packedObjectCoordinate(), 0.0, 1.0);
#elif defined(PATH_MASK)
  fragColor = vec4(0.0);
#ifdef MASK_STROKE_ANGLE
  maskStrokeAngle = vec4(strokeAngle, strokeValid ? 1.0 : 0.0, 0.0, 1.0);
#endif
#ifdef MASK_PATTERN_COORDINATE
  maskPatternCoordinate = vec4(packedObjectCoordinate(), 0.0, 1.0);
#endif
#elif defined(PATH_EYE_POSITION)
  fragColor = vec4(vPosition, gl_FrontFacing ? 1.0 : -1.0);
#elif defined(PATH_EYE_NORMAL)
  fragColor = vec4(vNormal, 1.0);
#elif defined(PATH_TRIANGLE)
  fragColor = SHOW_ENTRY(uEntry);
#elif defined(PATH_VERTEX)
  setPaletteRow(vPosition, vNormal);
  fragColor = SHOW_MATCHED(gl_FrontFacing ? vColorFront : vColorBack);
#elif defined(PATH_GOURAUD)
  fragColor = vec4(gl_FrontFacing ? vColorFront : vColorBack, 1.0);
#else
#ifdef MATERIALS
  SurfaceMaterial mat = fetchMaterial(vMaterial);
#ifdef VERTEX_COLOURS
  vec3 scale = vColour;
#else
  vec3 scale = vec3(1.0);
#endif
#ifdef MATERIAL_MAPS
  if (mat.map >= 0.0) scale *= texture(uMaterialMaps, vec3(vTexcoord, mat.map)).rgb;
#endif
  vec3 lit = shadeScaled(mat, vPosition, vNormal, !gl_FrontFacing, scale * OCCLUSION_FACTOR);
#else
  vec3 lit = shadeScaled(vPosition, vNormal, !gl_FrontFacing, vec3(OCCLUSION_FACTOR));
#endif
#if defined(PATH_PIXEL) || defined(PATH_SMOOTH)
  setPaletteRow(vPosition, vNormal);
#endif
#if defined(PATH_PIXEL)
  fragColor = SHOW_MATCHED(lit);
#elif defined(PATH_SMOOTH) && defined(OUTPUT_BLEND)
  fragColor = vec4(blendSelection(lit), 1.0);
#elif defined(PATH_SMOOTH) && defined(DEFER_TURN)
  vec3 b = blendSelection(lit);
  deferredTurn = vec4(strokeAngle, strokeValid ? b.x + 1.0 : -(b.x + 1.0), b.y, b.z);
  fragColor = vec4(0.0);
#elif defined(PATH_SMOOTH)
  fragColor = vec4(paletteBlend(lit), 1.0);
#elif defined(PATH_PHONG)
  fragColor = vec4(lit, 1.0);
#elif defined(PATH_LIT_TEXTURED)
  fragColor = vec4(lit * paletteColour(0), 1.0);
#endif
#endif
#ifdef CONTROL
  fragColor.a = min(control, 1.0);
#endif
}
