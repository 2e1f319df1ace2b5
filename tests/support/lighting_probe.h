// Evaluates the GLSL lighting (shaders/lighting.glsl) at arbitrary eye-space points and
// normals on the GPU and reads the colours back: the check that CPU and GLSL compute the
// same equation. Needs a current GL context.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/lighting/lighting_state.h"
#include "renderer/core/result.h"

namespace npr {

struct LightingSample {
  glm::vec3 position;  // eye space
  glm::vec3 normal;
  bool back = false;
};

Result<std::vector<glm::vec3>> evaluateLightingOnGpu(const LightingState& state, const std::vector<LightingSample>& samples);

}  // namespace npr
