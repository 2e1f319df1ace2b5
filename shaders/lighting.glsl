// The OpenGL 2.1 lighting equation (section 2.14.1), in eye space: the same equation as
// renderer/lighting/lighting_model.h, specialised by #defines to the features the scene uses:
// NUM_LIGHTS, HAS_POSITIONAL, HAS_ATTENUATION, HAS_SPOT, HAS_SPECULAR, LOCAL_VIEWER,
// TWO_SIDED, LIGHTING_OFF, and the tone models TONE_GOOCH / TONE_SPLASHBACK. Uniforms are
// the prepared products of light and material colours.

#ifndef NUM_LIGHTS
#define NUM_LIGHTS 0
#endif

uniform vec3 uBase[2];  // emission + ambient x light-model ambient, [front, back]
#if NUM_LIGHTS > 0
uniform vec3 uLightAmbient[2 * NUM_LIGHTS];  // front products, then back products
uniform vec3 uLightDiffuse[2 * NUM_LIGHTS];
uniform vec4 uLightPosition[NUM_LIGHTS];  // w = 0: unit direction; w = 1: eye-space point
#ifdef HAS_SPECULAR
uniform vec3 uLightSpecular[2 * NUM_LIGHTS];
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

#if defined(TONE_GOOCH) || defined(TONE_SPLASHBACK)
uniform vec3 uCool[2];
uniform vec3 uWarm[2];
uniform vec2 uSplash;  // alpha, power
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

vec3 shadeGL(vec3 pos, vec3 normal, bool backFacing) {
#ifdef LIGHTING_OFF
  return vec3(1.0);
#else
  int side = 0;
#ifdef TWO_SIDED
  if (backFacing) side = 1;
#endif
  vec3 n = safeNormalize(normal);
  if (side == 1) n = -n;
#if defined(TONE_GOOCH) || defined(TONE_SPLASHBACK)
  // Cool-to-warm tone with the first light (see lighting_model.h for the sign convention).
  vec3 vp = vec3(0.0, 0.0, 1.0);
#if NUM_LIGHTS > 0
  vp = uLightPosition[0].w != 0.0 ? safeNormalize(uLightPosition[0].xyz - pos) : uLightPosition[0].xyz;
#endif
  float ndl = dot(n, vp);
  float t = (1.0 - ndl) * 0.5;
  vec3 tone = t * uCool[side] + (1.0 - t) * uWarm[side];
#ifdef TONE_SPLASHBACK
  tone *= powGL(uSplash.x * abs(ndl) + (1.0 - uSplash.x), uSplash.y);
#endif
  return clamp01(tone);
#endif
  vec3 c = uBase[side];
#if NUM_LIGHTS > 0
#ifdef HAS_SPECULAR
  vec3 toEye = vec3(0.0, 0.0, 1.0);
#ifdef LOCAL_VIEWER
  toEye = safeNormalize(-pos);
  if (toEye == vec3(0.0)) toEye = vec3(0.0, 0.0, 1.0);
#endif
#endif
  for (int i = 0; i < NUM_LIGHTS; ++i) {
    vec3 vp = uLightPosition[i].xyz;
    float att = 1.0;
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
    float spot = 1.0;
#ifdef HAS_SPOT
    float sdot = dot(-vp, uSpotDirection[i]);
    spot = sdot >= uSpotCosCutoff[i] ? powGL(max(sdot, 0.0), uSpotExponent[i]) : 0.0;
#endif
    if (spot == 0.0) continue;
    float ndl = max(dot(n, vp), 0.0);
    vec3 term = uLightAmbient[side * NUM_LIGHTS + i] + ndl * uLightDiffuse[side * NUM_LIGHTS + i];
#ifdef HAS_SPECULAR
    if (ndl > 0.0) {
      vec3 h = safeNormalize(vp + toEye);
      term += powGL(max(dot(n, h), 0.0), uShininess[side]) * uLightSpecular[side * NUM_LIGHTS + i];
    }
#endif
    vec3 contrib = (att * spot) * term;
    contrib = mix(contrib, vec3(0.0), isnan(contrib));
    c += contrib;
  }
#endif
  return clamp01(c);
#endif
}
