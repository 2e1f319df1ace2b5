// The mesh's interpolated eye-space geometry instead of an image: position (alpha -1 on back
// faces) or normal, into a float target. What the benchmark's accuracy reference and the
// tests light on the CPU, and what the image-space edges run Sobel on.
#pragma once

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/program_cache.h"
#include "renderer/mesh/placed_mesh.h"

namespace npr {

enum class GeometryOutput { EyePosition, EyeNormal };

// A see-through mesh leaves out what its materials' alpha does in every other pass.
[[nodiscard]] Status drawGeometry(const PlacedMesh& mesh, GeometryOutput output, gl::ProgramCache& programs, FrameStats& stats);

}  // namespace npr
