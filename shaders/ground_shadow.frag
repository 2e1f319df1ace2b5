// The ground plane's visibility per light (renderer/shadows/ground_shadow_pass.h): one texel per
// point of the ground's square, each light's shadowVisibility there in one channel, looked up
// exactly as a ground fragment would (shadows.glsl bound for model space: its "eye" space is the
// model's).
uniform vec4 uGroundRect;   // x0, z0, x1, z1
uniform float uGroundY;
uniform vec2 uSize;
uniform vec4 uLightKey[NUM_LIGHTS];  // model space: (direction, 0) or (position, 1)
out vec4 fragColor;

#include "shadows.glsl"

void main() {
  vec2 uv = gl_FragCoord.xy / uSize;
  vec3 p = vec3(mix(uGroundRect.x, uGroundRect.z, uv.x), uGroundY, mix(uGroundRect.y, uGroundRect.w, uv.y));
  const vec3 n = vec3(0.0, 1.0, 0.0);
  vec4 visible = vec4(1.0);
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    vec3 vp = uLightKey[i].w == 0.0 ? uLightKey[i].xyz : normalize(uLightKey[i].xyz - p);
    float ndl = dot(n, vp);
    if (ndl > 0.0) visible[i] = shadowVisibility(i, p, n, ndl);
  }
  fragColor = visible;
}
