// Analytic principal directions of the generated test surfaces (mesh/mesh_generators.h), and
// the field's angular error against them: what the direction field's tests and benchmark
// compare with.
#pragma once

#include <cstddef>
#include <functional>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr::test {

struct Principal {
  glm::vec3 e1, e2;  // unit: the direction of largest |k|, and across it
  float k1, k2;      // |k| along each
};

Principal cylinderPrincipal(const glm::vec3& p);  // generated cylinder (axis y, radius 0.5)
Principal torusPrincipal(const glm::vec3& p);     // generated torus (axis y, fitted to the unit sphere)
Principal ellipsoidPrincipal(const glm::vec3& p, const glm::vec3& radii);

// The generated surfaces are aligned with the model's up axis, which the direction field also
// starts from where curvature does not decide; tests turn them off that axis first.
glm::mat3 obliqueRotation();
Mesh rotatedMesh(Mesh mesh, const glm::mat3& rotation);
std::function<Principal(const glm::vec3&)> rotatedPrincipal(std::function<Principal(const glm::vec3&)> analytic, const glm::mat3& rotation);

// Angle between two lines, degrees in [0, 90].
double degreesBetweenLines(const glm::vec3& a, const glm::vec3& b);

struct FieldError {
  double medianDegrees = 90.0;  // against the nearer principal direction (a cross field)
  std::size_t vertices = 0;     // compared: where |k1| > 2 |k2|
};
// `directions` per vertex of `mesh`; a zero direction counts as 90 degrees off.
FieldError fieldError(const Mesh& mesh, const std::vector<glm::vec3>& directions,
                      const std::function<Principal(const glm::vec3&)>& analytic);

}  // namespace npr::test
