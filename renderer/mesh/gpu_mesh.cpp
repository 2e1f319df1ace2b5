// Mesh upload and drawing (see gpu_mesh.h).
#include "renderer/mesh/gpu_mesh.h"

#include <algorithm>

namespace npr {
namespace {

gl::Buffer staticBuffer(const void* data, std::size_t bytes) {
  gl::Buffer b = gl::createBuffer();
  gl::uploadBuffer(b, data, bytes, GL_STATIC_DRAW);
  return b;
}

// Float attribute `location` from `buffer` (tightly packed), in the bound vertex array.
void floatAttribute(GLuint location, const gl::Buffer& buffer, int components) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, components * static_cast<GLsizei>(sizeof(float)), nullptr);
}

// The mesh's triangles grouped by material, each group in the mesh's order (a counting sort),
// and the groups.
std::vector<std::uint32_t> groupedByMaterial(const Mesh& mesh, std::vector<MaterialRun>& runs) {
  const std::size_t n = mesh.triangleCount();
  runs.clear();
  if (mesh.faceMaterials.size() != n) {
    runs.push_back({0, 0, static_cast<std::uint32_t>(n)});
    return mesh.indices;
  }
  std::vector<std::uint32_t> count(std::size_t(*std::max_element(mesh.faceMaterials.begin(), mesh.faceMaterials.end())) + 1, 0);
  for (std::uint16_t m : mesh.faceMaterials) ++count[m];
  std::vector<std::uint32_t> next(count.size(), 0);
  std::uint32_t first = 0;
  for (std::size_t m = 0; m < count.size(); ++m) {
    next[m] = first;
    if (count[m] > 0) runs.push_back({static_cast<std::uint16_t>(m), first, count[m]});
    first += count[m];
  }
  std::vector<std::uint32_t> indices(mesh.indices.size());
  for (std::size_t f = 0; f < n; ++f) {
    const std::size_t to = std::size_t(next[mesh.faceMaterials[f]]++) * 3;
    for (std::size_t k = 0; k < 3; ++k) indices[to + k] = mesh.indices[f * 3 + k];
  }
  return indices;
}

}  // namespace

void GpuMesh::clear() {
  vao_.reset();
  positions_.reset();
  normals_.reset();
  indices_.reset();
  colours_.reset();
  texcoords_.reset();
  materials_.reset();
  mapAverages_.reset();
  directions_.reset();
  occlusion_.reset();
  restPositions_.reset();
  restNormals_.reset();
  runs_.clear();
  shared_ = nullptr;
  triangleCount_ = 0;
  vertexCount_ = 0;
}

void GpuMesh::upload(const Mesh& mesh) {
  clear();
  if (mesh.indices.empty()) return;
  vertexCount_ = mesh.positions.size();
  positions_ = staticBuffer(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  normals_ = staticBuffer(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  if (!mesh.deformation.empty()) {  // uploaded at rest: kept as the rest pose
    restPositions_ = staticBuffer(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    restNormals_ = staticBuffer(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  }
  if (mesh.hasAppearance()) uploadAppearance(mesh);
  uploadIndices(mesh);
  vao_ = gl::createVertexArray();
  bindStreams(*this);
}

void GpuMesh::updateGeometry(const Mesh& mesh) {
  if (!positions_.id() || mesh.positions.size() != vertexCount_ || mesh.normals.size() != vertexCount_) return;
  gl::updateBuffer(positions_, mesh.positions.data(), vertexCount_ * sizeof(glm::vec3));
  gl::updateBuffer(normals_, mesh.normals.data(), vertexCount_ * sizeof(glm::vec3));
}

void GpuMesh::uploadPart(const GpuMesh& base, const Mesh& part) {
  clear();
  if (part.indices.empty() || !base.vao_.id()) return;
  vertexCount_ = base.vertexCount_;
  uploadIndices(part);
  vao_ = gl::createVertexArray();
  bindStreams(base);
}

void GpuMesh::shareStreamsOf(const GpuMesh& base) { bindStreams(base); }

void GpuMesh::uploadIndices(const Mesh& mesh) {
  triangleCount_ = mesh.triangleCount();
  if (mesh.hasAppearance()) {
    const std::vector<std::uint32_t> grouped = groupedByMaterial(mesh, runs_);
    indices_ = staticBuffer(grouped.data(), grouped.size() * sizeof(std::uint32_t));
  } else {
    indices_ = staticBuffer(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  }
}

void GpuMesh::bindStreams(const GpuMesh& source) {
  if (!vao_.id()) return;
  // A part draws through its model's streams: vertices are split per material while loading,
  // so a vertex's faces, its material and its map average are all of one part, and the
  // model's per-vertex streams are the part's exactly.
  glBindVertexArray(vao_.id());
  floatAttribute(0, source.positions_, 3);
  floatAttribute(1, source.normals_, 3);
  if (source.colours_.id()) {  // attributes 2-5 of mesh.vert's MATERIALS variant
    floatAttribute(2, source.colours_, 3);
    floatAttribute(3, source.texcoords_, 2);
    glBindBuffer(GL_ARRAY_BUFFER, source.materials_.id());
    glEnableVertexAttribArray(4);
    glVertexAttribIPointer(4, 1, GL_UNSIGNED_SHORT, sizeof(std::uint16_t), nullptr);
    floatAttribute(5, source.mapAverages_, 3);
  }
  if (source.directions_.id()) floatAttribute(6, source.directions_, 3);
  if (source.occlusion_.id()) floatAttribute(7, source.occlusion_, 1);
  if (source.restPositions_.id()) {
    floatAttribute(8, source.restPositions_, 3);
    floatAttribute(9, source.restNormals_, 3);
  }
  shared_ = &source == this ? nullptr : &source;
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBindVertexArray(0);
}

void GpuMesh::uploadDirections(const std::vector<glm::vec3>& directions) {
  if (!vao_.id() || directions.size() != vertexCount_) return;
  if (directions_.id()) {  // a posed mesh's field, again: the same buffer
    gl::updateBuffer(directions_, directions.data(), directions.size() * sizeof(glm::vec3));
    return;
  }
  directions_ = staticBuffer(directions.data(), directions.size() * sizeof(glm::vec3));
  glBindVertexArray(vao_.id());
  floatAttribute(6, directions_, 3);
  glBindVertexArray(0);
}

void GpuMesh::uploadOcclusion(const std::vector<float>& occlusion) {
  if (!vao_.id() || occlusion.size() != vertexCount_) return;
  occlusion_ = staticBuffer(occlusion.data(), occlusion.size() * sizeof(float));
  glBindVertexArray(vao_.id());
  floatAttribute(7, occlusion_, 1);
  glBindVertexArray(0);
}

void GpuMesh::drawPoints() const {
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertexCount_));
}

void GpuMesh::uploadAppearance(const Mesh& mesh) {
  const std::size_t nv = mesh.positions.size();
  // The streams of attributes 2-5 (bindStreams); where the mesh lacks one, a neutral array
  // (white, (0,0), material 0) keeps one vertex layout for every mesh with an appearance.
  const std::vector<glm::vec3> white(mesh.colours.size() == nv ? 0 : nv, glm::vec3(1.0f));
  const std::vector<glm::vec3>& colours = mesh.colours.size() == nv ? mesh.colours : white;
  colours_ = staticBuffer(colours.data(), nv * sizeof(glm::vec3));
  const std::vector<glm::vec2> zero(mesh.texcoords.size() == nv ? 0 : nv, glm::vec2(0.0f));
  const std::vector<glm::vec2>& uv = mesh.texcoords.size() == nv ? mesh.texcoords : zero;
  texcoords_ = staticBuffer(uv.data(), nv * sizeof(glm::vec2));
  // Vertices are split per material while loading, so each has one.
  std::vector<std::uint16_t> material(nv, 0);
  if (mesh.faceMaterials.size() == mesh.triangleCount())
    for (std::size_t f = 0; f < mesh.faceMaterials.size(); ++f)
      for (int k = 0; k < 3; ++k) material[mesh.indices[f * 3 + static_cast<std::size_t>(k)]] = mesh.faceMaterials[f];
  materials_ = staticBuffer(material.data(), nv * sizeof(std::uint16_t));
  // The per-vertex paths light each vertex with its diffuse map's average over the faces
  // around it (a per-triangle value would need gl_PrimitiveID, which made llvmpipe about 30%
  // slower on the large mesh).
  std::vector<glm::vec3> mapAverage(nv, glm::vec3(1.0f));
  if (mesh.faceTints.size() == mesh.triangleCount()) {
    std::vector<glm::vec3> sum(nv, glm::vec3(0.0f));
    std::vector<float> count(nv, 0.0f);
    for (std::size_t f = 0; f < mesh.faceTints.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.indices[f * 3 + static_cast<std::size_t>(k)];
        sum[v] += mesh.faceTints[f];
        count[v] += 1.0f;
      }
    for (std::size_t v = 0; v < nv; ++v)
      if (count[v] > 0.0f) mapAverage[v] = sum[v] / count[v];
  }
  mapAverages_ = staticBuffer(mapAverage.data(), nv * sizeof(glm::vec3));
}

void GpuMesh::drawAll() const {
  bindIndices(indices_);
  drawTriangles(0, static_cast<std::uint32_t>(triangleCount_));  // a file of only points and lines has none
}

void GpuMesh::drawRun(const MaterialRun& run) const {
  bindIndices(indices_);
  drawTriangles(run.first, run.count);
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
  // Directions to clip space in one product per vertex (the hatching field, mesh.vert).
  program.set("uModelViewProjection", camera.projection * modelView);
}

}  // namespace npr
