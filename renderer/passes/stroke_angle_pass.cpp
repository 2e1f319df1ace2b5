// The stroke-angle buffer (see stroke_angle_pass.h).
#include "renderer/passes/stroke_angle_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture.h"
#include "renderer/gl/texture_units.h"

namespace npr {

void StrokeAnglePass::resize(const glm::ivec2& size, FrameStats& stats) {
  angles_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, angles_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, size.x, size.y, 0, GL_RG, GL_FLOAT, nullptr);
  gl::setNearestSingleLevel(GL_TEXTURE_2D);
  depth_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size.x, size.y, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  gl::setNearestSingleLevel(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  fbo_ = gl::createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, angles_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  size_ = size;
  ++stats.bufferUploads;
}

Status drawStrokeAngles(FrameContext& f) {
  gl::MeshProgram variant;
  variant.shading = gl::MeshShading::StrokeAngle;
  variant.stroke = f.strokeSource();
  Result<gl::ShaderProgram*> prog = f.program(variant);
  if (!prog) return Error{prog.error()};
  gl::apply(gl::pass::kMesh);
  (*prog)->use();
  setMeshTransform(**prog, f.camera);
  f.palette->bindStrokeSource(**prog);
  f.gpuMesh.drawAll();
  ++f.stats.drawCalls;
  return okStatus();
}

Status StrokeAnglePass::draw(FrameContext& f) {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const glm::ivec4& vp = f.viewport;
  const glm::ivec2 size(vp.z, vp.w);
  if (size != size_) resize(size, f.stats);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size.x, size.y);
  glClearColor(0, 0, 0, 0);
  gl::apply(gl::pass::kClearTarget);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Status st = drawStrokeAngles(f);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(vp.x, vp.y, vp.z, vp.w);
  return st;
}

void StrokeAnglePass::bind(gl::ShaderProgram& p, const glm::ivec4& viewport) const {
  gl::bindTexture(gl::TextureUnit::StrokeAngles, GL_TEXTURE_2D, angles_.id());
  p.set("uStrokeAngles", gl::unitIndex(gl::TextureUnit::StrokeAngles));
  p.set("uViewportOrigin", glm::ivec2(viewport.x, viewport.y));
}

}  // namespace npr
