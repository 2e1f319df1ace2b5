// A scene file's node hierarchy and its keyframed node animations (glTF 2.0's translation,
// rotation and scale channels), CPU-side and without GL: sampling a channel at a time (step,
// linear with spherical interpolation for rotations, cubic Hermite spline) and posing every
// node's world transform at a scene time. The reader checks the data (node_animation's
// invariants below) before anything here sees it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace npr {

// One node of the file's default scene. Parents come before their children in the list, so a
// pose is one pass in order.
struct SceneNode {
  std::string name;
  int parent = -1;
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  std::optional<glm::mat4> matrix;  // a node given by a matrix, which glTF forbids animating
  glm::mat4 local() const;
};

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimatedProperty { Translation, Rotation, Scale };

// A channel with its sampler. Invariants (the reader refuses data that breaks them): `times`
// finite and strictly increasing, at least one; `values` finite, one per time (three for a
// cubic spline: in-tangent, value, out-tangent); rotations as (x, y, z, w), the others in xyz.
struct AnimationChannel {
  int node = 0;  // into the scene's nodes
  AnimatedProperty property = AnimatedProperty::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;
  std::vector<glm::vec4> values;
};

struct SceneAnimation {
  std::string name;
  std::vector<AnimationChannel> channels;
  float start = 0.0f, end = 0.0f;  // the first and last keyframe over the channels
};

// The channel's value at `time`: the first key's before the first, the last's after the last.
glm::vec4 sampleChannel(const AnimationChannel& channel, float time);

// Every node's world transform at `time` with `animations` applied (each node's rest
// transform where no channel drives it). `world` is resized to the nodes.
void poseNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations, float time,
               std::vector<glm::mat4>& world);

// Per node: whether an animation of `animations` moves it (a channel targets it or a parent).
std::vector<char> animatedNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations);

}  // namespace npr
