// The animation tests' skinned cylinder (see skinned_cylinder.h).
#include "support/skinned_cylinder.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/mesh/mesh_generators.h"

namespace npr::test {
namespace {

double upperWeight(double y) { return std::clamp((y + 0.15) / 0.3, 0.0, 1.0); }

}  // namespace

Mesh skinnedCylinder(int around, int along) {
  Mesh m = cylinder(around, along);
  m.deformation.joints.assign(m.positions.size(), glm::u16vec4(0, 1, 0, 0));
  m.deformation.weights.resize(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const float w1 = static_cast<float>(upperWeight(m.positions[i].y));
    m.deformation.weights[i] = glm::vec4(1.0f - w1, w1, 0.0f, 0.0f);
  }
  return m;
}

std::vector<glm::mat4> bendJoints(float degrees) {
  return {glm::mat4(1.0f), glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 0, 1))};
}

glm::dvec3 referenceBend(const Mesh& m, std::size_t i, double degrees) {
  const glm::dvec3 p(m.positions[i]);
  const double a = degrees * M_PI / 180.0;
  const glm::dvec3 turned(p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z);
  const double w1 = upperWeight(p.y);
  return (1.0 - w1) * p + w1 * turned;
}

}  // namespace npr::test
