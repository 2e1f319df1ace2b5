// The vertex stage's half of the anchored and scaled patterns' mapping (pattern.glsl), compiled
// in with PATTERN_FROM_VERTEX: the pattern coordinate times the clip w, which is linear in the
// clip position, so the rasterizer interpolates it exactly (clipped triangles included) and the
// fragment stage multiplies by gl_FragCoord.w (1 / w). On llvmpipe an interpolated pair costs a
// pixel far less than the mapping's four multiply-adds from gl_FragCoord (bunny, triangle path,
// anchored / screen: 1.08-1.10x -> 0.99-1.01x) but costs each triangle's set-up: meshes whose
// triangles span under a pixel or two map per pixel instead (Renderer::preparePattern), and
// the stencil path's full-screen layer quads always interpolate.
#ifndef PATTERN_VERTEX_GLSL
#define PATTERN_VERTEX_GLSL
#ifdef PATTERN_FROM_VERTEX  // only with PATTERN_ANCHORED or PATTERN_SCALED
uniform vec4 uPatternClipMatrix;  // column-major 2x2: clip (x, y) to pattern texels times w
uniform vec2 uPatternClipOffset;  // clip w to pattern texels times w
out vec2 vPatternCoordinate;      // pattern texels times clip w
void setPatternCoordinate(vec4 clip) {
  vPatternCoordinate = mat2(uPatternClipMatrix.xy, uPatternClipMatrix.zw) * clip.xy + uPatternClipOffset * clip.w;
}
#else
void setPatternCoordinate(vec4 clip) {}
#endif
#endif
