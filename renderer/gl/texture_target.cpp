// Off-screen colour and depth targets (see texture_target.h).
#include "renderer/gl/texture_target.h"

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture.h"

namespace npr::gl {

bool TextureTarget::resize(const glm::ivec2& size, GLint internalFormat, GLenum format) {
  if (size == size_ && fbo_.id()) return false;
  colour_ = createTexture();
  glBindTexture(GL_TEXTURE_2D, colour_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, size.x, size.y, 0, format, GL_FLOAT, nullptr);
  setNearestSingleLevel(GL_TEXTURE_2D);
  depth_ = createTexture();
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size.x, size.y, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  setNearestSingleLevel(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  fbo_ = createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  size_ = size;
  return true;
}

void TextureTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size_.x, size_.y);
}

void TextureTarget::bindAndClear() const {
  bind();
  glClearColor(0, 0, 0, 0);
  apply(pass::kClearTarget);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void setDepthCompare(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

}  // namespace npr::gl
