// The OpenGL 2.1 lighting equation (section 2.14.1), in eye space: the same equation as
// renderer/lighting/lighting_model.h, specialised by #defines to the features the scene uses:
// NUM_LIGHTS, HAS_POSITIONAL, HAS_ATTENUATION, HAS_SPOT, HAS_SPECULAR, LOCAL_VIEWER,
// TWO_SIDED, LIGHTING_OFF, and the tone models TONE_GOOCH / TONE_SPLASHBACK / TONE_CHARCOAL. Uniforms are
// the prepared products of light and material colours; with MATERIALS (the mesh's own
// materials) they are the lights' own colours, multiplied here by the material the caller
// passes (material.glsl) for the vertex or fragment. SHADOWS (with SHADOW_LAYERS) looks each
// light up in its shadow map: a blocked light keeps its ambient term only, as OpenGL's would.
// GROUND_SHADOW_MAP (the ground plane, per pixel) reads the lights' visibility from the
// ground's shadow texture instead. CONTROL_SHADOW adds shadowShareAt: how much of the diffuse
// light reaching the surface the shadows block (control palettes: passes/control_palette_pass.h).

#ifndef NUM_LIGHTS
#define NUM_LIGHTS 0
#endif

#ifdef MATERIALS
#include "material.glsl"
uniform vec3 uModelAmbient;
#define LIGHT_SLOTS NUM_LIGHTS
#define MATERIAL_PARAMETER SurfaceMaterial mat,
#define MATERIAL_ARGUMENT mat,
#define EMISSION(side) mat.emission
#define AMBIENT_BASE(side) (mat.ambient * uModelAmbient)
#define LIGHT_AMBIENT(side, i) (mat.ambient * uLightAmbient[i])
#define LIGHT_DIFFUSE(side, i) (mat.diffuse * uLightDiffuse[i])
#define LIGHT_SPECULAR(side, i) (mat.specular * uLightSpecular[i])
#define SHININESS(side) mat.shininess
#else
uniform vec3 uBase[2];  // emission + ambient x light-model ambient, [front, back]
#define MATERIAL_PARAMETER
#define MATERIAL_ARGUMENT
#define LIGHT_SLOTS (2 * NUM_LIGHTS)
#define EMISSION(side) vec3(0.0)
#define AMBIENT_BASE(side) uBase[side]
#define LIGHT_AMBIENT(side, i) uLightAmbient[(side) * NUM_LIGHTS + (i)]
#define LIGHT_DIFFUSE(side, i) uLightDiffuse[(side) * NUM_LIGHTS + (i)]
#define LIGHT_SPECULAR(side, i) uLightSpecular[(side) * NUM_LIGHTS + (i)]
#define SHININESS(side) uShininess[side]
#endif

#if NUM_LIGHTS > 0
uniform vec3 uLightAmbient[LIGHT_SLOTS];  // products: front, then back; MATERIALS: the lights' colours
uniform vec3 uLightDiffuse[LIGHT_SLOTS];
uniform vec4 uLightPosition[NUM_LIGHTS];  // w = 0: unit direction; w = 1: eye-space point
#ifdef HAS_SPECULAR
uniform vec3 uLightSpecular[LIGHT_SLOTS];
uniform float uShininess[2];
#endif
#ifdef HAS_SPOT
uniform vec3 uSpotDirection[NUM_LIGHTS];
uniform float uSpotExponent[NUM_LIGHTS];
uniform float uSpotCosCutoff[NUM_LIGHTS];  // -2 for a light with no spot (cutoff 180)
#endif
#ifdef HAS_ATTENUATION
uniform vec3 uAttenuation[NUM_LIGHTS];  // constant, linear, quadratic
#endif
#endif

#if defined(SHADOWS) && NUM_LIGHTS > 0
#include "shadows.glsl"
#endif

#if defined(TONE_GOOCH) || defined(TONE_SPLASHBACK)
uniform vec3 uCool[2];  // MATERIALS: [0] is k_blue alone, [1] unused
uniform vec3 uWarm[2];  // MATERIALS: [0] is k_yellow alone
uniform vec2 uSplash;   // alpha, power
#ifdef MATERIALS
uniform vec2 uToneWeights;  // alpha, beta: k_cool = k_blue + alpha k_d
#endif
#endif

const float kMaxFloat = 3.402823e38;

// x^e with OpenGL's convention x^0 = 1, and 0 for x <= 0 otherwise (GLSL's pow is undefined there).
float powGL(float x, float e) {
  if (e == 0.0) return 1.0;
  return x > 0.0 ? pow(x, e) : 0.0;
}

vec3 safeNormalize(vec3 v) {
  float len = length(v);
  return (len > 0.0 && !isinf(len)) ? v / len : vec3(0.0);
}

vec3 clamp01(vec3 c) {  // NaN -> 0, like the CPU
  bvec3 positive = greaterThan(c, vec3(0.0));
  return mix(vec3(0.0), min(c, vec3(1.0)), positive);
}

#if NUM_LIGHTS > 0
// Light i as seen from eye-space point `pos` with unit normal `n`: the unit direction to it,
// its attenuation and its spot factor (0: outside the cone).
void lightReach(int i, vec3 pos, vec3 n, out vec3 vp, out float att, out float spot) {
  vp = uLightPosition[i].xyz;
  att = 1.0;
#ifdef HAS_POSITIONAL
  if (uLightPosition[i].w != 0.0) {
    vec3 d = uLightPosition[i].xyz - pos;
    float dist = length(d);
    vp = (dist > 0.0 && !isinf(dist)) ? d / dist : n;
#ifdef HAS_ATTENUATION
    float den = uAttenuation[i].x + (uAttenuation[i].y + uAttenuation[i].z * dist) * dist;
    att = den > 0.0 ? 1.0 / den : kMaxFloat;
    if (isinf(att)) att = kMaxFloat;
#endif
  }
#endif
  spot = 1.0;
#ifdef HAS_SPOT
  float sdot = dot(-vp, uSpotDirection[i]);
  spot = sdot >= uSpotCosCutoff[i] ? powGL(max(sdot, 0.0), uSpotExponent[i]) : 0.0;
#endif
}
#endif

#if defined(GROUND_SHADOW_MAP) && defined(SHADOWS) && NUM_LIGHTS > 0
// The ground plane's fragments read each light's visibility from the texture the ground's
// shadows were drawn into (shadows/ground_shadow_pass.h): one filtered fetch instead of
// filtering every light's map.
in vec2 vGroundXZ;  // model space
uniform sampler2D uGroundShadows;
uniform vec4 uGroundShadowFrame;  // x0, z0, 1 / width, 1 / depth
float groundShadow(int i) { return texture(uGroundShadows, (vGroundXZ - uGroundShadowFrame.xy) * uGroundShadowFrame.zw)[i]; }
#define SHADOW_LOOKUP(i, pos, n, ndl) groundShadow(i)
#elif defined(SHADOWS)
#define SHADOW_LOOKUP(i, pos, n, ndl) shadowVisibility(i, pos, n, ndl)
#endif

#if defined(CONTROL_SHADOW) && defined(SHADOWS) && NUM_LIGHTS > 0
// Each light's visibility as shadowShareAt found it. Per fragment shadeParts reuses it, so the
// shadow maps are read once per pixel (they are the expensive part on a software rasterizer).
// Per vertex the lighting looks the maps up itself: it lights both sides of a two-sided
// surface, and the share is asked for the front after it.
float controlVisible[NUM_LIGHTS];
#endif
#if defined(CONTROL_SHADOW) && defined(SHADOWS) && NUM_LIGHTS > 0 && !defined(PER_VERTEX_LIGHTING)
#define LIGHT_VISIBILITY(i, pos, n, ndl) controlVisible[i]
#elif defined(SHADOWS)
#define LIGHT_VISIBILITY(i, pos, n, ndl) SHADOW_LOOKUP(i, pos, n, ndl)
#endif

#ifdef CONTROL_SHADOW
// The share of the diffuse light reaching the surface that shadows block: 0 lit (or facing
// away from every light: attached shadow is the tone's business), 1 in full cast shadow; each
// light weighted by its unshadowed diffuse term there (the lights' own colours, so the control
// pass can ask before it lights). Per fragment, call it before shadeParts at the same point:
// that reuses the visibilities found here.
float shadowShareAt(vec3 pos, vec3 normal, bool backFacing) {
#if defined(SHADOWS) && NUM_LIGHTS > 0 && !defined(LIGHTING_OFF)
  vec3 n = safeNormalize(normal);
#ifdef TWO_SIDED
  if (backFacing) n = -n;
#endif
  float diffuseSum = 0.0, blockedSum = 0.0;
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    vec3 vp;
    float att, spot;
    lightReach(i, pos, n, vp, att, spot);
    float ndl = max(dot(n, vp), 0.0);
    controlVisible[i] = ndl > 0.0 && spot != 0.0 ? SHADOW_LOOKUP(i, pos, n, ndl) : 1.0;
    // Bounded weights (attenuation can reach kMaxFloat): the share stays finite.
    float reach = ndl * min(att * spot, 1e6) * dot(uLightDiffuse[i], vec3(1.0 / 3.0));
    if (!(reach > 0.0) || isinf(reach)) continue;
    diffuseSum += reach;
    blockedSum += reach * (1.0 - controlVisible[i]);
  }
  return diffuseSum > 0.0 ? clamp(blockedSum / diffuseSum, 0.0, 1.0) : 0.0;
#else
  return 0.0;
#endif
}
#endif

// The lit colour in two parts: the return value is what a surface colour does not scale
// (emission, specular), `scaled` what it does (ambient and diffuse), so a vertex colour or a
// texture map can modulate the reflectance after lighting (per vertex: the triangle's map
// average is applied per fragment). shadeGL is their sum, clamped.
vec3 shadeParts(MATERIAL_PARAMETER vec3 pos, vec3 normal, bool backFacing, out vec3 scaled) {
  scaled = vec3(0.0);
#ifdef LIGHTING_OFF
  return vec3(1.0);
#else
  int side = 0;
#ifdef TWO_SIDED
  if (backFacing) side = 1;
#endif
  vec3 n = safeNormalize(normal);
  if (side == 1) n = -n;
#ifdef TONE_CHARCOAL
  // (1 + V.N) / 3 with the true direction to the eye (the origin of eye space).
  vec3 toEye = safeNormalize(-pos);
  if (toEye == vec3(0.0)) toEye = vec3(0.0, 0.0, 1.0);
  return vec3(clamp((1.0 + dot(n, toEye)) / 3.0, 0.0, 1.0));
#endif
#if defined(TONE_GOOCH) || defined(TONE_SPLASHBACK)
  // Cool-to-warm tone with the first light (see lighting_model.h for the sign convention).
  vec3 vp = vec3(0.0, 0.0, 1.0);
#if NUM_LIGHTS > 0
  vp = uLightPosition[0].w != 0.0 ? safeNormalize(uLightPosition[0].xyz - pos) : uLightPosition[0].xyz;
#endif
  float ndl = dot(n, vp);
#if defined(SHADOWS) && NUM_LIGHTS > 0
  // In the first light's cast shadow the surface turns as far as the terminator's tone: a
  // blocked light lights no more than one grazing the surface (lighting_model.h alike).
  if (ndl > 0.0) ndl *= LIGHT_VISIBILITY(0, pos, n, ndl);
#endif
  float t = (1.0 - ndl) * 0.5;
#ifdef MATERIALS
  vec3 tone = t * uCool[0] + (1.0 - t) * uWarm[0];
  scaled = mat.diffuse * (t * uToneWeights.x + (1.0 - t) * uToneWeights.y);
#else
  vec3 tone = t * uCool[side] + (1.0 - t) * uWarm[side];
#endif
#ifdef TONE_SPLASHBACK
  float splash = powGL(uSplash.x * abs(ndl) + (1.0 - uSplash.x), uSplash.y);
  tone *= splash;
  scaled *= splash;
#endif
  return tone;
#endif
  vec3 c = EMISSION(side);
  scaled = AMBIENT_BASE(side);
#if NUM_LIGHTS > 0
#ifdef HAS_SPECULAR
  vec3 toEye = vec3(0.0, 0.0, 1.0);
#ifdef LOCAL_VIEWER
  toEye = safeNormalize(-pos);
  if (toEye == vec3(0.0)) toEye = vec3(0.0, 0.0, 1.0);
#endif
#endif
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    vec3 vp;
    float att, spot;
    lightReach(i, pos, n, vp, att, spot);
    if (spot == 0.0) continue;
    float ndl = max(dot(n, vp), 0.0);
    float visible = 1.0;
#ifdef SHADOWS
    if (ndl > 0.0) visible = LIGHT_VISIBILITY(i, pos, n, ndl);
    ndl *= visible;
#endif
    vec3 term = LIGHT_AMBIENT(side, i) + ndl * LIGHT_DIFFUSE(side, i);
    vec3 contrib = (att * spot) * term;
    scaled += mix(contrib, vec3(0.0), isnan(contrib));
#ifdef HAS_SPECULAR
    if (ndl > 0.0) {
      vec3 h = safeNormalize(vp + toEye);
      vec3 spec = (visible * att * spot) * powGL(max(dot(n, h), 0.0), SHININESS(side)) * LIGHT_SPECULAR(side, i);
      c += mix(spec, vec3(0.0), isnan(spec));
    }
#endif
  }
#endif
  return c;
#endif
}

// The lit colour with the surface's ambient and diffuse reflectance scaled by `scale`.
vec3 shadeScaled(MATERIAL_PARAMETER vec3 pos, vec3 normal, bool backFacing, vec3 scale) {
  vec3 scaled;
  vec3 c = shadeParts(MATERIAL_ARGUMENT pos, normal, backFacing, scaled);
  return clamp01(c + scaled * scale);
}

#ifndef MATERIALS
vec3 shadeGL(vec3 pos, vec3 normal, bool backFacing) { return shadeScaled(pos, normal, backFacing, vec3(1.0)); }
#endif
