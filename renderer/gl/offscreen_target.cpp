// FBO creation and read-back (see offscreen_target.h).
#include "renderer/gl/offscreen_target.h"
#include "renderer/gl/pass_state.h"

#include <algorithm>

#include <string>

#include "renderer/gl/texture.h"

namespace npr {

Result<OffscreenTarget> OffscreenTarget::create(int width, int height, Format format) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize)
    return Error{"framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                 " is outside 1.." + std::to_string(maxSize)};
  OffscreenTarget t;
  t.width_ = width;
  t.height_ = height;
  t.color_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, t.color_.id());
  const bool f32 = format == Format::RGBA32F;
  glTexImage2D(GL_TEXTURE_2D, 0, f32 ? GL_RGBA32F : GL_RGBA8, width, height, 0, GL_RGBA, f32 ? GL_FLOAT : GL_UNSIGNED_BYTE, nullptr);
  gl::setNearestSingleLevel(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  t.depthStencil_ = gl::createRenderbuffer();
  glBindRenderbuffer(GL_RENDERBUFFER, t.depthStencil_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  t.fbo_ = gl::createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, t.fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, t.depthStencil_.id());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) return Error{"offscreen framebuffer incomplete (status " + std::to_string(status) + ")"};
  return t;
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
}

void OffscreenTarget::clear(const glm::vec4& colour) const {
  bind();
  glClearColor(colour.r, colour.g, colour.b, colour.a);
  glClear(GL_COLOR_BUFFER_BIT);
}

void OffscreenTarget::copyToWindow() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glDisable(GL_SCISSOR_TEST);  // a blit is clipped by it (a pass may leave it on)
  gl::forgetAppliedState();
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {
template <class T>
void flipRows(std::vector<T>& px, int w, int h) {
  const size_t row = static_cast<size_t>(w) * 4;
  for (int y = 0; y < h / 2; ++y)
    std::swap_ranges(px.begin() + y * row, px.begin() + (y + 1) * row, px.begin() + (h - 1 - y) * row);
}
}  // namespace

ImageRGBA8 OffscreenTarget::readRGBA8() const {
  ImageRGBA8 img{width_, height_, std::vector<std::uint8_t>(static_cast<size_t>(width_) * height_ * 4)};
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  flipRows(img.pixels, width_, height_);
  return img;
}

ImageRGBA32F OffscreenTarget::readRGBA32F() const {
  ImageRGBA32F img{width_, height_, std::vector<float>(static_cast<size_t>(width_) * height_ * 4)};
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, img.pixels.data());
  flipRows(img.pixels, width_, height_);
  return img;
}

}  // namespace npr

namespace npr {
ImageRGBA8 readFramebufferRGBA8(int x, int y, int width, int height) {
  ImageRGBA8 img{width, height, std::vector<std::uint8_t>(static_cast<size_t>(width) * height * 4)};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
  flipRows(img.pixels, width, height);
  for (size_t i = 3; i < img.pixels.size(); i += 4) img.pixels[i] = 255;  // a window's alpha is meaningless
  return img;
}
}  // namespace npr

namespace npr {
void bindWindowFramebuffer() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }
void finishGpuWork() { glFinish(); }
void clearRightOf(int fromX, int width, int height) {
  if (fromX >= width || height <= 0) return;
  glEnable(GL_SCISSOR_TEST);
  glScissor(fromX, 0, width - fromX, height);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  gl::forgetAppliedState();
}
int maxFramebufferSide() {
  GLint renderbuffer = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  return std::min({int(renderbuffer), int(viewport[0]), int(viewport[1])});
}

}  // namespace npr
