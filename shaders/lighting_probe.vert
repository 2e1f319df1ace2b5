// Evaluates shaders/lighting.glsl at given eye-space points and normals, one point per
// pixel of a float target: how the CPU and GLSL lighting are checked against each other.
// Used only by the GL tests (tests/support/lighting_probe.cpp); it lives here, embedded with
// the others, because it #includes lighting.glsl from the same table.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aBack;
uniform ivec2 uSize;
flat out vec3 vPosition;
flat out vec3 vNormal;
flat out float vBack;
void main() {
  vec2 pixel = vec2(gl_VertexID % uSize.x, gl_VertexID / uSize.x) + 0.5;
  gl_Position = vec4(pixel / vec2(uSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
  vPosition = aPosition;
  vNormal = aNormal;
  vBack = aBack;
}
