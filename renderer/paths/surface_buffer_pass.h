// The stencil path's per-pixel buffers: its layer quads cover the screen and know nothing of
// the surface under a pixel, so what they need of it is written before they are drawn: each
// pixel's stroke angle on screen and whether it has one (hatching orientation along the
// curvature or the light), or its object-space pattern coordinate and mip level (--pattern
// object): what the shaded paths compute in place. The stencil path's masks write them as
// they mark (output() below, gl/shared_depth_framebuffer.h); where they cannot (the window's
// own framebuffer, the per-bucket order), draw() draws them in an extra geometry pass each,
// with its own depth buffer, only when a frame needs them.
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/result.h"
#include "renderer/gl/texture_target.h"
#include "renderer/frame/frame_context.h"

namespace npr {

// Draws each pixel's (stroke angle in radians, 1 where it has one) of `f`'s mesh into the
// bound framebuffer (a float target): the buffer's contents, and a test output.
[[nodiscard]] Status drawStrokeAngles(FrameContext& f);

class SurfaceBufferPass {
 public:
  enum class Content { StrokeAngles, PatternCoordinates };
  explicit SurfaceBufferPass(Content content) : content_(content) {}
  // Draws the buffer for `f`'s mesh (its palette says where angles and patterns come from)
  // and leaves the bound framebuffer and viewport as they were. `meshRect` (x0, y0, x1, y1,
  // viewport pixels) bounds the mesh on screen: only there is the depth cleared. The colour
  // is never cleared: the quads read only pixels their mask marked, which the mesh covers, so
  // the pass has written them (clearing the float buffer was 3 of the bunny's 7 ms here).
  [[nodiscard]] Status draw(FrameContext& f, const glm::ivec4& meshRect);
  // The buffer's texture sized for the whole framebuffer up to the viewport's far corner, for
  // a mask pass to write at its pixels' own coordinates (allocates only on a size change).
  GLuint output(const glm::ivec4& viewport, FrameStats& stats);
  // Binds the buffer for a layer quad compiled with ORIENT_BUFFER or PATTERN_OBJECT_BUFFER;
  // `origin` is the framebuffer pixel its texel (0, 0) holds: the viewport's corner after
  // draw(), (0, 0) after output().
  void bind(gl::ShaderProgram& program, const glm::ivec2& origin) const;

 private:
  bool resize(const glm::ivec2& size, FrameStats& stats);
  Content content_;
  gl::TextureTarget target_;
};

}  // namespace npr
