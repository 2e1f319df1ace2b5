// The background every frame starts from: the palette's paper (a colour or a tiled image in
// screen space, at the frame's pattern scale and tile offset), white without a palette. Drawn
// behind everything; touches no depth.
#pragma once

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/palette/gpu_palette.h"

namespace npr {

[[nodiscard]] Status drawBackground(const GpuPalette* palette, const PatternPlacement& pattern, gl::ProgramCache& programs,
                                    const gl::VertexArray& emptyVao, FrameStats& stats);

}  // namespace npr
