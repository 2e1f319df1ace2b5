// A small screen-facing disc at a world position: the light marker the viewer draws over
// the frame while the light is being moved.
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"

namespace npr {

[[nodiscard]] Status drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour,
                                float pixels, const glm::ivec4& viewport, gl::ProgramCache& programs,
                                const gl::VertexArray& emptyVao, FrameStats& stats);

}  // namespace npr
