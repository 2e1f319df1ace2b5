// A framebuffer of our own that draws into the depth-stencil image of whichever framebuffer
// the caller bound, plus colour textures of ours: how one geometry pass can both test and
// write the caller's depth and stencil and write per-pixel data the caller's framebuffer has
// no room for (the stencil path's masks and its surface buffers). The caller's framebuffer is
// only read about, never changed; the default framebuffer's images cannot be shared, so there
// the caller draws its data in a pass of its own.
#pragma once

#include <epoxy/gl.h>

#include <array>

#include "renderer/gl/gl_handle.h"

namespace npr::gl {

class SharedDepthFramebuffer {
 public:
  static constexpr int kOutputs = 2;
  // Binds a framebuffer with the bound draw framebuffer's depth and stencil images and
  // `outputs[i]` (a 2D texture, or 0 for none) at colour attachment i + 1, drawn to by
  // fragment output i + 1 (output 0 goes nowhere). False, with nothing changed, when the bound
  // framebuffer is the default one, multisampled, has no stencil, or holds its depth or
  // stencil in anything but one level of a 2D texture or a renderbuffer.
  bool bind(const std::array<GLuint, kOutputs>& outputs);
  // Binds back the framebuffer that was bound when bind() succeeded, and lets go of its
  // depth and stencil images.
  void restore() const;

 private:
  void detachDepthStencil() const;
  Framebuffer fbo_;
  GLint caller_ = 0;
  std::array<GLuint, kOutputs> outputs_{};
};

}  // namespace npr::gl
