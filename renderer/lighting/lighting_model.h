// The OpenGL 2.1 lighting equation (section 2.14.1) evaluated on the CPU, in float for the
// renderer and in double for accuracy references. shaders/lighting.glsl is the same equation;
// the two must agree within 1/255 (tested).
//
// The state is first "prepared" into a lighting space: products of light and material
// colours are folded, disabled lights dropped, and positions moved into that space. Eye space
// is the spec's; for a rigid modelview the renderer prepares in object space instead, so the
// per-triangle loop needs no matrix work (dot products and distances are the same there).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "renderer/lighting/lighting_state.h"

namespace npr {

template <class T>
struct PreparedLighting {
  using V3 = glm::vec<3, T>;
  struct L {
    V3 ambient[2], diffuse[2], specular[2];  // [front, back] light x material products
    V3 position;                             // positional: a point; directional: unit direction
    bool positional = false;
    V3 spotDirection{0};                     // unit
    T spotExponent = 0, spotCosCutoff = -1;
    bool spot = false;
    T k0 = 1, k1 = 0, k2 = 0;
    bool attenuation = false;
  };
  L lights[kMaxLights];
  int count = 0;
  V3 base[2];  // emission + material ambient x light-model ambient, [front, back]
  V3 emission[2];  // the part of base that a surface colour does not scale
  T shininess[2] = {0, 0};
  bool lighting = true, specular = false, localViewer = false, twoSided = false;
  V3 eye{0};              // local viewer: the eye's position in the lighting space
  V3 viewDirection{0, 0, 1};  // infinite viewer: direction towards the eye
  V3 unlit{1};
  // Tone models (Gooch, splashback): cool and warm colours per side, the splash multiplier.
  ToneModel tone = ToneModel::OpenGL;
  V3 cool[2], warm[2];
  V3 coolBase{0}, warmBase{0}, kd[2];  // cool = coolBase + alpha kd (kd scaled by a surface colour)
  T toneAlpha = 0, toneBeta = 0;
  T splashAlpha = 0, splashPower = 0;
};

// `toSpace` maps eye space into the lighting space (identity for eye space; the inverse of a
// modelview that is a similarity for object space).
template <class T>
PreparedLighting<T> prepareLighting(const LightingState& s, const glm::mat4& toSpace = glm::mat4(1.0f)) {
  using V3 = glm::vec<3, T>;
  using M4 = glm::mat<4, 4, T>;
  using V4 = glm::vec<4, T>;
  PreparedLighting<T> p;
  const M4 m(toSpace);
  const T spaceScale = glm::length(V3(m[0]));
  const LightingFeatures f = s.features();
  p.lighting = f.lighting;
  p.unlit = V3(s.unlitColor());
  p.specular = f.specular;
  p.localViewer = f.localViewer;
  p.twoSided = f.twoSided;
  p.eye = V3(m * V4(0, 0, 0, 1));
  p.viewDirection = glm::normalize(V3(m * V4(0, 0, 1, 0)));
  const Material* mats[2] = {&s.front(), &s.back()};
  for (int side = 0; side < 2; ++side) {
    p.emission[side] = V3(mats[side]->emission);
    p.base[side] = V3(mats[side]->emission) + V3(mats[side]->ambient) * V3(s.modelAmbient());
    p.shininess[side] = static_cast<T>(mats[side]->shininess);
  }
  p.tone = f.tone;
  const ToneParameters& tp = s.toneParameters();
  for (int side = 0; side < 2; ++side) {
    const V3 kd(mats[side]->diffuse);
    p.cool[side] = V3(0, 0, tp.blue) + T(tp.alpha) * kd;
    p.warm[side] = V3(tp.yellow, tp.yellow, 0) + T(tp.beta) * kd;
    p.kd[side] = kd;
  }
  p.coolBase = V3(0, 0, tp.blue);
  p.warmBase = V3(tp.yellow, tp.yellow, 0);
  p.toneAlpha = T(tp.alpha);
  p.toneBeta = T(tp.beta);
  p.splashAlpha = T(tp.splashAlpha);
  p.splashPower = T(tp.splashPower);
  for (int i = 0; i < kMaxLights; ++i) {
    const Light& l = s.light(i);
    if (!l.enabled) continue;
    auto& q = p.lights[p.count++];
    for (int side = 0; side < 2; ++side) {
      q.ambient[side] = V3(l.ambient) * V3(mats[side]->ambient);
      q.diffuse[side] = V3(l.diffuse) * V3(mats[side]->diffuse);
      q.specular[side] = V3(l.specular) * V3(mats[side]->specular);
    }
    q.positional = l.position.w != 0.0f;
    if (q.positional) {
      q.position = V3(m * V4(V3(l.position) / static_cast<T>(l.position.w), 1));
    } else {
      const V3 d = V3(m * V4(V3(l.position), 0));
      const T len = glm::length(d);
      q.position = len > 0 && std::isfinite(len) ? d / len : V3(0, 0, 1);
    }
    q.spot = l.spotCutoff != 180.0f;
    const V3 sd = V3(m * V4(V3(l.spotDirection), 0));
    const T sl = glm::length(sd);
    q.spotDirection = sl > 0 && std::isfinite(sl) ? sd / sl : V3(0, 0, -1);
    q.spotExponent = static_cast<T>(l.spotExponent);
    q.spotCosCutoff = std::cos(static_cast<T>(l.spotCutoff) * static_cast<T>(3.14159265358979323846 / 180.0));
    q.attenuation = q.positional;
    q.k0 = static_cast<T>(l.constantAttenuation);
    q.k1 = static_cast<T>(l.linearAttenuation);
    q.k2 = static_cast<T>(l.quadraticAttenuation);
    // A space scaled from the eye's (a similarity's inverse) measures distances `spaceScale`
    // times the eye's: the attenuation is the eye's.
    if (std::abs(spaceScale - T(1)) > T(1e-6)) {
      q.k1 /= spaceScale;
      q.k2 /= spaceScale * spaceScale;
    }
  }
  return p;
}

namespace lighting_detail {

template <class T>
T clamp01(T x) { return x > T(0) ? (x < T(1) ? x : T(1)) : T(0); }  // NaN -> 0

// pow with OpenGL's convention x^0 = 1 (also for x = 0), and 0 for x <= 0 otherwise.
template <class T>
T powGL(T x, T e) {
  if (e == T(0)) return T(1);
  return x > T(0) ? std::pow(x, e) : T(0);
}

template <class T>
glm::vec<3, T> safeNormalize(const glm::vec<3, T>& v) {
  const T len = glm::length(v);
  return len > T(0) && std::isfinite(len) ? v / len : glm::vec<3, T>(0);
}

}  // namespace lighting_detail

// The lit colour at point `pos` with normal `normal`, both in the prepared space. `back`
// selects the back material and the flipped normal (only when two-sided lighting is on).
// `scale` multiplies the material's ambient and diffuse reflectance (a vertex colour or a
// texture's colour at the point), as a colour-material or a modulating texture would.
// `visibility`, when given, is how much of each light (in p.lights order) reaches the point:
// 1 lit, 0 blocked (a cast shadow keeps the light's ambient term only, as lighting.glsl does).
// Always finite and in [0,1]: degenerate input (zero or NaN normal, NaN position, a light
// at the point, zero attenuation) gives a defined colour, never NaN.
template <class T>
glm::vec<3, T> shade(const PreparedLighting<T>& p, const glm::vec<3, T>& pos, const glm::vec<3, T>& normal, bool back = false,
                     const glm::vec<3, T>& scale = glm::vec<3, T>(1), const T* visibility = nullptr) {
  using namespace lighting_detail;
  using V3 = glm::vec<3, T>;
  if (!p.lighting) return p.unlit;
  const int side = (back && p.twoSided) ? 1 : 0;
  V3 n = safeNormalize(normal);
  if (side) n = -n;
  if (p.tone == ToneModel::Charcoal) {
    // The true direction to the eye even for an infinite viewer: at the silhouette it is
    // what makes V.N zero.
    V3 toEye = safeNormalize(p.eye - pos);
    if (toEye == V3(0)) toEye = p.viewDirection;
    const T t = clamp01((T(1) + glm::dot(n, toEye)) / T(3));
    return V3(t);
  }
  if (p.tone != ToneModel::OpenGL) {
    // Gooch: l is the direction the light travels (towards the surface), so surfaces facing
    // the light (l.n = -1) get the warm colour and those facing away the cool one.
    V3 vp(0, 0, 1);  // no light: a headlight
    if (p.count > 0) {
      const auto& l = p.lights[0];
      vp = l.positional ? safeNormalize(l.position - pos) : l.position;
    }
    T ndl = glm::dot(n, vp);
    // In the first light's cast shadow: no more than the terminator's tone (lighting.glsl alike).
    if (visibility && p.count > 0 && ndl > T(0)) ndl *= clamp01(visibility[0]);
    const T t = (T(1) - ndl) * T(0.5);  // (1 + l.n) / 2 with l = -vp
    V3 c = t * (p.coolBase + p.toneAlpha * p.kd[side] * scale) + (T(1) - t) * (p.warmBase + p.toneBeta * p.kd[side] * scale);
    if (p.tone == ToneModel::Splashback) c *= powGL(p.splashAlpha * std::fabs(ndl) + (T(1) - p.splashAlpha), p.splashPower);
    return V3(clamp01(c.x), clamp01(c.y), clamp01(c.z));
  }
  V3 c = p.emission[side];               // what the surface colour does not scale
  V3 scaled = p.base[side] - p.emission[side];  // ambient and diffuse: what it does
  V3 toEye = p.viewDirection;
  if (p.localViewer) {
    toEye = safeNormalize(p.eye - pos);
    if (toEye == V3(0)) toEye = p.viewDirection;  // the eye at the point: fall back to the axis
  }
  for (int i = 0; i < p.count; ++i) {
    const auto& l = p.lights[i];
    V3 vp = l.position;  // unit vector from the point to the light
    T att = T(1);
    if (l.positional) {
      const V3 d = l.position - pos;
      const T dist = glm::length(d);
      // A light at the point (or a non-finite point) has no direction: light it head-on.
      vp = dist > T(0) && std::isfinite(dist) ? d / dist : n;
      const T den = l.k0 + (l.k1 + l.k2 * dist) * dist;
      // Zero attenuation coefficients (or a light at the point with k0 = 0) would divide by
      // zero; the largest finite factor gives the same clamped colour OpenGL aims for.
      att = den > T(0) ? T(1) / den : std::numeric_limits<T>::max();
      if (!std::isfinite(att)) att = std::numeric_limits<T>::max();
    }
    T spot = T(1);
    if (l.spot) {
      const T sdot = glm::dot(-vp, l.spotDirection);
      spot = sdot >= l.spotCosCutoff ? powGL(std::max(sdot, T(0)), l.spotExponent) : T(0);
    }
    if (spot == T(0)) continue;
    const T visible = visibility ? clamp01(visibility[i]) : T(1);
    const T ndl = std::max(glm::dot(n, vp), T(0)) * visible;
    V3 term = l.ambient[side] + ndl * l.diffuse[side];
    V3 spec(0);
    if (p.specular && ndl > T(0)) {
      const V3 h = safeNormalize(vp + toEye);
      spec = visible * powGL(std::max(glm::dot(n, h), T(0)), p.shininess[side]) * l.specular[side];
    }
    V3 contrib = (att * spot) * term, contribSpec = (att * spot) * spec;
    for (int k = 0; k < 3; ++k) {
      if (std::isnan(contrib[k])) contrib[k] = T(0);  // inf x 0 from huge colours
      if (std::isnan(contribSpec[k])) contribSpec[k] = T(0);
    }
    scaled += contrib;
    c += contribSpec;
  }
  c += scaled * scale;
  for (int k = 0; k < 3; ++k)
    if (std::isnan(c[k])) c[k] = T(0);
  return V3(clamp01(c.x), clamp01(c.y), clamp01(c.z));
}

}  // namespace npr
