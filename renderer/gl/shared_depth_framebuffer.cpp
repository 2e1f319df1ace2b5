// Sharing the caller's depth-stencil image (see shared_depth_framebuffer.h).
#include "renderer/gl/shared_depth_framebuffer.h"

namespace npr::gl {
namespace {

struct Attached {
  GLint type = GL_NONE, name = 0;
  bool usable = false;
};

// What the bound draw framebuffer holds at `attachment`, and whether we may attach it too.
Attached attachedAt(GLenum attachment) {
  Attached a;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &a.type);
  if (a.type == GL_NONE) return a;
  glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &a.name);
  if (a.type == GL_RENDERBUFFER) {
    a.usable = true;
  } else if (a.type == GL_TEXTURE) {
    GLint level = -1, layered = GL_TRUE, target = 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
    glGetTextureParameteriv(static_cast<GLuint>(a.name), GL_TEXTURE_TARGET, &target);
    a.usable = level == 0 && layered == GL_FALSE && target == GL_TEXTURE_2D;
  }
  return a;
}

void attach(GLuint fbo, GLenum attachment, GLint type, GLint name) {
  if (type == GL_RENDERBUFFER) glNamedFramebufferRenderbuffer(fbo, attachment, GL_RENDERBUFFER, static_cast<GLuint>(name));
  else glNamedFramebufferTexture(fbo, attachment, static_cast<GLuint>(name), 0);
}

}  // namespace

bool SharedDepthFramebuffer::bind(const std::array<GLuint, kOutputs>& outputs) {
  GLint caller = 0, samples = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &caller);
  if (caller == 0) return false;
  glGetIntegerv(GL_SAMPLES, &samples);
  if (samples > 0) return false;
  const Attached depth = attachedAt(GL_DEPTH_ATTACHMENT), stencil = attachedAt(GL_STENCIL_ATTACHMENT);
  if (!stencil.usable || (depth.type != GL_NONE && !depth.usable)) return false;
  if (!fbo_.id()) {
    GLuint n = 0;
    glCreateFramebuffers(1, &n);
    fbo_ = Framebuffer(n);
    const GLenum buffers[kOutputs + 1] = {GL_NONE, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fbo_.id(), kOutputs + 1, buffers);
  }
  // Attached afresh each time and detached by restore(): a name the caller deleted and had
  // given again would otherwise leave us drawing into the old image, and holding it alive.
  if (depth.type == stencil.type && depth.name == stencil.name) {  // one packed image
    attach(fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, stencil.type, stencil.name);
  } else {
    if (depth.type != GL_NONE) attach(fbo_.id(), GL_DEPTH_ATTACHMENT, depth.type, depth.name);
    attach(fbo_.id(), GL_STENCIL_ATTACHMENT, stencil.type, stencil.name);
  }
  if (outputs != outputs_) {
    for (int i = 0; i < kOutputs; ++i)
      glNamedFramebufferTexture(fbo_.id(), GLenum(GL_COLOR_ATTACHMENT1 + i), outputs[static_cast<std::size_t>(i)], 0);
    outputs_ = outputs;
  }
  if (glCheckNamedFramebufferStatus(fbo_.id(), GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    detachDepthStencil();
    return false;
  }
  caller_ = caller;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
  return true;
}

void SharedDepthFramebuffer::restore() const {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(caller_));
  detachDepthStencil();
}

void SharedDepthFramebuffer::detachDepthStencil() const {
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);  // both
}

}  // namespace npr::gl
