// A full-screen triangle generated from gl_VertexID (no vertex buffer), at the far plane; with
// a mapped pattern (the stencil path's layer quads) it hands on the pattern coordinate.
#include "pattern_vertex.glsl"
void main() {
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
  setPatternCoordinate(gl_Position);
}
