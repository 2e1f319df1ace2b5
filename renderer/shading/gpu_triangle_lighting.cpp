// Per-triangle lighting on the GPU (see gpu_triangle_lighting.h).
#include "renderer/shading/gpu_triangle_lighting.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture.h"
#include "renderer/lighting/lighting_uniforms.h"
#include "renderer/lighting/occlusion_factor.h"

namespace npr {

void GpuTriangleLighting::setMesh(const Mesh* mesh, const Mesh* vertices) {
  mesh_ = mesh;
  vertices_ = vertices ? vertices : mesh;
  vao_.reset();
  centroids_.reset();
  normals_.reset();
  occlusion_.reset();
  occlusionFrom_ = nullptr;
}

void GpuTriangleLighting::geometryChanged() {
  if (!mesh_ || !vao_.id()) return;
  const std::size_t nt = mesh_->triangleCount();
  gl::updateBuffer(centroids_, mesh_->faceCentroids.data(), nt * sizeof(glm::vec3));
  gl::updateBuffer(normals_, mesh_->faceNormals.data(), nt * sizeof(glm::vec3));
}

Status GpuTriangleLighting::shade(const GpuTriangleLightingInputs& in, gl::ProgramCache& programs, FrameStats& stats,
                                  std::vector<std::uint8_t>& entries) {
  if (!mesh_ || mesh_->triangleCount() == 0) return okStatus();
  const std::size_t nt = mesh_->triangleCount();
  if (!vao_.id()) {
    centroids_ = gl::createBuffer();
    gl::uploadBuffer(centroids_, mesh_->faceCentroids.data(), nt * sizeof(glm::vec3), GL_STATIC_DRAW);
    normals_ = gl::createBuffer();
    gl::uploadBuffer(normals_, mesh_->faceNormals.data(), nt * sizeof(glm::vec3), GL_STATIC_DRAW);
    vao_ = gl::createVertexArray();
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, centroids_.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, normals_.id());
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    stats.bufferUploads += 2;
  }
  const bool occluded = in.occlusion && in.occlusion->size() == vertices_->positions.size();
  if (occluded && occlusionFrom_ != in.occlusion->data()) {
    std::vector<float> face(nt);
    const float* o = in.occlusion->data();
    for (std::size_t f = 0; f < nt; ++f) {
      const std::uint32_t* v = &mesh_->indices[f * 3];
      face[f] = (o[v[0]] + o[v[1]] + o[v[2]]) / 3.0f;
    }
    occlusion_ = gl::createBuffer();
    gl::uploadBuffer(occlusion_, face.data(), nt * sizeof(float), GL_STATIC_DRAW);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, occlusion_.id());
    glEnableVertexAttribArray(7);
    glVertexAttribPointer(7, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    occlusionFrom_ = in.occlusion->data();
    ++stats.bufferUploads;
  }
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int w = std::min(maxSize, 4096);
  const glm::ivec2 size(w, int((nt + std::size_t(w) - 1) / std::size_t(w)));
  if (size.y > maxSize) return Error{"GPU triangle lighting: too many triangles for one target"};
  GLint previous = 0, vp[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glGetIntegerv(GL_VIEWPORT, vp);
  if (size != size_ || !fbo_.id()) {
    target_ = gl::createTexture();
    glBindTexture(GL_TEXTURE_2D, target_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, size.x, size.y, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    gl::setNearestSingleLevel(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    fbo_ = gl::createFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target_.id(), 0);
    size_ = size;
  }

  gl::TriangleLightProgram variant;
  variant.lighting = in.lighting.features();
  variant.palette = in.palette.matchingVariant(in.match);
  variant.shadowLayers = in.shadows ? in.shadows->layers() : 0;
  variant.occlusion = occluded;
  Result<gl::ShaderProgram*> prog = programs.get(variant, stats.shaderBuilds);
  if (!prog) {
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
    return Error{prog.error()};
  }
  gl::ShaderProgram& p = **prog;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, size.x, size.y);
  gl::apply(gl::pass::kBackground);
  p.use();
  p.set("uModelView", in.camera.view);
  p.set("uNormalMatrix", glm::transpose(glm::inverse(glm::mat3(in.camera.view))));
  p.set("uTargetSize", size);
  uploadLightingUniforms(p, prepareLighting<float>(in.lighting));
  in.palette.bindMatching(p);
  if (in.shadows) in.shadows->bind(p, in.sceneView);
  if (occluded) p.set("uOcclusionStrength", occlusionStrength(in.occlusionStrength));
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(nt));
  ++stats.drawCalls;
  // The whole rows, then the used prefix.
  std::vector<std::uint8_t> texels(std::size_t(size.x) * std::size_t(size.y));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, size.x, size.y, GL_RED_INTEGER, GL_UNSIGNED_BYTE, texels.data());
  entries.assign(texels.begin(), texels.begin() + static_cast<std::ptrdiff_t>(nt));
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  glViewport(vp[0], vp[1], vp[2], vp[3]);
  return okStatus();
}

}  // namespace npr
