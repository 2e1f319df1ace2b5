// OpenGL-shaped lighting state calls with OpenGL's validation rules (see lighting_state.h).
#include "renderer/lighting/lighting_state.h"

#include <cassert>
#include <cmath>
#include <cstdio>

namespace npr {
namespace {

std::string hexEnum(GLenum e) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04X", e);
  return buf;
}

bool allFinite(const float* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

Status invalid(const std::string& call, const std::string& why) { return Error{call + ": " + why + "; state unchanged"}; }

}  // namespace

Status LightingState::setToneModel(ToneModel model, const ToneParameters& p) {
  auto in01 = [](float v) { return v >= 0.0f && v <= 1.0f; };
  if (!in01(p.blue) || !in01(p.yellow) || !in01(p.alpha) || !in01(p.beta) || !in01(p.splashAlpha))
    return invalid("setToneModel", "blue, yellow, alpha, beta and splash alpha must be in [0, 1]");
  if (!(p.splashPower >= 0.0f && p.splashPower <= 64.0f)) return invalid("setToneModel", "splash power must be in [0, 64]");
  tone_ = model;
  toneParams_ = p;
  ++revision_;
  return okStatus();
}

bool LightingFeatures::operator==(const LightingFeatures& o) const {
  return tone == o.tone && lightCount == o.lightCount && lighting == o.lighting && positional == o.positional &&
         attenuation == o.attenuation && spot == o.spot && specular == o.specular && localViewer == o.localViewer &&
         twoSided == o.twoSided;
}

std::vector<std::string> LightingFeatures::glslDefines() const {
  std::vector<std::string> d;
  if (!lighting) {
    d.push_back("LIGHTING_OFF");
    d.push_back("NUM_LIGHTS 0");
    return d;
  }
  d.push_back("NUM_LIGHTS " + std::to_string(lightCount));
  if (tone == ToneModel::Gooch) d.push_back("TONE_GOOCH");
  if (tone == ToneModel::Splashback) d.push_back("TONE_SPLASHBACK");
  if (tone == ToneModel::Charcoal) d.push_back("TONE_CHARCOAL");
  if (positional) d.push_back("HAS_POSITIONAL");
  if (attenuation) d.push_back("HAS_ATTENUATION");
  if (spot) d.push_back("HAS_SPOT");
  if (specular) d.push_back("HAS_SPECULAR");
  if (localViewer) d.push_back("LOCAL_VIEWER");
  if (twoSided) d.push_back("TWO_SIDED");
  return d;
}

LightingState::LightingState() {
  lights_[0].diffuse = {1, 1, 1, 1};
  lights_[0].specular = {1, 1, 1, 1};
  lights_[0].enabled = true;  // a lit renderer with no light would show only ambient
}

Status LightingState::Lightfv(GLenum light, GLenum pname, const float* v) {
  const std::string call = "Lightfv(" + hexEnum(light) + ", " + hexEnum(pname) + ")";
  if (light < GL_LIGHT0 || light >= GL_LIGHT0 + kMaxLights)
    return invalid(call, "light must be GL_LIGHT0..GL_LIGHT7");
  if (!v) return invalid(call, "null value pointer");
  Light next = lights_[light - GL_LIGHT0];
  switch (pname) {
    case GL_AMBIENT: if (!allFinite(v, 4)) return invalid(call, "non-finite colour"); next.ambient = {v[0], v[1], v[2], v[3]}; break;
    case GL_DIFFUSE: if (!allFinite(v, 4)) return invalid(call, "non-finite colour"); next.diffuse = {v[0], v[1], v[2], v[3]}; break;
    case GL_SPECULAR: if (!allFinite(v, 4)) return invalid(call, "non-finite colour"); next.specular = {v[0], v[1], v[2], v[3]}; break;
    case GL_POSITION:
      if (!allFinite(v, 4)) return invalid(call, "non-finite position");
      next.position = modelView_ * glm::vec4(v[0], v[1], v[2], v[3]);
      break;
    case GL_SPOT_DIRECTION:
      if (!allFinite(v, 3)) return invalid(call, "non-finite direction");
      next.spotDirection = glm::mat3(modelView_) * glm::vec3(v[0], v[1], v[2]);
      break;
    case GL_SPOT_EXPONENT:
      if (!(v[0] >= 0.0f && v[0] <= 128.0f)) return invalid(call, "spot exponent must be in [0, 128]");
      next.spotExponent = v[0];
      break;
    case GL_SPOT_CUTOFF:
      if (!((v[0] >= 0.0f && v[0] <= 90.0f) || v[0] == 180.0f))
        return invalid(call, "spot cutoff must be in [0, 90], or 180 for no spotlight");
      next.spotCutoff = v[0];
      break;
    case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION:
      if (!(v[0] >= 0.0f) || !std::isfinite(v[0])) return invalid(call, "attenuation must be a finite value >= 0");
      (pname == GL_CONSTANT_ATTENUATION ? next.constantAttenuation
       : pname == GL_LINEAR_ATTENUATION ? next.linearAttenuation
                                        : next.quadraticAttenuation) = v[0];
      break;
    default: return invalid(call, "unknown light parameter");
  }
  lights_[light - GL_LIGHT0] = next;
  ++revision_;
  return okStatus();
}

Status LightingState::Lightf(GLenum light, GLenum pname, float value) {
  if (pname != GL_SPOT_EXPONENT && pname != GL_SPOT_CUTOFF && pname != GL_CONSTANT_ATTENUATION &&
      pname != GL_LINEAR_ATTENUATION && pname != GL_QUADRATIC_ATTENUATION)
    return invalid("Lightf(" + hexEnum(pname) + ")", "only scalar parameters can be set with Lightf");
  return Lightfv(light, pname, &value);
}

Status LightingState::Materialfv(GLenum face, GLenum pname, const float* v) {
  const std::string call = "Materialfv(" + hexEnum(face) + ", " + hexEnum(pname) + ")";
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return invalid(call, "face must be GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (!v) return invalid(call, "null value pointer");
  auto apply = [&](Material& m) -> Status {
    switch (pname) {
      case GL_AMBIENT: m.ambient = {v[0], v[1], v[2], v[3]}; break;
      case GL_DIFFUSE: m.diffuse = {v[0], v[1], v[2], v[3]}; break;
      case GL_SPECULAR: m.specular = {v[0], v[1], v[2], v[3]}; break;
      case GL_EMISSION: m.emission = {v[0], v[1], v[2], v[3]}; break;
      case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = {v[0], v[1], v[2], v[3]}; break;
      case GL_SHININESS:
        if (!(v[0] >= 0.0f && v[0] <= 128.0f)) return invalid(call, "shininess must be in [0, 128]");
        m.shininess = v[0];
        break;
      default: return invalid(call, "unknown material parameter");
    }
    return okStatus();
  };
  if (pname != GL_SHININESS && !allFinite(v, 4)) return invalid(call, "non-finite colour");
  Material f = front_, b = back_;
  if (face != GL_BACK) if (Status s = apply(f); !s) return s;
  if (face != GL_FRONT) if (Status s = apply(b); !s) return s;
  front_ = f;
  back_ = b;
  ++revision_;
  return okStatus();
}

Status LightingState::Materialf(GLenum face, GLenum pname, float value) {
  if (pname != GL_SHININESS) return invalid("Materialf(" + hexEnum(pname) + ")", "only GL_SHININESS is scalar");
  return Materialfv(face, pname, &value);
}

Status LightingState::LightModelfv(GLenum pname, const float* v) {
  const std::string call = "LightModelfv(" + hexEnum(pname) + ")";
  if (!v) return invalid(call, "null value pointer");
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
      if (!allFinite(v, 4)) return invalid(call, "non-finite colour");
      modelAmbient_ = {v[0], v[1], v[2], v[3]};
      break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: localViewer_ = v[0] != 0.0f; break;
    case GL_LIGHT_MODEL_TWO_SIDE: twoSided_ = v[0] != 0.0f; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      if (static_cast<GLenum>(v[0]) != GL_SINGLE_COLOR)
        return invalid(call, "only GL_SINGLE_COLOR is supported: the lit colour is matched, not textured");
      break;
    default: return invalid(call, "unknown light model parameter");
  }
  ++revision_;
  return okStatus();
}

Status LightingState::LightModeli(GLenum pname, int value) {
  const float f = static_cast<float>(value);
  if (pname == GL_LIGHT_MODEL_AMBIENT) return invalid("LightModeli", "GL_LIGHT_MODEL_AMBIENT needs LightModelfv");
  return LightModelfv(pname, &f);
}

Status LightingState::setEnabled(GLenum cap, bool on) {
  if (cap == GL_LIGHTING) lighting_ = on;
  else if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + kMaxLights) lights_[cap - GL_LIGHT0].enabled = on;
  else return invalid(std::string(on ? "Enable" : "Disable") + "(" + hexEnum(cap) + ")", "only GL_LIGHTING and GL_LIGHT0..7");
  ++revision_;
  return okStatus();
}

Status LightingState::Enable(GLenum cap) { return setEnabled(cap, true); }
Status LightingState::Disable(GLenum cap) { return setEnabled(cap, false); }

LightingFeatures LightingState::features() const {
  LightingFeatures f;
  f.lighting = lighting_;
  if (!lighting_) return f;
  f.localViewer = localViewer_;
  f.twoSided = twoSided_;
  f.tone = tone_;
  const bool matSpec = glm::any(glm::notEqual(glm::vec3(front_.specular), glm::vec3(0.0f))) ||
                       (twoSided_ && glm::any(glm::notEqual(glm::vec3(back_.specular), glm::vec3(0.0f))));
  for (const Light& l : lights_) {
    if (!l.enabled) continue;
    ++f.lightCount;
    const bool positional = l.position.w != 0.0f;
    f.positional |= positional;
    f.attenuation |= positional && (l.constantAttenuation != 1.0f || l.linearAttenuation != 0.0f || l.quadraticAttenuation != 0.0f);
    f.spot |= l.spotCutoff != 180.0f;
    f.specular |= matSpec && glm::any(glm::notEqual(glm::vec3(l.specular), glm::vec3(0.0f)));
  }
  // The view direction matters only to the specular term, which tone models do not have.
  if (f.tone != ToneModel::OpenGL) f.specular = f.spot = f.attenuation = false;
  if (!f.specular) f.localViewer = false;
  return f;
}

void applyDefaultMaterial(LightingState& lighting) {
  const float spec[4] = {0.35f, 0.35f, 0.35f, 1.0f};
  [[maybe_unused]] const bool ok =
      lighting.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec).ok() && lighting.Materialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f).ok();
  assert(ok && "the default material is within OpenGL's ranges");
}

}  // namespace npr
