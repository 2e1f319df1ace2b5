// Image-space edges: the frame's eye-space normals and depth drawn into textures of the
// viewport's size, then Sobel on both, thresholded, blended over the frame as ink. Finds
// silhouettes and creases of any geometry with no adjacency, at one extra mesh draw.
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/texture_target.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/mesh/placed_mesh.h"
#include "renderer/settings/render_settings.h"

namespace npr {

class ImageEdgesPass {
 public:
  [[nodiscard]] Status draw(const std::vector<PlacedMesh>& meshes, const CameraMatrices& camera, const LineSettings& lines,
                            const glm::ivec4& viewport, gl::ProgramCache& programs, const gl::VertexArray& emptyVao,
                            FrameStats& stats);

 private:
  gl::TextureTarget target_;  // eye-space normals and depth
};

}  // namespace npr
