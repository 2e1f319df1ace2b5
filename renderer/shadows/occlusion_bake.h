// Ambient occlusion per vertex, baked once per mesh on the GPU (`--occlusion`): the mesh's
// depth seen from many directions over the sphere (orthographic maps, as a directional light's
// shadow map), and for each vertex the cosine-weighted share of those directions in which it
// sees the sky. Directions come in an order whose every prefix covers the sphere evenly, so
// the bake can run a few directions per frame (the viewer stays interactive and shows
// progress) and any prefix is already an estimate. The result scales the ambient and diffuse
// terms (lighting.glsl, with a strength setting).
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/mesh/mesh.h"

namespace npr {

class OcclusionBake {
 public:
  static constexpr int kDefaultDirections = 64;
  static constexpr int kDepthSize = 1024;

  // The directions a bake of `count` takes, in its order (unit, model space, toward the sky):
  // the benchmark's ray-cast reference casts the same ones.
  static std::vector<glm::vec3> sampleDirections(int count);

  // Prepares a bake of `mesh` (uploaded as `gpuMesh`, which must outlive the bake).
  [[nodiscard]] static Result<std::unique_ptr<OcclusionBake>> start(const Mesh& mesh, const GpuMesh& gpuMesh, int directions = kDefaultDirections);

  // Bakes directions until `budgetMs` has passed (0: all that are left); reads the result back
  // when the last is done.
  [[nodiscard]] Status step(double budgetMs, gl::ProgramCache& programs, FrameStats& stats);
  bool done() const { return next_ >= count_; }
  int directionsDone() const { return next_; }
  int directions() const { return count_; }
  double ms() const { return ms_; }  // time spent so far
  // Per vertex in [0, 1] (1: open to the whole hemisphere); empty until done.
  const std::vector<float>& values() const { return values_; }

 private:
  OcclusionBake() = default;
  const GpuMesh* gpuMesh_ = nullptr;
  std::size_t vertexCount_ = 0;
  float radius_ = 1.0f;
  glm::ivec2 targetSize_{1};
  std::vector<glm::vec3> dirs_;
  int count_ = 0, next_ = 0;
  double ms_ = 0.0;
  gl::Texture depth_, accumulation_;
  gl::Framebuffer depthFbo_, accumulationFbo_;
  std::vector<float> values_;
};

}  // namespace npr
