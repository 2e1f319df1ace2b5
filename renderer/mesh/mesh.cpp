// Derives the radius, centroids and normals of a Mesh from its positions and indices.
#include "renderer/mesh/mesh.h"

#include <cmath>

namespace npr {

void finalizeMesh(Mesh& m) {
  const size_t nv = m.positions.size(), nf = m.indices.size() / 3;
  float r2 = 0.0f;
  for (const glm::vec3& p : m.positions) r2 = std::max(r2, glm::dot(p, p));
  m.radius = r2 > 0.0f ? std::sqrt(r2) : 1.0f;
  m.faceCentroids.resize(nf);
  m.faceNormals.resize(nf);
  std::vector<glm::dvec3> accum(nv, glm::dvec3(0.0));
  for (size_t fi = 0; fi < nf; ++fi) {
    const std::uint32_t* id = &m.indices[fi * 3];
    const glm::vec3 a = m.positions[id[0]], b = m.positions[id[1]], c = m.positions[id[2]];
    const glm::dvec3 cr = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));  // length = 2 x area
    const double len = glm::length(cr);
    m.faceCentroids[fi] = (a + b + c) / 3.0f;
    m.faceNormals[fi] = len > 0.0 && std::isfinite(len) ? glm::vec3(cr / len) : glm::vec3(0.0f);
    for (int k = 0; k < 3; ++k) accum[id[k]] += cr;  // area weighting
  }
  m.normals.resize(nv);
  for (size_t i = 0; i < nv; ++i) {
    const double len = glm::length(accum[i]);
    // Vertices touching only zero-area faces (or none) get +Z: finite, and harmless to light.
    m.normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(accum[i] / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
  m.report.vertices = nv;
  m.report.triangles = nf;
}

}  // namespace npr
