// libFuzzer harness: the glTF reader (tinygltf's JSON and GLB parsing, then our checks of every
// accessor, buffer view, node, material, camera and light) on arbitrary bytes, JSON and GLB
// alike, read both flattened and as a scene, never crashes, hangs or leaks; what it accepts is
// meshes the renderer can draw (fuzz_mesh.h: faces, or points and lines) and finite object, camera and light transforms.
// External files are looked up beside a folder that does not exist, so none is ever read.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_mesh.h"
#include "renderer/mesh/mesh_formats.h"

namespace {
bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  npr::Result<npr::Mesh> m = npr::parseGltf("/nonexistent-npr-fuzz/fuzz.gltf", bytes);
  npr::fuzz::checkMesh(m);
  npr::Result<npr::LoadedScene> s = npr::parseGltfScene("/nonexistent-npr-fuzz/fuzz.gltf", bytes);
  if (!s) {
    if (s.error().empty()) __builtin_trap();
    return 0;
  }
  if (s->objects.empty()) __builtin_trap();
  for (const npr::SceneObject& o : s->objects) {
    if (!o.mesh || (o.mesh->indices.empty() && !o.mesh->hasMarks()) || o.mesh->normals.size() != o.mesh->positions.size()) __builtin_trap();
    for (std::uint32_t i : o.mesh->indices)
      if (i >= o.mesh->positions.size()) __builtin_trap();
  }
  for (const npr::SceneCamera& c : s->cameras)
    if (!finite(c.world) || !(c.znear >= 0.0f)) __builtin_trap();
  for (const npr::SceneLight& l : s->lights)
    if (!(l.intensity >= 0.0f) || !(l.outerCone > l.innerCone)) __builtin_trap();
  // Animations keep node_animation.h's invariants, and posing them at their ends and middle
  // runs (the viewer drops a pose that overflows; see SceneObjects::pose).
  for (std::size_t i = 0; i < s->nodes.size(); ++i)
    if (s->nodes[i].parent >= static_cast<int>(i)) __builtin_trap();
  for (const npr::SceneObject& o : s->objects)
    if (o.node >= static_cast<int>(s->nodes.size())) __builtin_trap();
  for (const npr::SceneSkin& k : s->skins) {
    if (k.joints.empty() || k.inverseBind.size() != k.joints.size()) __builtin_trap();
    for (int j : k.joints)
      if (j < 0 || j >= static_cast<int>(s->nodes.size())) __builtin_trap();
  }
  for (const npr::SceneObject& o : s->objects) {
    const npr::MeshDeformation& d = o.mesh->deformation;
    const std::size_t nv = o.mesh->positions.size();
    if (o.skin >= static_cast<int>(s->skins.size()) || (o.skin >= 0 && !d.skinned())) __builtin_trap();
    if (d.skinned() && (d.joints.size() != nv || d.weights.size() != nv)) __builtin_trap();
    for (std::size_t t = 0; t < d.targets(); ++t)
      if (d.targetPositions[t].size() != nv || d.targetNormals[t].size() != nv) __builtin_trap();
  }
  std::vector<const npr::SceneAnimation*> all;
  for (const npr::SceneAnimation& a : s->animations) {
    if (a.channels.empty() || !(a.end >= a.start)) __builtin_trap();
    for (const npr::AnimationChannel& c : a.channels) {
      if (c.node < 0 || c.node >= static_cast<int>(s->nodes.size()) || c.times.empty()) __builtin_trap();
      const std::size_t perKey = c.interpolation == npr::Interpolation::CubicSpline ? 3 : 1;
      if (c.width < 1 || c.values.size() != perKey * c.times.size() * static_cast<std::size_t>(c.width)) __builtin_trap();
      for (std::size_t k = 1; k < c.times.size(); ++k)
        if (!(c.times[k] > c.times[k - 1])) __builtin_trap();
    }
    all.push_back(&a);
  }
  npr::NodePose pose;
  for (const npr::SceneAnimation* a : all)
    for (float t : {a->start, 0.5f * (a->start + a->end), a->end}) npr::poseNodes(s->nodes, all, t, pose);
  return 0;
}
