// CPU tier: the benchmark's ray-cast reference (app/benchmark/ray_reference.h). Its hierarchy
// must find exactly the hits a test of every triangle finds, and its openness must be the
// occlusion bake's quantity: 1 in the open, about half beside a wall, 0 under a lid.
#include <gtest/gtest.h>

#include <random>

#include "app/benchmark/ray_reference.h"
#include "renderer/immediate_api.h"
#include "renderer/shadows/occlusion_bake.h"
#include "support/test_util.h"

namespace npr {
namespace {

// Every triangle, no hierarchy (float corners promoted, as the scene stores them).
bool bruteForceBlocked(const Mesh& m, const glm::dvec3& o, const glm::dvec3& d, double maxT) {
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const glm::dvec3 a(m.positions[m.indices[t * 3]]), b(m.positions[m.indices[t * 3 + 1]]), c(m.positions[m.indices[t * 3 + 2]]);
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-300) continue;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double hit = glm::dot(e2, q) / det;
    if (hit > 1e-9 && hit < maxT) return true;
  }
  return false;
}

TEST(RayReference, HierarchyFindsWhatEveryTriangleFinds) {
  const Mesh m = test::torus(40, 24);
  const RayScene scene(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int hits = 0;
  for (int i = 0; i < 4000; ++i) {
    const glm::dvec3 o(u(rng), u(rng), u(rng));
    const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
    const double maxT = i % 2 ? INFINITY : std::fabs(u(rng)) + 0.1;
    const bool expected = bruteForceBlocked(m, o, d, maxT);
    hits += expected;
    ASSERT_EQ(scene.blocked(o, d, maxT), expected) << "ray " << i;
  }
  EXPECT_GT(hits, 400);   // the rays test both outcomes
  EXPECT_LT(hits, 3600);
}

TEST(RayReference, OpennessIsTheBakesQuantity) {
  const std::vector<glm::vec3> dirs = OcclusionBake::sampleDirections(OcclusionBake::kDefaultDirections);
  // A lid (two triangles, 4 x 4) above the origin, facing down.
  std::vector<Triangle> lid(2);
  lid[0].v = {glm::vec3(-2, 0.2f, -2), glm::vec3(2, 0.2f, 2), glm::vec3(-2, 0.2f, 2)};
  lid[1].v = {glm::vec3(-2, 0.2f, -2), glm::vec3(2, 0.2f, -2), glm::vec3(2, 0.2f, 2)};
  const Mesh m = meshFromTriangles(lid);
  const RayScene scene(m);
  EXPECT_DOUBLE_EQ(scene.openness({0, 1, 0}, {0, 1, 0}, dirs), 1.0);   // above it: open
  EXPECT_LT(scene.openness({0, 0, 0}, {0, 1, 0}, dirs), 0.1);          // under it, facing it
  const double side = scene.openness({0, 0, 0}, {1, 0, 0}, dirs);       // under it, facing sideways
  EXPECT_GT(side, 0.3);
  EXPECT_LT(side, 0.7);
  // Nothing blocks a ray that stops before the lid.
  EXPECT_FALSE(scene.blocked({0, 0, 0}, {0, 1, 0}, 0.1));
  EXPECT_TRUE(scene.blocked({0, 0, 0}, {0, 1, 0}, 0.3));
}

}  // namespace
}  // namespace npr
