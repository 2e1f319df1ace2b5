// Node animation: sampling and posing (see node_animation.h).
#include "renderer/animation/node_animation.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace npr {
namespace {

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }
glm::vec4 fromQuat(const glm::quat& q) { return glm::vec4(q.x, q.y, q.z, q.w); }

glm::vec4 normalisedRotation(const glm::vec4& v) {
  const float len = glm::length(v);
  return len > 1e-12f ? v / len : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
}

}  // namespace

glm::mat4 SceneNode::local() const {
  if (matrix) return *matrix;
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

glm::vec4 sampleChannel(const AnimationChannel& c, float time) {
  const bool cubic = c.interpolation == Interpolation::CubicSpline;
  const bool rotation = c.property == AnimatedProperty::Rotation;
  // The value of key k (the middle of a cubic spline's three).
  const auto value = [&](std::size_t k) { return c.values[cubic ? 3 * k + 1 : k]; };
  const std::size_t n = c.times.size();
  if (n == 0) return glm::vec4(0.0f);
  if (!(time > c.times.front())) return rotation ? normalisedRotation(value(0)) : value(0);
  if (time >= c.times.back()) return rotation ? normalisedRotation(value(n - 1)) : value(n - 1);
  // times[k] <= time < times[k + 1]
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(c.times.begin(), c.times.end(), time) - c.times.begin()) - 1;
  const float t0 = c.times[k], t1 = c.times[k + 1];
  const float dt = t1 - t0;
  const float s = std::clamp((time - t0) / dt, 0.0f, 1.0f);
  switch (c.interpolation) {
    case Interpolation::Step: return rotation ? normalisedRotation(value(k)) : value(k);
    case Interpolation::Linear:
      if (rotation) return fromQuat(glm::normalize(glm::slerp(glm::normalize(toQuat(value(k))), glm::normalize(toQuat(value(k + 1))), s)));
      return glm::mix(value(k), value(k + 1), s);
    case Interpolation::CubicSpline: {
      // glTF's Hermite form: p0 = v_k, m0 = dt * out-tangent_k, p1 = v_k+1, m1 = dt * in-tangent_k+1.
      const glm::vec4 p0 = c.values[3 * k + 1], m0 = dt * c.values[3 * k + 2];
      const glm::vec4 p1 = c.values[3 * (k + 1) + 1], m1 = dt * c.values[3 * (k + 1)];
      const float s2 = s * s, s3 = s2 * s;
      const glm::vec4 p = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
      return rotation ? normalisedRotation(p) : p;
    }
  }
  return value(k);
}

void poseNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations, float time,
               std::vector<glm::mat4>& world) {
  // The animated properties over the rest ones; later animations win where two drive one.
  std::vector<SceneNode> posed = nodes;
  for (const SceneAnimation* a : animations)
    for (const AnimationChannel& c : a->channels) {
      if (c.node < 0 || c.node >= static_cast<int>(posed.size())) continue;
      SceneNode& n = posed[static_cast<std::size_t>(c.node)];
      const glm::vec4 v = sampleChannel(c, time);
      switch (c.property) {
        case AnimatedProperty::Translation: n.translation = glm::vec3(v); break;
        case AnimatedProperty::Rotation: n.rotation = toQuat(v); break;
        case AnimatedProperty::Scale: n.scale = glm::vec3(v); break;
      }
    }
  world.resize(nodes.size());
  for (std::size_t i = 0; i < posed.size(); ++i) {
    const glm::mat4 local = posed[i].local();
    const int p = posed[i].parent;
    world[i] = p >= 0 && p < static_cast<int>(i) ? world[static_cast<std::size_t>(p)] * local : local;
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
