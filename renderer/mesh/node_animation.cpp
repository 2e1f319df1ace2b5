// Node animation: sampling and posing (see node_animation.h).
#include "renderer/mesh/node_animation.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace npr {
namespace {

glm::quat toQuat(const float* v) { return glm::quat(v[3], v[0], v[1], v[2]); }

void normaliseRotation(float* v) {
  const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
  if (len > 1e-12f) {
    for (int i = 0; i < 4; ++i) v[i] /= len;
  } else {
    v[0] = v[1] = v[2] = 0.0f;
    v[3] = 1.0f;
  }
}

}  // namespace

glm::mat4 SceneNode::local() const {
  if (matrix) return *matrix;
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

void sampleChannel(const AnimationChannel& c, float time, float* out) {
  const std::size_t w = static_cast<std::size_t>(c.width);
  const bool cubic = c.interpolation == Interpolation::CubicSpline;
  const bool rotation = c.property == AnimatedProperty::Rotation;
  // Key k's value (the middle of a cubic spline's three), its in- and out-tangents.
  const auto value = [&](std::size_t k) { return &c.values[(cubic ? 3 * k + 1 : k) * w]; };
  const auto copy = [&](const float* v) {
    std::copy(v, v + w, out);
    if (rotation) normaliseRotation(out);
  };
  const std::size_t n = c.times.size();
  if (n == 0 || c.values.size() < n * w * (cubic ? 3 : 1)) {
    std::fill(out, out + w, 0.0f);
    return;
  }
  if (!(time > c.times.front())) return copy(value(0));
  if (time >= c.times.back()) return copy(value(n - 1));
  // times[k] <= time < times[k + 1]
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(c.times.begin(), c.times.end(), time) - c.times.begin()) - 1;
  const float dt = c.times[k + 1] - c.times[k];
  const float s = std::clamp((time - c.times[k]) / dt, 0.0f, 1.0f);
  switch (c.interpolation) {
    case Interpolation::Step: return copy(value(k));
    case Interpolation::Linear:
      if (rotation) {
        const glm::quat q = glm::normalize(glm::slerp(glm::normalize(toQuat(value(k))), glm::normalize(toQuat(value(k + 1))), s));
        out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
        return;
      }
      for (std::size_t i = 0; i < w; ++i) out[i] = value(k)[i] + s * (value(k + 1)[i] - value(k)[i]);
      return;
    case Interpolation::CubicSpline: {
      // glTF's Hermite form: p0 = v_k, m0 = dt * out-tangent_k, p1 = v_k+1, m1 = dt * in-tangent_k+1.
      const float* p0 = value(k);
      const float* m0 = &c.values[(3 * k + 2) * w];
      const float* p1 = value(k + 1);
      const float* m1 = &c.values[3 * (k + 1) * w];
      const float s2 = s * s, s3 = s2 * s;
      const float h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
      for (std::size_t i = 0; i < w; ++i) out[i] = h00 * p0[i] + h10 * dt * m0[i] + h01 * p1[i] + h11 * dt * m1[i];
      if (rotation) normaliseRotation(out);
      return;
    }
  }
}

glm::vec4 sampleChannel(const AnimationChannel& c, float time) {
  float v[4] = {0, 0, 0, 0};
  if (c.width > 4) return glm::vec4(0.0f);
  sampleChannel(c, time, v);
  return glm::vec4(v[0], v[1], v[2], v[3]);
}

void poseNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations, float time, NodePose& pose) {
  // The animated properties over the rest ones; later animations win where two drive one.
  std::vector<SceneNode> posed = nodes;
  float v[4];
  for (const SceneAnimation* a : animations)
    for (const AnimationChannel& c : a->channels) {
      if (c.node < 0 || c.node >= static_cast<int>(posed.size())) continue;
      SceneNode& n = posed[static_cast<std::size_t>(c.node)];
      if (c.property == AnimatedProperty::Weights) {
        if (static_cast<std::size_t>(c.width) == n.weights.size()) sampleChannel(c, time, n.weights.data());
        continue;
      }
      sampleChannel(c, time, v);
      switch (c.property) {
        case AnimatedProperty::Translation: n.translation = glm::vec3(v[0], v[1], v[2]); break;
        case AnimatedProperty::Rotation: n.rotation = toQuat(v); break;
        case AnimatedProperty::Scale: n.scale = glm::vec3(v[0], v[1], v[2]); break;
        case AnimatedProperty::Weights: break;
      }
    }
  pose.world.resize(nodes.size());
  pose.weights.resize(nodes.size());
  for (std::size_t i = 0; i < posed.size(); ++i) {
    const glm::mat4 local = posed[i].local();
    const int p = posed[i].parent;
    pose.world[i] = p >= 0 && p < static_cast<int>(i) ? pose.world[static_cast<std::size_t>(p)] * local : local;
    pose.weights[i] = std::move(posed[i].weights);
  }
}

std::vector<char> animatedNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations) {
  std::vector<char> moved(nodes.size(), 0);
  for (const SceneAnimation* a : animations)
    for (const AnimationChannel& c : a->channels)
      if (c.node >= 0 && c.node < static_cast<int>(nodes.size())) moved[static_cast<std::size_t>(c.node)] = 1;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const int p = nodes[i].parent;
    if (p >= 0 && p < static_cast<int>(i) && moved[static_cast<std::size_t>(p)]) moved[i] = 1;
  }
  return moved;
}

}  // namespace npr
