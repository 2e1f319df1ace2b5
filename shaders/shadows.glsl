// Shadow-map lookups for lighting.glsl (SHADOWS): how much of light i reaches eye-space point
// `pos` with unit normal `n` (0: blocked, 1: lit; filtered at edges). Every shadowed light has
// its maps as layers of one depth array (renderer/shadows/shadow_maps.h): one layer for a
// directional or spot light, six for a point light (one per axis direction of model space,
// chosen here by the major axis). Acne is kept off by the depth pass's slope-scaled offset and
// by looking up a point pushed along the normal by about a shadow texel, more at grazing light.
#ifndef SHADOWS_GLSL
#define SHADOWS_GLSL

uniform sampler2DArrayShadow uShadowMaps;
uniform mat4 uShadowMatrix[SHADOW_LAYERS];  // eye space -> the layer's light clip space
uniform int uShadowLayer[NUM_LIGHTS];       // light i's first layer; -1: unshadowed
uniform int uShadowPoint[NUM_LIGHTS];       // 1: six layers, +x -x +y -y +z -z of model space
uniform float uShadowTexelSize[NUM_LIGHTS]; // a shadow texel's size in eye units (at distance 1 if perspective)
uniform int uShadowPerspective[NUM_LIGHTS];
uniform vec3 uShadowLightPosition[NUM_LIGHTS];  // eye space (point and spot lights)
uniform mat3 uEyeToModel;
uniform float uShadowTexel;  // 1 / map size

float shadowVisibility(int i, vec3 pos, vec3 n, float ndl) {
  int layer = uShadowLayer[i];
  if (layer < 0) return 1.0;
  float texel = uShadowTexelSize[i];
  if (uShadowPerspective[i] == 1) texel *= length(pos - uShadowLightPosition[i]);
  vec3 p = pos + n * (texel * (0.75 + 1.5 * sqrt(max(1.0 - ndl * ndl, 0.0))));
  if (uShadowPoint[i] == 1) {
    vec3 d = uEyeToModel * (p - uShadowLightPosition[i]);
    vec3 a = abs(d);
    layer += a.x >= a.y && a.x >= a.z ? (d.x > 0.0 ? 0 : 1) : (a.y >= a.z ? (d.y > 0.0 ? 2 : 3) : (d.z > 0.0 ? 4 : 5));
  }
  vec4 c = uShadowMatrix[layer] * vec4(p, 1.0);
  if (!(c.w > 0.0)) return 1.0;
  vec3 ndc = c.xyz / c.w;
  // Outside the map nothing casts (the map covers every caster) and beyond its far plane
  // nothing is behind.
  if (abs(ndc.x) > 1.0 || abs(ndc.y) > 1.0 || ndc.z > 1.0) return 1.0;
  vec3 uvz = ndc * 0.5 + 0.5;
  // Four bilinear comparisons on a rotated grid: a 4x4-texel filter.
  float s = texture(uShadowMaps, vec4(uvz.xy + vec2(-0.5, -1.5) * uShadowTexel, float(layer), uvz.z));
  s += texture(uShadowMaps, vec4(uvz.xy + vec2(1.5, -0.5) * uShadowTexel, float(layer), uvz.z));
  s += texture(uShadowMaps, vec4(uvz.xy + vec2(0.5, 1.5) * uShadowTexel, float(layer), uvz.z));
  s += texture(uShadowMaps, vec4(uvz.xy + vec2(-1.5, 0.5) * uShadowTexel, float(layer), uvz.z));
  return 0.25 * s;
}

#endif
