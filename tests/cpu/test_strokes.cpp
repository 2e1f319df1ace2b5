// Painterly stroke seeding (strokes/stroke_seeding.h): as many strokes as the density asks
// (capped by the budget), spread as blue noise (and every prefix of the ranks too), on the
// surface, deterministic, and nothing for degenerate meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "renderer/mesh/mesh_generators.h"
#include "renderer/orientation/direction_field.h"
#include "renderer/strokes/stroke_seeding.h"

namespace npr {
namespace {

// The 10th percentile of each point's distance to its nearest neighbour (brute force).
float nearestP10(const std::vector<glm::vec3>& pts) {
  std::vector<float> d;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    float best = INFINITY;
    for (std::size_t j = 0; j < pts.size(); ++j)
      if (i != j) best = std::min(best, glm::length(pts[i] - pts[j]));
    d.push_back(best);
  }
  std::sort(d.begin(), d.end());
  return d[d.size() / 10];
}

std::vector<glm::vec3> positions(const StrokeSeeding& s, float maxRank = 1.0f) {
  std::vector<glm::vec3> p;
  for (const StrokeParticle& q : s.particles)
    if (q.rank < maxRank) p.push_back(q.position);
  return p;
}

TEST(StrokeSeeding, CountFollowsDensityAndBudget) {
  const Mesh sphere = icosphere(4);
  const StrokeSeeding s = seedStrokes(sphere, 200.0f, 1000000, {});
  EXPECT_NEAR(s.area, 4.0 * M_PI, 0.1);  // a unit icosphere, a little under the sphere's
  EXPECT_NEAR(double(s.particles.size()), 200.0 * s.area, 200.0 * s.area * 0.02);
  EXPECT_EQ(seedStrokes(sphere, 200.0f, 500, {}).particles.size(), 500u);
  EXPECT_TRUE(seedStrokes(sphere, 0.0f, 500, {}).particles.empty());
  EXPECT_TRUE(seedStrokes(sphere, 200.0f, 0, {}).particles.empty());
}

TEST(StrokeSeeding, BlueNoiseOnTheSurfaceAndDeterministic) {
  const Mesh sphere = icosphere(4);
  const StrokeSeeding s = seedStrokes(sphere, 150.0f, 1000000, {});
  ASSERT_GT(s.particles.size(), 1500u);
  // White noise of the same count: area-weighted uniform points on the sphere.
  std::mt19937 rng(3);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> white;
  for (std::size_t i = 0; i < s.particles.size(); ++i) white.push_back(glm::normalize(glm::vec3(g(rng), g(rng), g(rng))));
  const float blue = nearestP10(positions(s)), random = nearestP10(white);
  std::printf("nearest-neighbour p10: seeded %.4f, white noise %.4f\n", double(blue), double(random));
  EXPECT_GT(blue, 3.0f * random);
  // The strokes of the lower ranks are spread evenly too (what thinning with distance keeps).
  const std::vector<glm::vec3> quarter = positions(s, 0.25f);
  EXPECT_NEAR(double(quarter.size()), 0.25 * double(s.particles.size()), 2.0);
  EXPECT_GT(nearestP10(quarter), 1.6f * blue);
  for (const StrokeParticle& p : s.particles) {
    EXPECT_NEAR(glm::length(p.position), 1.0f, 0.01f);  // on the surface
    EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-4f);
    EXPECT_GE(p.rank, 0.0f);
    EXPECT_LT(p.rank, 1.0f);
  }
  const StrokeSeeding again = seedStrokes(sphere, 150.0f, 1000000, {});
  ASSERT_EQ(again.particles.size(), s.particles.size());
  for (std::size_t i = 0; i < s.particles.size(); ++i) EXPECT_EQ(again.particles[i].position, s.particles[i].position);
}

TEST(StrokeSeeding, DirectionsLieInTheTangentPlane) {
  const Mesh torus = npr::torus(48, 24);
  const DirectionField field = computeDirectionField(torus);
  const StrokeSeeding s = seedStrokes(torus, 300.0f, 1000000, field.directions);
  int directed = 0;
  for (const StrokeParticle& p : s.particles) {
    const float len = glm::length(p.direction);
    if (len == 0.0f) continue;
    ++directed;
    EXPECT_NEAR(len, 1.0f, 1e-4f);
    EXPECT_LT(std::abs(glm::dot(p.direction, p.normal)), 1e-4f);
  }
  EXPECT_GT(directed, int(s.particles.size()) * 9 / 10);
}

TEST(StrokeSeeding, DegenerateMeshesGetNoStrokesAndNoNaN) {
  Mesh flat;
  flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 0}};
  flat.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  flat.indices = {0, 1, 2, 0, 0, 3};  // collinear and repeated corners: zero area
  EXPECT_TRUE(seedStrokes(flat, 1000.0f, 1000, {}).particles.empty());
  Mesh none;
  EXPECT_TRUE(seedStrokes(none, 1000.0f, 1000, {}).particles.empty());
  // One good triangle among degenerate ones: every stroke on it, finite.
  flat.positions.push_back({0, 1, 0});
  flat.normals.push_back({0, 0, 0});  // a zero normal falls back to the face's
  flat.indices.insert(flat.indices.end(), {0, 1, 4});
  const StrokeSeeding s = seedStrokes(flat, 1000.0f, 1000, {});
  ASSERT_FALSE(s.particles.empty());
  for (const StrokeParticle& p : s.particles) {
    EXPECT_TRUE(std::isfinite(p.position.x) && std::isfinite(p.normal.z));
    EXPECT_NEAR(p.position.z, 0.0f, 1e-6f);
    EXPECT_NEAR(std::abs(p.normal.z), 1.0f, 1e-4f);
  }
}

TEST(StrokeSeeding, StrokesRideTheirTrianglesWhenTheMeshDeforms) {
  const Mesh rest = icosphere(3);
  const StrokeSeeding seeded = seedStrokes(rest, 40.0f, 5000, {});
  ASSERT_EQ(seeded.anchors.size(), seeded.particles.size());
  ASSERT_GT(seeded.particles.size(), 100u);
  // Put back on the same mesh: where seeding put them.
  std::vector<StrokeParticle> again = seeded.particles;
  placeStrokes(rest, {}, seeded.anchors, again);
  for (std::size_t i = 0; i < again.size(); ++i) ASSERT_LT(glm::length(again[i].position - seeded.particles[i].position), 1e-6f);
  // On the mesh stretched along y and moved: each stroke stretched and moved with its
  // triangle, its rank and seed kept.
  Mesh moved = rest;
  for (glm::vec3& p : moved.positions) p = p * glm::vec3(1.0f, 2.0f, 1.0f) + glm::vec3(3.0f, 0.0f, 0.0f);
  placeStrokes(moved, {}, seeded.anchors, again);
  for (std::size_t i = 0; i < again.size(); ++i) {
    const glm::vec3 want = seeded.particles[i].position * glm::vec3(1.0f, 2.0f, 1.0f) + glm::vec3(3.0f, 0.0f, 0.0f);
    ASSERT_LT(glm::length(again[i].position - want), 1e-5f) << i;
    ASSERT_EQ(again[i].rank, seeded.particles[i].rank);
  }
}

}  // namespace
}  // namespace npr
