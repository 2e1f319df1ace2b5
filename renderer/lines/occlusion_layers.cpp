// Depth peeling for the hidden lines' occlusion levels (see occlusion_layers.h).
#include "renderer/lines/occlusion_layers.h"

#include <string>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture.h"
#include "renderer/materials/gpu_materials.h"
#include "renderer/programs/program_variants.h"

namespace npr {

Status OcclusionLayers::build(int levels, const std::vector<PlacedMesh>& meshes, float radius, const glm::ivec4& viewport,
                              gl::ProgramCache& programs, FrameStats& stats) {
  const glm::ivec2 size(viewport.z, viewport.w);
  if (size.x < 1 || size.y < 1) return okStatus();
  if (!fbo_) fbo_ = gl::createFramebuffer();
  if (int(layers_.size()) < levels + 1 || size.x > size_.x || size.y > size_.y) {
    size_ = glm::max(size_, size);
    layers_.clear();
    for (int k = 0; k <= levels; ++k) {
      layers_.push_back(gl::createTexture());
      glBindTexture(GL_TEXTURE_2D, layers_.back().id());
      glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size_.x, size_.y, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
      gl::setNearestSingleLevel(GL_TEXTURE_2D);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  tolerance_ = 0.005f * radius;
  GLint drawn = 0, read = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawn);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  // Layer 0: what the frame drew.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(drawn));
  glBindTexture(GL_TEXTURE_2D, layers_[0].id());
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, viewport.x, viewport.y, size.x, size.y);
  glBindTexture(GL_TEXTURE_2D, 0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));

  Status result = okStatus();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  for (int k = 1; k <= levels && result; ++k) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, layers_[std::size_t(k)].id(), 0);
    if (const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE) {
      result = Error{"the hidden lines' occlusion layers: framebuffer incomplete (status " + std::to_string(status) + ")"};
      break;
    }
    glViewport(0, 0, size.x, size.y);
    gl::apply(gl::pass::kClearTarget);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    gl::apply(gl::pass::kMesh);
    gl::bindTexture(kPeelUnit, GL_TEXTURE_2D, layers_[std::size_t(k - 1)].id());
    for (const PlacedMesh& m : meshes) {
      gl::MeshProgram variant;
      variant.shading = gl::MeshShading::Mask;
      variant.peel = true;
      if (m.materials) m.materials->addCoverage(variant);
      Result<gl::ShaderProgram*> prog = programs.get(variant, stats.shaderBuilds);
      if (!prog) {
        result = Error{prog.error()};
        break;
      }
      gl::ShaderProgram& p = **prog;
      p.use();
      if (variant.alphaCoverage) m.materials->bind(p);
      setMeshTransform(p, m.camera);
      p.set("uPeelFront", gl::unitIndex(kPeelUnit));
      p.set("uPeelDepthMap", depthDistanceMap(m.camera.projection));
      p.set("uPeelTolerance", tolerance_);
      m.mesh->drawAll();
      ++stats.drawCalls;
    }
  }
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawn));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  gl::restoreDefaults();
  return result;
}

}  // namespace npr
