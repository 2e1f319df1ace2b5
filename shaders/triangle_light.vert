// Per-triangle lighting on the GPU (the original report's proposed experiment: "an initial full
// lighting rendering pass and then frame buffer read back to get the OpenGL lighting for every
// triangle"): each triangle, as a point at its centroid with its face normal, is lit with the
// same lighting.glsl as the shaded paths, shadows and occlusion included, and lands on its own
// texel; triangle_light.frag matches it and writes the palette entry, read back for bucketing.
layout(location = 0) in vec3 aCentroid;
layout(location = 1) in vec3 aFaceNormal;
#ifdef OCCLUSION
layout(location = 7) in float aOcclusion;  // the face's vertices' mean
uniform float uOcclusionStrength;
#include "occlusion_factor.glsl"
#endif

uniform mat4 uModelView;
uniform mat3 uNormalMatrix;
uniform ivec2 uTargetSize;

#include "lighting.glsl"

flat out vec3 vLit;

void main() {
  vec3 eye = (uModelView * vec4(aCentroid, 1.0)).xyz;
  vec3 n = uNormalMatrix * aFaceNormal;
#ifdef OCCLUSION
  float occlusion = occlusionFactor(aOcclusion, uOcclusionStrength);
#else
  float occlusion = 1.0;
#endif
  // Facing as the CPU decides it: the eye behind the face's plane.
  vLit = shadeScaled(eye, n, dot(n, -eye) < 0.0, vec3(occlusion));
  ivec2 texel = ivec2(gl_VertexID % uTargetSize.x, gl_VertexID / uTargetSize.x);
  gl_Position = vec4((vec2(texel) + 0.5) / vec2(uTargetSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
