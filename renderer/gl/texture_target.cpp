// Off-screen colour and depth targets (see texture_target.h).
#include "renderer/gl/texture_target.h"

#include "renderer/gl/pass_state.h"

namespace npr::gl {

bool TextureTarget::resize(const glm::ivec2& size, GLenum internalFormat) {
  if (size == size_ && fbo_.id()) return false;
  // Direct state access throughout: resizing happens in the middle of passes that draw into
  // the caller's framebuffer, and leaves every binding (framebuffer, texture unit) as it was.
  const auto image = [&](GLenum storage) {
    GLuint n = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &n);
    Texture t(n);
    glTextureStorage2D(n, 1, storage, size.x, size.y);
    glTextureParameteri(n, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(n, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
  };
  colour_ = image(internalFormat);
  depth_ = image(GL_DEPTH_COMPONENT24);
  GLuint n = 0;
  glCreateFramebuffers(1, &n);
  fbo_ = Framebuffer(n);
  glNamedFramebufferTexture(n, GL_COLOR_ATTACHMENT0, colour_.id(), 0);
  glNamedFramebufferTexture(n, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
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
