// Anti-aliasing over the whole frame (RenderSettings::aa), drawn into a target of ours and then
// resolved into the framebuffer that was bound, over the viewport. Supersampling (SsaaK): the
// frame drawn at k times the viewport's width and height, every size in pixels scaled by k
// (pixelSizesScaled), box-filtered down: tone edges, silhouettes and lines are smoothed, a
// palette's texels cover whole k x k blocks and come out as drawn; about k^2 the frame's fill.
// The post-process filter (Fxaa): the frame drawn at its size, then shaders/edge_filter.frag:
// one full-screen pass, which softens the pattern's strokes with the edges.
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
  // target's corner); the result is resolved (box-filtered, or with `filter` the edge filter
  // run over it) into the framebuffer bound on entry, which is bound again on return. `k` is
  // lowered to what the GL's framebuffer limit allows; at 1 without `filter` the frame is drawn
  // straight into the bound framebuffer.
  Status run(int k, bool filter, const glm::ivec4& viewport, gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats,
             const std::function<Status(int k, const glm::ivec4& viewport)>& draw);
  // The factor run() draws `viewport` at when asked for `k`: lowered to what the GL's
  // framebuffer limit allows.
  static int factorFor(int k, const glm::ivec4& viewport);

 private:
  std::optional<OffscreenTarget> target_;
};

}  // namespace npr
