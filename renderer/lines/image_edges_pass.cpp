// Image-space edges (see image_edges_pass.h).
#include "renderer/lines/image_edges_pass.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture.h"
#include "renderer/gl/texture_units.h"
#include "renderer/passes/geometry_pass.h"

namespace npr {

void ImageEdgesPass::resize(const glm::ivec2& size, FrameStats& stats) {
  normals_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, normals_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
  gl::setNearestSingleLevel(GL_TEXTURE_2D);
  depth_ = gl::createTexture();
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size.x, size.y, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  gl::setNearestSingleLevel(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, 0);
  fbo_ = gl::createFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, normals_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  size_ = size;
  ++stats.bufferUploads;
}

Status ImageEdgesPass::draw(const GpuMesh& mesh, const CameraMatrices& camera, const LineSettings& ls, const glm::ivec4& viewport,
                            gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats) {
  if (!ls.imageSpace) return okStatus();
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const glm::ivec2 size(viewport.z, viewport.w);
  if (size != size_) resize(size, stats);
  // The geometry pass: normals and depth of what this frame shows.
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size.x, size.y);
  glClearColor(0, 0, 0, 0);
  gl::apply(gl::pass::kClearTarget);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  Status status = drawGeometry(mesh, camera, GeometryOutput::EyeNormal, programs, stats);
  Result<gl::ShaderProgram*> sobel = programs.get(gl::EdgeProgram{}, stats.shaderBuilds);
  if (status && !sobel) status = Error{sobel.error()};
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  if (!status) return status;
  // The full-screen pass over the frame.
  gl::apply(gl::pass::kScreenOverlay);
  gl::ShaderProgram& p = **sobel;
  p.use();
  gl::bindTexture(gl::TextureUnit::EdgeNormals, GL_TEXTURE_2D, normals_.id());
  gl::bindTexture(gl::TextureUnit::EdgeDepth, GL_TEXTURE_2D, depth_.id());
  p.set("uNormals", gl::unitIndex(gl::TextureUnit::EdgeNormals));
  p.set("uDepth", gl::unitIndex(gl::TextureUnit::EdgeDepth));
  p.set("uOrigin", glm::ivec2(viewport.x, viewport.y));
  p.set("uProjection", glm::vec2(camera.projection[2][2], camera.projection[3][2]));
  p.set("uThreshold", std::max(ls.imageThreshold, 1e-3f));
  p.set("uInk", ls.silhouetteColour);
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++stats.drawCalls;
  return okStatus();
}

}  // namespace npr
