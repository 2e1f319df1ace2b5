// Vertex stage shared by every mesh pass. gl_Position is computed by the same expression in
// every variant and declared invariant, so the stencil path's passes produce equal depths.
// PER_VERTEX_LIGHTING (the `vertex` path and Gouraud reference) lights here.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;

invariant gl_Position;

out vec3 vPosition;  // eye space
out vec3 vNormal;    // eye space, not normalised

#ifdef PER_VERTEX_LIGHTING
#include "lighting.glsl"
out vec3 vColorFront;
out vec3 vColorBack;
#endif

void main() {
  vec4 eye = uModelView * vec4(aPosition, 1.0);
  gl_Position = uProjection * eye;
  vPosition = eye.xyz;
  vNormal = uNormalMatrix * aNormal;
#ifdef PER_VERTEX_LIGHTING
  vColorFront = shadeGL(eye.xyz, vNormal, false);
#ifdef TWO_SIDED
  vColorBack = shadeGL(eye.xyz, vNormal, true);
#else
  vColorBack = vColorFront;
#endif
#endif
}
