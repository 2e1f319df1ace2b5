// File lights as GL lights (see file_lights.h).
#include "app/file_lights.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace npr {

Status applyFileLights(const std::vector<SceneLight>& lights, float fileUnits, const CameraMatrices& camera, LightingState& state) {
  std::vector<float> e(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const SceneLight& l = lights[i];
    const float d = glm::length(glm::vec3(l.world[3])) / std::max(fileUnits, 1e-30f);
    e[i] = l.type == SceneLight::Type::Directional ? l.intensity : l.intensity / std::max(d * d, 1e-12f);
    if (!std::isfinite(e[i])) e[i] = 0.0f;
  }
  std::vector<std::size_t> order(lights.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return e[a] > e[b]; });
  const float brightest = order.empty() ? 0.0f : e[order.front()];
  state.setModelView(camera.view);
  for (int i = 0; i < kMaxLights; ++i) {
    const GLenum id = GL_LIGHT0 + static_cast<GLenum>(i);
    if (i >= static_cast<int>(order.size())) {
      if (Status s = state.Disable(id); !s) return s;
      continue;
    }
    const SceneLight& l = lights[order[static_cast<std::size_t>(i)]];
    const float k = brightest > 0.0f ? e[order[static_cast<std::size_t>(i)]] / brightest : 0.0f;
    const glm::vec3 c = glm::clamp(l.colour, 0.0f, 1.0f) * k;
    const float colour[4] = {c.r, c.g, c.b, 1.0f}, black[4] = {0, 0, 0, 1};
    const glm::vec3 back = glm::normalize(glm::vec3(l.world[2])), at(l.world[3]);
    const float position[4] = {l.type == SceneLight::Type::Directional ? back.x : at.x, l.type == SceneLight::Type::Directional ? back.y : at.y,
                               l.type == SceneLight::Type::Directional ? back.z : at.z, l.type == SceneLight::Type::Directional ? 0.0f : 1.0f};
    const float direction[3] = {-back.x, -back.y, -back.z};
    float cutoff = 180.0f, exponent = 0.0f;
    if (l.type == SceneLight::Type::Spot) {
      cutoff = std::clamp(glm::degrees(l.outerCone), 0.0f, 90.0f);
      const float mid = 0.5f * (l.innerCone + l.outerCone);
      exponent = mid > 1e-4f ? std::clamp(std::log(0.5f) / std::log(std::cos(mid)), 0.0f, 128.0f) : 0.0f;
    }
    for (Status s : {state.Enable(id), state.Lightfv(id, GL_AMBIENT, black), state.Lightfv(id, GL_DIFFUSE, colour),
                     state.Lightfv(id, GL_SPECULAR, colour), state.Lightfv(id, GL_POSITION, position),
                     state.Lightfv(id, GL_SPOT_DIRECTION, direction), state.Lightf(id, GL_SPOT_CUTOFF, cutoff),
                     state.Lightf(id, GL_SPOT_EXPONENT, exponent), state.Lightf(id, GL_CONSTANT_ATTENUATION, 1.0f),
                     state.Lightf(id, GL_LINEAR_ATTENUATION, 0.0f), state.Lightf(id, GL_QUADRATIC_ATTENUATION, 0.0f)})
      if (!s) return s;
  }
  return okStatus();
}

void restoreViewerLight(LightingState& state) {
  const float white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1}, down[3] = {0, 0, -1};
  (void)state.Enable(GL_LIGHT0);
  (void)state.Lightfv(GL_LIGHT0, GL_AMBIENT, black);
  (void)state.Lightfv(GL_LIGHT0, GL_DIFFUSE, white);
  (void)state.Lightfv(GL_LIGHT0, GL_SPECULAR, white);
  (void)state.Lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, down);
  (void)state.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180.0f);
  (void)state.Lightf(GL_LIGHT0, GL_SPOT_EXPONENT, 0.0f);
  (void)state.Lightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 1.0f);
  for (int i = 1; i < kMaxLights; ++i) (void)state.Disable(GL_LIGHT0 + static_cast<GLenum>(i));
}

}  // namespace npr
