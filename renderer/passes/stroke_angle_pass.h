// The stencil path's stroke-angle buffer: its layer quads cover the screen and know nothing of
// the surface under a pixel, so with hatching orientation on (curvature or light) the mesh is
// drawn once more into a texture of the viewport's size holding each pixel's stroke angle on
// screen and whether it has one (the angle the shaded paths compute in place). One extra
// geometry pass, with its own depth buffer, drawn only when a frame needs it.
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/result.h"
#include "renderer/gl/texture_target.h"
#include "renderer/paths/render_pass.h"

namespace npr {

// Draws each pixel's (stroke angle in radians, 1 where it has one) of `f`'s mesh into the
// bound framebuffer (a float target): the buffer's contents, and a test output.
[[nodiscard]] Status drawStrokeAngles(FrameContext& f);

class StrokeAnglePass {
 public:
  // Draws the angles of `f`'s mesh (its palette says where they come from) and leaves the
  // bound framebuffer and viewport as they were.
  [[nodiscard]] Status draw(FrameContext& f);
  // Binds the angles for a layer quad compiled with ORIENT_BUFFER.
  void bind(gl::ShaderProgram& program, const glm::ivec4& viewport) const;

 private:
  gl::TextureTarget target_;  // (angle, valid) and depth
};

}  // namespace npr
