// A framebuffer object with a colour attachment and a depth24/stencil8 attachment: what
// headless rendering draws into and reads back from, and what the window draws its scene
// into (passes that share a framebuffer's depth and stencil cannot share the window's).
#pragma once

#include <glm/glm.hpp>

#include "renderer/core/image.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/core/result.h"

namespace npr {

class OffscreenTarget {
 public:
  enum class Format { RGBA8, RGBA32F };
  static Result<OffscreenTarget> create(int width, int height, Format format = Format::RGBA8);

  void bind() const;  // binds for drawing and sets the viewport to the whole target
  void clear(const glm::vec4& colour) const;  // binds, then clears colour (for float read-backs)
  int width() const { return width_; }
  int height() const { return height_; }
  GLuint colourTexture() const { return color_.id(); }
  ImageRGBA8 readRGBA8() const;
  ImageRGBA32F readRGBA32F() const;
  // Copies the colour to the window's framebuffer at its corner, pixel for pixel, and leaves
  // the window's framebuffer bound: how the viewer shows a scene it drew here.
  void copyToWindow() const;

 private:
  int width_ = 0, height_ = 0;
  gl::Framebuffer fbo_;
  gl::Texture color_;
  gl::Renderbuffer depthStencil_;
};

}  // namespace npr

namespace npr {
// Reads `width` x `height` pixels from the bound read framebuffer (the window's for F12).
ImageRGBA8 readFramebufferRGBA8(int x, int y, int width, int height);
// The largest framebuffer side this GL draws into (renderbuffer and viewport limits).
int maxFramebufferSide();
// Makes the window's own framebuffer the target again (after offscreen passes).
void bindWindowFramebuffer();
// Clears the pixels x >= `fromX` of the bound framebuffer to black (the strip under the
// window's docked panel, which the scene does not draw).
void clearRightOf(int fromX, int width, int height);
// Blocks until the GPU has finished all submitted work: what frame timings must include.
void finishGpuWork();
}  // namespace npr
