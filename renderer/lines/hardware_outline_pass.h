// Hardware outlines (`--lines hardware`) and the charcoal rim (`--lines rim`): silhouettes
// made by the rasterizer from polygons instead of found as edges (lines/feature_edges.h).
// Drawn after the path's front faces, from the same vertex buffers, through one geometry
// stage (shaders/outline.geom) that keeps or drops each triangle: no adjacency, no CPU work
// per frame, any mesh (soups, refused faces) at the cost of one more draw of every triangle.
// Where each is the better choice is in the README (*Lines*), measured by bench_styles.
#pragma once

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/program_cache.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// Draws what `lines` asks of the two (nothing when neither is on). The rim needs `palette`
// (it is skipped without one), laid as `pattern` says, and matches in `match`.
[[nodiscard]] Status drawHardwareOutlines(const GpuMesh& mesh, const CameraMatrices& camera, const LineSettings& lines,
                                          const GpuPalette* palette, const PatternPlacement& pattern, MatchMode match, const glm::ivec4& viewport,
                                          gl::ProgramCache& programs, FrameStats& stats);

}  // namespace npr
