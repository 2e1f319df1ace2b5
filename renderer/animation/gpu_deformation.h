// A deforming mesh posed on the GPU: shaders/deform.comp rewrites the model's position and
// normal buffers (and the hatching field's directions) from its rest pose, once per pose. Every
// pass that draws from those buffers (the GPU-lit paths, the stencil path's masks, shadows,
// hardware outlines, screen-space edges and occlusion) then draws the pose, with no skinning
// variant of its own and no upload: on a GPU the CPU pose and its upload cost more than the
// frame (docs/animation.md). What reads the mesh on the CPU (per-triangle lighting, object-space
// lines, painterly strokes, the anchored pattern) still needs the CPU pose; the renderer decides
// per frame (Renderer::posesOnGpu). Needs compute shaders (OpenGL 4.3); without them every pose
// is made on the CPU.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// Whether the current context can pose meshes on the GPU (compute shaders, storage buffers).
bool gpuDeformationSupported();

class GpuDeformation {
 public:
  // Writes `gpu`'s positions and normals (the upload of `rest`, which deforms) for morph
  // `weights` and skin `joints`, as deformMesh would. The skin and the morph targets are
  // uploaded the first time; a pose uploads only the joints' matrices.
  [[nodiscard]] Status pose(const Mesh& rest, const GpuMesh& gpu, const std::vector<glm::mat4>& joints, const std::vector<float>& weights,
                            gl::ProgramCache& programs, FrameStats& stats);
  // Carries `restDirections` (the field on the rest mesh; uploaded the first time) by the skin
  // of the last pose into `gpu`'s direction stream.
  [[nodiscard]] Status poseDirections(const Mesh& rest, const std::vector<glm::vec3>& restDirections, const GpuMesh& gpu,
                                      gl::ProgramCache& programs, FrameStats& stats);
  // A bound on the radius of `rest` posed by `joints` and `weights` (a vertex's posed position
  // is a convex combination of its joints' images; morph deltas add at most their weighted
  // largest): what the scene's bounds use while the CPU pose is not made.
  float radiusBound(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights);
  // Whether `weights` has more targets with a weight than one dispatch takes (then the CPU poses).
  static bool fits(const std::vector<float>& weights);
  void clear();

 private:
  void upload(const Mesh& rest, FrameStats& stats);
  gl::Buffer skin_, joints_, targets_, restDirections_;
  std::vector<float> targetExtent_;  // per morph target, its largest position delta
  std::size_t jointCapacity_ = 0, jointCount_ = 0;  // the joint buffer's size and the last pose's joints
  bool uploaded_ = false;
};

}  // namespace npr
