// The per-triangle paths' lighting on the GPU (the original report's proposed experiment):
// every triangle lit at its centroid with its face normal by shaders/triangle_light.*, shadows
// and occlusion included, matched there, and the entries read back for bucketing on the CPU.
// What the per-triangle paths use when shadows are on (the CPU lighting has no shadow maps);
// bench_frames --gpu-triangles measures it against the CPU's.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/shadows/shadow_maps.h"

namespace npr {

struct GpuTriangleLightingInputs {
  const LightingState& lighting;
  const CameraMatrices& camera;
  const GpuPalette& palette;
  MatchMode match;
  const ShadowMaps* shadows = nullptr;           // null: unshadowed
  glm::mat4 sceneView{1.0f};                     // the shadow maps' eye-to-scene transform
  const std::vector<float>* occlusion = nullptr;  // per vertex; null: none
  float occlusionStrength = 1.0f;
};

class GpuTriangleLighting {
 public:
  // `vertices`: the mesh `mesh`'s indices point into when it holds only triangles (a part of a
  // model, mesh_subset.h); null: `mesh` itself.
  void setMesh(const Mesh* mesh, const Mesh* vertices = nullptr);
  // The mesh's faces moved (a posed mesh): their centroids and normals are sent again.
  void geometryChanged();
  // One entry per triangle of the mesh into `entries`.
  [[nodiscard]] Status shade(const GpuTriangleLightingInputs& in, gl::ProgramCache& programs, FrameStats& stats,
                             std::vector<std::uint8_t>& entries);

 private:
  const Mesh* mesh_ = nullptr;
  const Mesh* vertices_ = nullptr;
  gl::VertexArray vao_;
  gl::Buffer centroids_, normals_, occlusion_;
  const float* occlusionFrom_ = nullptr;
  gl::Texture target_;
  gl::Framebuffer fbo_;
  glm::ivec2 size_{0};
};

}  // namespace npr
