// Derives the flat GPU/lighting arrays and the normals of a Mesh from its OpenMesh TriMesh.
#include "renderer/mesh/mesh.h"

#include <cmath>

namespace npr {

void finalizeMesh(Mesh& m) {
  TriMesh& mesh = *m.mesh;
  const size_t nv = mesh.n_vertices(), nf = mesh.n_faces();
  const auto* pts = mesh.points();
  m.positions.resize(nv);
  float r2 = 0.0f;
  for (size_t i = 0; i < nv; ++i) {
    m.positions[i] = glm::vec3(pts[i][0], pts[i][1], pts[i][2]);
    r2 = std::max(r2, glm::dot(m.positions[i], m.positions[i]));
  }
  m.radius = r2 > 0.0f ? std::sqrt(r2) : 1.0f;

  m.indices.resize(nf * 3);
  m.faceCentroids.resize(nf);
  m.faceNormals.resize(nf);
  std::vector<glm::dvec3> accum(nv, glm::dvec3(0.0));
  for (auto f : mesh.faces()) {
    const size_t fi = static_cast<size_t>(f.idx());
    auto h = mesh.halfedge_handle(f);
    std::uint32_t id[3];
    for (int k = 0; k < 3; ++k) {
      id[k] = static_cast<std::uint32_t>(mesh.to_vertex_handle(h).idx());
      h = mesh.next_halfedge_handle(h);
    }
    // A cyclic rotation of the file's corner order: the winding is kept.
    for (int k = 0; k < 3; ++k) m.indices[fi * 3 + k] = id[k];
    const glm::vec3 a = m.positions[id[0]], b = m.positions[id[1]], c = m.positions[id[2]];
    const glm::dvec3 cr = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));  // length = 2 x area
    const double len = glm::length(cr);
    m.faceCentroids[fi] = (a + b + c) / 3.0f;
    m.faceNormals[fi] = len > 0.0 && std::isfinite(len) ? glm::vec3(cr / len) : glm::vec3(0.0f);
    for (std::uint32_t v : id) accum[v] += cr;  // area weighting
  }
  m.normals.resize(nv);
  for (size_t i = 0; i < nv; ++i) {
    const double len = glm::length(accum[i]);
    // Vertices touching only zero-area faces (or none) get +Z: finite, and harmless to light.
    m.normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(accum[i] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
  mesh.request_face_normals();
  mesh.request_vertex_normals();
  for (auto f : mesh.faces()) {
    const glm::vec3& n = m.faceNormals[static_cast<size_t>(f.idx())];
    mesh.set_normal(f, TriMesh::Normal(n.x, n.y, n.z));
  }
  for (auto v : mesh.vertices()) {
    const glm::vec3& n = m.normals[static_cast<size_t>(v.idx())];
    mesh.set_normal(v, TriMesh::Normal(n.x, n.y, n.z));
  }
  m.report.vertices = nv;
  m.report.triangles = nf;
}

}  // namespace npr
