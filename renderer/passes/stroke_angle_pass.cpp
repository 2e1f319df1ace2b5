// The stroke-angle buffer (see stroke_angle_pass.h).
#include "renderer/passes/stroke_angle_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"

namespace npr {

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
  if (target_.resize({vp.z, vp.w}, GL_RG16F, GL_RG)) ++f.stats.bufferUploads;
  target_.bindAndClear();
  const Status st = drawStrokeAngles(f);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(vp.x, vp.y, vp.z, vp.w);
  return st;
}

void StrokeAnglePass::bind(gl::ShaderProgram& p, const glm::ivec4& viewport) const {
  gl::bindTexture(gl::TextureUnit::StrokeAngles, GL_TEXTURE_2D, target_.colour());
  p.set("uStrokeAngles", gl::unitIndex(gl::TextureUnit::StrokeAngles));
  p.set("uViewportOrigin", glm::ivec2(viewport.x, viewport.y));
}

}  // namespace npr
