// CPU tier: node animation (renderer/animation/node_animation.h): channels sampled at and
// between their keyframes against values worked out by hand (step, linear, slerp, cubic
// spline), and poses carried from parents to children; and deformation (deformation.h):
// a skinned cylinder bent against a linear blend skinning reference, morph targets between
// known shapes.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/animation/deformation.h"
#include "renderer/mesh/node_animation.h"
#include "renderer/mesh/mesh_generators.h"
#include "support/skinned_cylinder.h"

namespace npr {
namespace {

// A channel of width 3 (4 for rotations) from values given as vec4s.
AnimationChannel channel(AnimatedProperty p, Interpolation i, std::vector<float> times, const std::vector<glm::vec4>& values) {
  AnimationChannel c;
  c.property = p;
  c.interpolation = i;
  c.times = std::move(times);
  c.width = p == AnimatedProperty::Rotation ? 4 : 3;
  for (const glm::vec4& v : values)
    for (int k = 0; k < c.width; ++k) c.values.push_back(v[k]);
  return c;
}

void expectNear(const glm::vec4& got, const glm::vec4& want, float tolerance = 1e-5f) {
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], want[k], tolerance) << "component " << k;
}

TEST(NodeAnimation, StepHoldsEachKeyUntilTheNext) {
  const AnimationChannel c = channel(AnimatedProperty::Translation, Interpolation::Step, {1.0f, 2.0f, 4.0f},
                                     {{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}});
  expectNear(sampleChannel(c, 0.0f), {1, 0, 0, 0});  // before the first key: the first
  expectNear(sampleChannel(c, 1.0f), {1, 0, 0, 0});
  expectNear(sampleChannel(c, 1.99f), {1, 0, 0, 0});
  expectNear(sampleChannel(c, 2.0f), {2, 0, 0, 0});
  expectNear(sampleChannel(c, 3.5f), {2, 0, 0, 0});
  expectNear(sampleChannel(c, 9.0f), {3, 0, 0, 0});  // after the last: the last
}

TEST(NodeAnimation, LinearInterpolatesBetweenKeys) {
  const AnimationChannel c = channel(AnimatedProperty::Scale, Interpolation::Linear, {0.0f, 2.0f, 3.0f},
                                     {{1, 1, 1, 0}, {3, 5, 1, 0}, {3, 5, 0, 0}});
  expectNear(sampleChannel(c, 0.5f), {1.5f, 2.0f, 1.0f, 0.0f});
  expectNear(sampleChannel(c, 2.0f), {3, 5, 1, 0});
  expectNear(sampleChannel(c, 2.25f), {3.0f, 5.0f, 0.75f, 0.0f});
}

TEST(NodeAnimation, LinearRotationIsASlerpAtConstantAngularSpeed) {
  // From the identity to 90 degrees about z: a quarter of the way is 22.5 degrees, where a
  // normalised lerp of the quaternions would give 19.5.
  const float h = std::sqrt(0.5f);
  const AnimationChannel c = channel(AnimatedProperty::Rotation, Interpolation::Linear, {0.0f, 1.0f}, {{0, 0, 0, 1}, {0, 0, h, h}});
  const float half = glm::radians(22.5f) / 2.0f;
  expectNear(sampleChannel(c, 0.25f), {0.0f, 0.0f, std::sin(half), std::cos(half)});
  // The shorter way round when the keys' quaternions lie in opposite hemispheres.
  const AnimationChannel flipped = channel(AnimatedProperty::Rotation, Interpolation::Linear, {0.0f, 1.0f}, {{0, 0, 0, 1}, {0, 0, -h, -h}});
  const glm::vec4 q = sampleChannel(flipped, 0.5f);
  const float angle = 2.0f * std::acos(std::min(1.0f, std::abs(q.w)));
  EXPECT_NEAR(glm::degrees(angle), 45.0f, 1e-3f);
}

TEST(NodeAnimation, CubicSplineIsGltfsHermiteForm) {
  // Keys at t = 1 and 3 (dt 2): values 0 and 10, out-tangent of the first 4, in-tangent of the
  // second -2. At s = 0.5: h00 = 0.5, h10 = 0.125, h01 = 0.5, h11 = -0.125, so
  // p = 0.5*0 + 0.125*(2*4) + 0.5*10 - 0.125*(2*-2) = 1 + 5 + 0.5 = 6.5.
  const AnimationChannel c = channel(AnimatedProperty::Translation, Interpolation::CubicSpline, {1.0f, 3.0f},
                                     {{9, 0, 0, 0}, {0, 0, 0, 0}, {4, 0, 0, 0}, {-2, 0, 0, 0}, {10, 0, 0, 0}, {7, 0, 0, 0}});
  EXPECT_NEAR(sampleChannel(c, 2.0f).x, 6.5f, 1e-5f);
  // At the keys, the keys' values (the tangents 9 and 7 play no part outside).
  EXPECT_NEAR(sampleChannel(c, 1.0f).x, 0.0f, 1e-6f);
  EXPECT_NEAR(sampleChannel(c, 3.0f).x, 10.0f, 1e-6f);
  EXPECT_NEAR(sampleChannel(c, 0.0f).x, 0.0f, 1e-6f);
  // s = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875:
  // 0 + 0.140625*8 + 1.5625 - 0.046875*(-4) = 1.125 + 1.5625 + 0.1875 = 2.875.
  EXPECT_NEAR(sampleChannel(c, 1.5f).x, 2.875f, 1e-5f);
}

TEST(NodeAnimation, APoseCarriesParentsToChildrenAndLeavesUndrivenNodesAtRest) {
  std::vector<SceneNode> nodes(3);
  nodes[0].translation = {5, 0, 0};
  nodes[1].parent = 0;
  nodes[1].translation = {0, 1, 0};
  nodes[2].translation = {0, 0, 7};  // a second root, not animated
  SceneAnimation a;
  AnimationChannel c = channel(AnimatedProperty::Translation, Interpolation::Linear, {0.0f, 1.0f}, {{0, 0, 0, 0}, {10, 0, 0, 0}});
  c.node = 0;
  a.channels.push_back(c);
  NodePose pose;
  poseNodes(nodes, {&a}, 0.5f, pose);
  ASSERT_EQ(pose.world.size(), 3u);
  EXPECT_NEAR(pose.world[0][3].x, 5.0f, 1e-6f);
  EXPECT_NEAR(pose.world[1][3].x, 5.0f, 1e-6f);
  EXPECT_NEAR(pose.world[1][3].y, 1.0f, 1e-6f);
  EXPECT_NEAR(pose.world[2][3].z, 7.0f, 1e-6f);
  poseNodes(nodes, {}, 0.5f, pose);  // nothing plays: the rest pose
  EXPECT_NEAR(pose.world[1][3].x, 5.0f, 1e-6f);
  poseNodes(nodes, {}, 0.0f, pose);
  EXPECT_NEAR(pose.world[0][3].x, 5.0f, 1e-6f);
  const std::vector<char> moved = animatedNodes(nodes, {&a});
  EXPECT_EQ(moved, (std::vector<char>{1, 1, 0}));
}

TEST(NodeAnimation, MorphWeightsAreSampledWholeAndRestWhereUndriven) {
  std::vector<SceneNode> nodes(2);
  nodes[0].weights = {0.0f, 0.0f, 0.25f};
  nodes[1].weights = {0.5f};
  SceneAnimation a;
  AnimationChannel c;
  c.node = 0;
  c.property = AnimatedProperty::Weights;
  c.width = 3;
  c.times = {0.0f, 1.0f};
  c.values = {0, 0, 0, 1, 0.5f, 0};
  a.channels.push_back(c);
  NodePose pose;
  poseNodes(nodes, {&a}, 0.5f, pose);
  EXPECT_EQ(pose.weights[0], (std::vector<float>{0.5f, 0.25f, 0.0f}));
  EXPECT_EQ(pose.weights[1], std::vector<float>{0.5f});
  float w[3];
  sampleChannel(c, 2.0f, w);
  EXPECT_EQ(w[0], 1.0f);
  EXPECT_EQ(w[1], 0.5f);
}

TEST(Deformation, ASkinnedCylinderBendsAsLinearBlendSkinningSays) {
  const Mesh rest = test::skinnedCylinder(32, 30);
  Mesh posed = rest;
  for (float degrees : {0.0f, 45.0f, 90.0f}) {
    deformMesh(rest, test::bendJoints(degrees), {}, posed);
    double worst = 0.0;
    for (std::size_t i = 0; i < rest.positions.size(); ++i)
      worst = std::max(worst, glm::length(glm::dvec3(posed.positions[i]) - test::referenceBend(rest, i, degrees)));
    EXPECT_LT(worst, 1e-5) << degrees << " degrees";
  }
  // Bent 90 degrees, the head's rim point (0.5, 0.75, 0) is at (-0.75, 0.5, 0) and its normal
  // (nx, ny, nz) turned to (-ny, nx, nz); the foot has not moved.
  for (std::size_t i = 0; i < rest.positions.size(); ++i) {
    if (glm::length(rest.positions[i] - glm::vec3(0.5f, 0.75f, 0.0f)) < 1e-6f) {
      EXPECT_LT(glm::length(posed.positions[i] - glm::vec3(-0.75f, 0.5f, 0.0f)), 1e-5f);
      const glm::vec3 n = rest.normals[i];
      EXPECT_LT(glm::length(posed.normals[i] - glm::vec3(-n.y, n.x, n.z)), 1e-5f);
    }
    if (rest.positions[i].y < -0.7f) {
      EXPECT_EQ(posed.positions[i], rest.positions[i]);
    }
  }
  // Faces follow their vertices; the radius still bounds the surface.
  for (std::size_t f = 0; f < rest.triangleCount(); ++f) {
    const std::uint32_t* id = &rest.indices[3 * f];
    const glm::vec3 c = (posed.positions[id[0]] + posed.positions[id[1]] + posed.positions[id[2]]) / 3.0f;
    ASSERT_LT(glm::length(posed.faceCentroids[f] - c), 1e-5f);
  }
  for (const glm::vec3& p : posed.positions) EXPECT_LE(glm::length(p), posed.radius + 1e-5f);
  // Tangents (the hatching direction field) are carried by the same skin: along y at rest,
  // along -x on the head bent 90 degrees, unchanged at the foot.
  const std::vector<glm::vec3> along(rest.positions.size(), glm::vec3(0.0f, 1.0f, 0.0f));
  std::vector<glm::vec3> carried;
  deformMesh(rest, test::bendJoints(90.0f), {}, posed, &along, &carried);
  ASSERT_EQ(carried.size(), rest.positions.size());
  for (std::size_t i = 0; i < rest.positions.size(); ++i) {
    if (rest.positions[i].y > 0.5f) {
      EXPECT_LT(glm::length(carried[i] - glm::vec3(-1.0f, 0.0f, 0.0f)), 1e-5f);
    } else if (rest.positions[i].y < -0.5f) {
      EXPECT_EQ(carried[i], along[i]);
    }
  }
}

TEST(Deformation, MorphTargetsBlendBetweenKnownShapes) {
  // A sphere and, as its one target, the sphere squashed to half its height.
  Mesh rest = icosphere(2);
  rest.deformation.targetPositions.assign(1, std::vector<glm::vec3>(rest.positions.size()));
  rest.deformation.targetNormals.assign(1, std::vector<glm::vec3>(rest.positions.size(), glm::vec3(0.0f)));
  for (std::size_t i = 0; i < rest.positions.size(); ++i) rest.deformation.targetPositions[0][i] = glm::vec3(0.0f, -0.5f * rest.positions[i].y, 0.0f);
  Mesh posed = rest;
  for (float w : {0.0f, 0.5f, 1.0f}) {
    deformMesh(rest, {}, {w}, posed);
    for (std::size_t i = 0; i < rest.positions.size(); ++i) {
      const glm::vec3 want = rest.positions[i] * glm::vec3(1.0f, 1.0f - 0.5f * w, 1.0f);
      ASSERT_LT(glm::length(posed.positions[i] - want), 1e-6f) << "weight " << w << " vertex " << i;
    }
  }
  // Weights the mesh has no target for change nothing.
  deformMesh(rest, {}, {0.0f, 7.0f}, posed);
  EXPECT_EQ(posed.positions, rest.positions);
}

TEST(Deformation, AVertexWithNoWeightStaysAtRest) {
  Mesh rest = test::skinnedCylinder(8, 4);
  rest.deformation.weights[0] = glm::vec4(0.0f);
  Mesh posed = rest;
  deformMesh(rest, test::bendJoints(90.0f), {}, posed);
  EXPECT_EQ(posed.positions[0], rest.positions[0]);
}

// The tone sampler's triangles posed alone (while the GPU holds the whole pose) are posed
// exactly as the whole mesh's pose has them, and no other triangle is touched.
TEST(Deformation, PosingEveryStrideThTriangleMatchesTheWholePose) {
  Mesh rest = test::skinnedCylinder(24, 16);
  rest.deformation.targetPositions.assign(1, std::vector<glm::vec3>(rest.positions.size(), glm::vec3(0.0f, 0.1f, 0.0f)));
  rest.deformation.targetNormals.assign(1, std::vector<glm::vec3>(rest.positions.size(), glm::vec3(0.0f)));
  Mesh whole = rest, some = rest;
  deformMesh(rest, test::bendJoints(75.0f), {0.5f}, whole);
  const std::size_t stride = 7, first = stride / 2;
  deformFaces(rest, test::bendJoints(75.0f), {0.5f}, some, first, stride);
  for (std::size_t f = 0; f < rest.triangleCount(); ++f) {
    const bool sampled = f >= first && (f - first) % stride == 0;
    const Mesh& want = sampled ? whole : rest;
    EXPECT_EQ(some.faceCentroids[f], want.faceCentroids[f]) << "triangle " << f;
    EXPECT_EQ(some.faceNormals[f], want.faceNormals[f]) << "triangle " << f;
    if (!sampled) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = rest.indices[3 * f + std::size_t(k)];
      EXPECT_EQ(some.positions[v], whole.positions[v]);
      EXPECT_EQ(some.normals[v], whole.normals[v]);
    }
  }
}

}  // namespace
}  // namespace npr
