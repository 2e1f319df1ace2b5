// The occlusion factor mesh.frag scales ambient and diffuse light by (OCCLUSION_FACTOR): this
// frame's screen-space occlusion (SCREEN_OCCLUSION, features/occlusion's screen method), the
// bake interpolated from the vertices (OCCLUSION, per-pixel shadings; the per-vertex ones light
// with it in mesh.vert), or 1. Reads vPosition (eye space), which mesh.frag declares.
#if defined(SCREEN_OCCLUSION)
uniform sampler2D uScreenOcclusion;  // this frame's, 1 open (features/occlusion/screen_occlusion_pass.h)
uniform vec4 uScreenOcclusionFrame;  // the viewport's origin, texels per pixel
uniform float uOcclusionStrength;
// The half-resolution estimate at this pixel: the four texels around it, bilinear weights
// scaled down where a texel's depth is not this surface's (no halo across silhouettes).
float screenOcclusion() {
  vec2 t = (gl_FragCoord.xy - uScreenOcclusionFrame.xy) * uScreenOcclusionFrame.zw - 0.5;
  ivec2 base = ivec2(floor(t));
  vec2 f = t - vec2(base);
  ivec2 top = textureSize(uScreenOcclusion, 0) - 1;
  float z = -vPosition.z, sum = 0.0, weight = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      vec2 s = texelFetch(uScreenOcclusion, clamp(base + ivec2(i, j), ivec2(0), top), 0).rg;
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) / (abs(s.y - z) + 0.01 * z + 1e-6);
      sum += w * s.x;
      weight += w;
    }
  return weight > 0.0 ? sum / weight : 1.0;
}
#include "occlusion_factor.glsl"
#define OCCLUSION_FACTOR occlusionFactor(screenOcclusion(), uOcclusionStrength)
#elif defined(OCCLUSION) && !defined(PATH_VERTEX) && !defined(PATH_GOURAUD)
in float vOcclusion;
#define OCCLUSION_FACTOR vOcclusion
#else
#define OCCLUSION_FACTOR 1.0
#endif
