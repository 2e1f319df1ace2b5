// Mesh upload and drawing (see gpu_mesh.h).
#include "renderer/mesh/gpu_mesh.h"

namespace npr {
namespace {

gl::Buffer staticBuffer(const void* data, std::size_t bytes) {
  gl::Buffer b = gl::createBuffer();
  gl::uploadBuffer(b, data, bytes, GL_STATIC_DRAW);
  return b;
}

}  // namespace

void GpuMesh::clear() {
  vao_.reset();
  positions_.reset();
  normals_.reset();
  indices_.reset();
  triangleCount_ = 0;
}

void GpuMesh::upload(const Mesh& mesh) {
  clear();
  if (mesh.indices.empty()) return;
  triangleCount_ = mesh.triangleCount();
  positions_ = staticBuffer(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  normals_ = staticBuffer(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  indices_ = staticBuffer(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  vao_ = gl::createVertexArray();
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, positions_.id());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, normals_.id());
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBindVertexArray(0);
}

void GpuMesh::drawAll() const {
  bindIndices(indices_);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangleCount_ * 3), GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::bindIndices(const gl::Buffer& indices) const {
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices.id());
}

void GpuMesh::drawTriangles(std::uint32_t first, std::uint32_t count) const {
  if (count == 0) return;
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count * 3), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 3 * sizeof(std::uint32_t)));
}

void setMeshTransform(gl::ShaderProgram& program, const CameraMatrices& camera) {
  const glm::mat4& modelView = camera.view;
  program.set("uModelView", modelView);
  program.set("uProjection", camera.projection);
  program.set("uNormalMatrix", glm::transpose(glm::inverse(glm::mat3(modelView))));
}

}  // namespace npr
