// Anti-aliasing by supersampling (RenderSettings::aa, SsaaK): the frame drawn at k times the
// viewport's width and height into a target of ours, every size in pixels scaled by k
// (pixelSizesScaled), then box-filtered into the framebuffer that was bound, over the
// viewport. Tone edges, silhouettes and lines are smoothed; a palette's texels cover whole
// k x k blocks and come out as drawn. It costs about k^2 the frame's fill.
#pragma once

#include <functional>
#include <optional>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/gl/program_cache.h"

namespace npr {

class Supersampler {
 public:
  // `draw` draws the frame over the viewport it is given (k times `viewport`'s size, at the
  // target's corner); the result is resolved into the framebuffer bound on entry, which is
  // bound again on return. `k` is lowered to what the GL's framebuffer limit allows.
  Status run(int k, const glm::ivec4& viewport, gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats,
             const std::function<Status(int k, const glm::ivec4& viewport)>& draw);
  // The factor run() draws `viewport` at when asked for `k`: lowered to what the GL's
  // framebuffer limit allows.
  static int factorFor(int k, const glm::ivec4& viewport);

 private:
  std::optional<OffscreenTarget> target_;
};

}  // namespace npr
