// A texture of the viewport's size with a depth texture, as one framebuffer: what passes that
// draw the mesh off screen and then read the result per pixel use (image-space edges, the
// stencil path's stroke angles). Reallocated only when the size changes.
#pragma once

#include <epoxy/gl.h>

#include <glm/glm.hpp>

#include "renderer/gl/gl_handle.h"

namespace npr::gl {

class TextureTarget {
 public:
  // (Re)allocates at `size` with a colour texture of `internalFormat`; true when it did, false
  // when it already had that size. Changes no binding.
  bool resize(const glm::ivec2& size, GLenum internalFormat);
  // Binds for drawing over the whole target and clears colour (to 0) and depth.
  void bindAndClear() const;
  // Binds for drawing over the whole target, clearing nothing.
  void bind() const;
  GLuint colour() const { return colour_.id(); }
  GLuint depth() const { return depth_.id(); }
  glm::ivec2 size() const { return size_; }

 private:
  Framebuffer fbo_;
  Texture colour_, depth_;
  glm::ivec2 size_{0};
};

// Depth-compare sampling (sampler*Shadow) with bilinear filtering of the comparisons, clamped
// at the edges, one level: for the texture bound to `target` on the active unit.
void setDepthCompare(GLenum target);

}  // namespace npr::gl
