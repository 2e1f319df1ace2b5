// Principal directions in closed form (see analytic_surfaces.h).
#include "support/analytic_surfaces.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "renderer/orientation/principal_curvature.h"

namespace npr::test {

Principal cylinderPrincipal(const glm::vec3& p) {
  const glm::vec3 around = glm::normalize(glm::vec3(p.z, 0.0f, -p.x));
  return {around, glm::vec3(0, 1, 0), 2.0f, 0.0f};
}

Principal torusPrincipal(const glm::vec3& p) {
  const float R = 1.0f / 1.35f, r = 0.35f / 1.35f;
  const glm::vec3 radial = glm::normalize(glm::vec3(p.x, 0.0f, p.z));
  const glm::vec3 toroidal = glm::vec3(-radial.z, 0.0f, radial.x);
  const glm::vec3 o = p - R * radial;
  const glm::vec3 poloidal = glm::normalize(glm::cross(toroidal, o));
  const float cosv = glm::dot(glm::normalize(o), radial);
  return {poloidal, toroidal, 1.0f / r, std::fabs(cosv / (R + r * cosv))};
}

// x^2/a^2 + y^2/b^2 + z^2/c^2 = 1: the shape operator is the Hessian of the implicit function
// restricted to the tangent plane, over the gradient's length.
Principal ellipsoidPrincipal(const glm::vec3& p, const glm::vec3& radii) {
  const glm::dvec3 r2 = glm::dvec3(radii) * glm::dvec3(radii);
  const glm::dvec3 g = 2.0 * glm::dvec3(p) / r2;
  const glm::dvec3 h = 2.0 / r2;  // diagonal Hessian
  const glm::dvec3 n = glm::normalize(g);
  glm::vec3 t1f, t2f;
  tangentBasis(glm::vec3(n), t1f, t2f);
  const glm::dvec3 t1(t1f), t2(t2f);
  const double L = glm::length(g);
  const double A = glm::dot(t1, h * t1) / L, B = glm::dot(t1, h * t2) / L, C = glm::dot(t2, h * t2) / L;
  const double mean = 0.5 * (A + C), half = std::sqrt(0.25 * (A - C) * (A - C) + B * B);
  const double angle = 0.5 * std::atan2(2.0 * B, A - C);  // both eigenvalues are positive here
  const glm::dvec3 e1 = std::cos(angle) * t1 + std::sin(angle) * t2;
  return {glm::vec3(e1), glm::vec3(glm::cross(n, e1)), float(mean + half), float(mean - half)};
}

glm::mat3 obliqueRotation() {
  const float a = 0.7f, b = 0.5f;  // radians about x, then z
  const glm::mat3 rx(1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a));
  const glm::mat3 rz(std::cos(b), std::sin(b), 0, -std::sin(b), std::cos(b), 0, 0, 0, 1);
  return rz * rx;
}

Mesh rotatedMesh(Mesh m, const glm::mat3& r) {
  for (glm::vec3& p : m.positions) p = r * p;
  finalizeMesh(m);
  return m;
}

std::function<Principal(const glm::vec3&)> rotatedPrincipal(std::function<Principal(const glm::vec3&)> analytic, const glm::mat3& r) {
  return [analytic = std::move(analytic), r](const glm::vec3& p) {
    Principal q = analytic(glm::transpose(r) * p);
    q.e1 = r * q.e1;
    q.e2 = r * q.e2;
    return q;
  };
}

double degreesBetweenLines(const glm::vec3& a, const glm::vec3& b) {
  const double c = std::min(1.0, std::fabs(double(glm::dot(glm::normalize(a), glm::normalize(b)))));
  return std::acos(c) * 180.0 / M_PI;
}

FieldError fieldError(const Mesh& m, const std::vector<glm::vec3>& directions, const std::function<Principal(const glm::vec3&)>& analytic) {
  std::vector<double> errors;
  for (std::size_t i = 0; i < m.positions.size() && i < directions.size(); ++i) {
    const Principal p = analytic(m.positions[i]);
    if (!(p.k1 > 2.0f * p.k2)) continue;
    const glm::vec3 d = directions[i];
    errors.push_back(d == glm::vec3(0.0f) ? 90.0 : std::min(degreesBetweenLines(d, p.e1), degreesBetweenLines(d, p.e2)));
  }
  FieldError out;
  out.vertices = errors.size();
  if (!errors.empty()) {
    std::nth_element(errors.begin(), errors.begin() + long(errors.size() / 2), errors.end());
    out.medianDegrees = errors[errors.size() / 2];
  }
  return out;
}

}  // namespace npr::test
