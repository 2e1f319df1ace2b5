// A scene file's node hierarchy and its keyframed animations (glTF 2.0's translation, rotation,
// scale and morph weight channels), CPU-side and without GL: sampling a channel at a time
// (step, linear with spherical interpolation for rotations, cubic Hermite spline) and posing
// every node's world transform and morph weights at a scene time. The reader checks the data (node_animation's
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
  std::vector<float> weights;       // its mesh's morph target weights at rest (empty: none)
  glm::mat4 local() const;
};

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimatedProperty { Translation, Rotation, Scale, Weights };

// A channel with its sampler. Invariants (the reader refuses data that breaks them): `times`
// finite and strictly increasing, at least one; `values` finite, `width` floats per value and
// one value per time (three for a cubic spline: in-tangent, value, out-tangent). Rotations are
// (x, y, z, w), width 4; translations and scales width 3; weights one per morph target of the
// node's mesh.
struct AnimationChannel {
  int node = 0;  // into the scene's nodes
  AnimatedProperty property = AnimatedProperty::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;
  std::vector<float> values;
  int width = 3;
};

struct SceneAnimation {
  std::string name;
  std::vector<AnimationChannel> channels;
  float start = 0.0f, end = 0.0f;  // the first and last keyframe over the channels
};

// The channel's value at `time` into `out` (`width` floats): the first key's before the first,
// the last's after the last.
void sampleChannel(const AnimationChannel& channel, float time, float* out);
// The same for channels of width 4 or less (the rest zero).
glm::vec4 sampleChannel(const AnimationChannel& channel, float time);

// The scene's nodes at one time: world transforms and morph weights.
struct NodePose {
  std::vector<glm::mat4> world;
  std::vector<std::vector<float>> weights;  // per node (its rest weights where no channel drives them)
};
// Every node posed at `time` with `animations` applied (each node at rest where no channel
// drives it).
void poseNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations, float time, NodePose& pose);

// Per node: whether an animation of `animations` moves it (a channel targets it or a parent).
std::vector<char> animatedNodes(const std::vector<SceneNode>& nodes, const std::vector<const SceneAnimation*>& animations);

}  // namespace npr
