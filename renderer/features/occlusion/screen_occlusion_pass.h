// Screen-space ambient occlusion (`--occlusion-method screen`): per frame, from what the frame
// shows, instead of baked per vertex once per mesh. The mesh (and the ground plane, so the
// model darkens the ground where it stands) is drawn once more into eye-space normals and
// depth, a full-screen pass estimates each pixel's openness from KERNEL points in the
// hemisphere over it (screen_occlusion.frag), a second one blurs the estimate's 4x4 pattern
// away; the per-pixel shadings then scale ambient and diffuse by it, as they do by the baked
// value. Local by nature: it sees only what is on screen, within `radius` of the point.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gl/texture_target.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/mesh/placed_mesh.h"

namespace npr {

class ScreenOcclusionPass {
 public:
  // Draws this frame's occlusion for `meshes` seen through `camera` in `viewport`, with
  // hemisphere radius `radius` (eye units); leaves the bound framebuffer and viewport as they were.
  [[nodiscard]] Status draw(const std::vector<PlacedMesh>& meshes, const CameraMatrices& camera, float radius, const glm::ivec4& viewport,
                            gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats);
  // Binds the result for a mesh program compiled with SCREEN_OCCLUSION.
  void bind(gl::ShaderProgram& program, const glm::ivec4& viewport) const;
  // The (blurred) result, one channel, 1 open, of the viewport's size.
  GLuint texture() const { return blurred_.colour(); }

 private:
  gl::TextureTarget geometry_;  // eye-space normals and depth
  gl::TextureTarget raw_, blurred_;
  std::vector<glm::vec3> kernel_;
};

}  // namespace npr
