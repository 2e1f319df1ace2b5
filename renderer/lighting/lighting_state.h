// The OpenGL 2.1 fixed-function lighting state (spec section 2.14.1) with OpenGL's own
// defaults, set through calls shaped like OpenGL's (Lightfv, Materialfv, LightModelfv...),
// as the original palette renderer offered. Invalid parameters are refused with a message
// and leave the state unchanged, as OpenGL does with GL_INVALID_VALUE.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/result.h"
#include "renderer/settings/choices.h"

namespace npr {

constexpr int kMaxLights = 8;

struct Light {
  bool enabled = false;
  glm::vec4 ambient{0, 0, 0, 1};
  glm::vec4 diffuse{0, 0, 0, 1};   // light 0: white
  glm::vec4 specular{0, 0, 0, 1};  // light 0: white
  glm::vec4 position{0, 0, 1, 0};  // eye space, transformed by the modelview current when set
  glm::vec3 spotDirection{0, 0, -1};  // eye space
  float spotExponent = 0.0f;
  float spotCutoff = 180.0f;
  float constantAttenuation = 1.0f;
  float linearAttenuation = 0.0f;
  float quadraticAttenuation = 0.0f;
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  glm::vec4 specular{0, 0, 0, 1};
  glm::vec4 emission{0, 0, 0, 1};
  float shininess = 0.0f;
};

// What the lit colour is computed with. OpenGL is the fixed-function equation; Gooch is
// cool-to-warm tone (Gooch et al. 1998) with the first enabled light; Splashback multiplies
// Gooch by (alpha |cos theta| + 1 - alpha)^p, theta between the normal and that light.
// Charcoal (the NPR lecture slides) ignores lights and colours: grey (1 + V.N) / 3 with V
// towards the eye, bright where the surface faces the viewer, 1/3 at the silhouette.
// (ToneModel is one of the settings' choices: settings/choices.h.)

struct ToneParameters {
  float blue = 0.4f;    // k_blue = (0, 0, blue)
  float yellow = 0.4f;  // k_yellow = (yellow, yellow, 0)
  float alpha = 0.2f;   // k_cool = k_blue + alpha k_d
  float beta = 0.6f;    // k_warm = k_yellow + beta k_d
  float splashAlpha = 0.5f;
  float splashPower = 2.0f;
};

// Which parts of the lighting equation a scene uses: shaders are compiled for exactly these,
// and the CPU lighting skips the rest.
struct LightingFeatures {
  int lightCount = 0;  // enabled lights
  bool lighting = true;
  bool positional = false;
  bool attenuation = false;
  bool spot = false;
  bool specular = false;
  bool localViewer = false;
  bool twoSided = false;
  ToneModel tone = ToneModel::OpenGL;
  bool operator==(const LightingFeatures& o) const;
  bool operator!=(const LightingFeatures& o) const { return !(*this == o); }
  std::vector<std::string> glslDefines() const;  // NUM_LIGHTS n, HAS_SPOT, ...
};

class LightingState {
 public:
  LightingState();

  // OpenGL-shaped state calls. `light` is GL_LIGHT0 + i; `face` is GL_FRONT, GL_BACK or
  // GL_FRONT_AND_BACK. Each returns an error (and changes nothing) where OpenGL would raise
  // GL_INVALID_ENUM or GL_INVALID_VALUE.
  Status Lightfv(GLenum light, GLenum pname, const float* values);
  Status Lightf(GLenum light, GLenum pname, float value);
  Status Materialfv(GLenum face, GLenum pname, const float* values);
  Status Materialf(GLenum face, GLenum pname, float value);
  Status LightModelfv(GLenum pname, const float* values);
  Status LightModeli(GLenum pname, int value);
  Status Enable(GLenum cap);
  Status Disable(GLenum cap);
  // The modelview used to transform light positions and spot directions when they are set.
  void setModelView(const glm::mat4& m) { modelView_ = m; }
  const glm::mat4& modelView() const { return modelView_; }

  const Light& light(int i) const { return lights_[static_cast<size_t>(i)]; }
  const Material& front() const { return front_; }
  const Material& back() const { return back_; }
  const glm::vec4& modelAmbient() const { return modelAmbient_; }
  bool localViewer() const { return localViewer_; }
  bool twoSided() const { return twoSided_; }
  bool lightingEnabled() const { return lighting_; }
  // Blue and yellow in [0,1], alpha and beta in [0,1], splash alpha in [0,1], power in [0,64].
  Status setToneModel(ToneModel model, const ToneParameters& parameters);
  ToneModel toneModel() const { return tone_; }
  const ToneParameters& toneParameters() const { return toneParams_; }
  glm::vec4 unlitColor() const { return {1, 1, 1, 1}; }  // glColor's default: what "lighting off" shows

  LightingFeatures features() const;
  // This state with `m` as the front and back material: how a mesh's own material is lit (the
  // material's values are the caller's to keep in OpenGL's ranges).
  LightingState withMaterial(const Material& m) const {
    LightingState s = *this;
    s.front_ = s.back_ = m;
    return s;
  }
  // Bumped on every successful change, so dependants recompute only when something changed.
  unsigned revision() const { return revision_; }

 private:
  Status setEnabled(GLenum cap, bool on);
  std::array<Light, kMaxLights> lights_;
  Material front_, back_;
  glm::vec4 modelAmbient_{0.2f, 0.2f, 0.2f, 1.0f};
  bool localViewer_ = false;
  bool twoSided_ = false;
  bool lighting_ = true;  // the renderer's whole purpose is lighting, so it starts enabled
  glm::mat4 modelView_{1.0f};
  ToneModel tone_ = ToneModel::OpenGL;
  ToneParameters toneParams_;
  unsigned revision_ = 0;
};

// The viewer's default material: OpenGL's defaults plus a modest specular highlight, so
// hatching shows a highlight on glossy parts.
void applyDefaultMaterial(LightingState& lighting);

}  // namespace npr
