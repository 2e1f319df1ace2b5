// Derives the radius, centroids, normals and texture averages of a Mesh from its arrays.
#include "renderer/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "renderer/core/parallel.h"
#include "renderer/mesh/texture_average.h"

namespace npr {

bool seeThrough(const Mesh& m) {
  for (const MeshMaterial& mat : m.materials) {
    if (mat.alpha == MeshMaterial::Alpha::Opaque) continue;
    // The least alpha the material reaches: the opacity, times its map's least alpha.
    float least = mat.opacity;
    if (mat.diffuseMap >= 0 && static_cast<std::size_t>(mat.diffuseMap) < m.textures.size()) {
      const std::vector<std::uint8_t>& px = m.textures[static_cast<std::size_t>(mat.diffuseMap)].image.pixels;
      std::uint8_t a = 255;
      for (std::size_t i = 3; i < px.size() && a > 0; i += 4) a = std::min(a, px[i]);
      least *= static_cast<float>(a) / 255.0f;
    }
    if (mat.alpha == MeshMaterial::Alpha::Mask ? least < mat.alphaCutoff : least < 1.0f) return true;
  }
  return false;
}

void computeFaceTints(Mesh& m) {
  m.faceTints.clear();
  const size_t nf = m.indices.size() / 3;
  bool textured = false;
  for (const MeshMaterial& mat : m.materials) textured |= mat.diffuseMap >= 0;
  if (!textured || m.texcoords.size() != m.positions.size() || m.faceMaterials.size() != nf) return;
  // Per map, an averager for opaque materials and one weighted by alpha for see-through ones,
  // each made only when some material needs it.
  std::vector<std::unique_ptr<TextureAverager>> maps[2] = {std::vector<std::unique_ptr<TextureAverager>>(m.textures.size()),
                                                           std::vector<std::unique_ptr<TextureAverager>>(m.textures.size())};
  m.faceTints.assign(nf, glm::vec3(1.0f));
  for (size_t f = 0; f < nf; ++f) {
    const std::uint16_t mi = m.faceMaterials[f];
    if (mi >= m.materials.size()) continue;
    const int map = m.materials[mi].diffuseMap;
    if (map < 0 || static_cast<size_t>(map) >= m.textures.size()) continue;
    const bool weighted = m.materials[mi].alpha != MeshMaterial::Alpha::Opaque;
    std::unique_ptr<TextureAverager>& averager = maps[weighted ? 1 : 0][static_cast<size_t>(map)];
    if (!averager) averager = std::make_unique<TextureAverager>(m.textures[static_cast<size_t>(map)].image, weighted);
    const std::uint32_t* id = &m.indices[f * 3];
    m.faceTints[f] = averager->average(m.texcoords[id[0]], m.texcoords[id[1]], m.texcoords[id[2]]);
  }
}

bool closedSurface(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
                   const std::vector<std::uint32_t>& sourceVertex) {
  const std::size_t nf = indices.size() / 3;
  if (nf == 0) return false;
  const bool split = sourceVertex.size() == positions.size();
  auto slot = [&](std::uint32_t v) -> std::uint32_t { return split ? sourceVertex[v] : v; };
  std::size_t slots = positions.size();
  if (split)
    for (std::uint32_t s : sourceVertex) slots = std::max<std::size_t>(slots, std::size_t(s) + 1);
  // The directed edges grouped by the vertex they leave (counting sort: linear, where sorting
  // all edges cost the 871K mesh 215 ms, most of its load). Closed and consistently wound: each
  // directed edge once, and its reverse once.
  std::vector<std::uint32_t> first(slots + 1, 0);
  double volume = 0.0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t* id = &indices[f * 3];
    for (int k = 0; k < 3; ++k) {
      if (slot(id[k]) == slot(id[(k + 1) % 3])) return false;  // a degenerate triangle: no orientation to trust
      ++first[slot(id[k]) + 1];
    }
    const glm::dvec3 p0 = positions[id[0]], p1 = positions[id[1]], p2 = positions[id[2]];
    volume += glm::dot(p0, glm::cross(p1, p2));
  }
  if (!(volume > 0.0) || !std::isfinite(volume)) return false;
  for (std::size_t v = 0; v < slots; ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> to(nf * 3), next(first.begin(), first.end() - 1);
  for (std::size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) to[next[slot(indices[f * 3 + std::size_t(k)])]++] = slot(indices[f * 3 + std::size_t((k + 1) % 3)]);
  for (std::size_t v = 0; v < slots; ++v) {
    const auto b = to.begin() + first[v], e = to.begin() + first[v + 1];
    std::sort(b, e);
    if (std::adjacent_find(b, e) != e) return false;
  }
  for (std::size_t a = 0; a < slots; ++a)
    for (std::uint32_t i = first[a]; i < first[a + 1]; ++i) {
      const std::uint32_t b = to[i];
      if (!std::binary_search(to.begin() + first[b], to.begin() + first[b + 1], std::uint32_t(a))) return false;
    }
  return true;
}

void updateFaceGeometry(Mesh& m) {
  const std::size_t nf = m.triangleCount();
  m.faceCentroids.resize(nf);
  m.faceNormals.resize(nf);
  parallelChunks(nf, workerCount(), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t f = b; f < e; ++f) {
      const std::uint32_t* id = &m.indices[3 * f];
      const glm::vec3 a = m.positions[id[0]], bb = m.positions[id[1]], c = m.positions[id[2]];
      const glm::vec3 cr = glm::cross(bb - a, c - a);
      const float len = glm::length(cr);
      m.faceCentroids[f] = (a + bb + c) / 3.0f;
      m.faceNormals[f] = len > 0.0f && std::isfinite(len) ? cr / len : glm::vec3(0.0f);
    }
  });
}

void finalizeMesh(Mesh& m) {
  const size_t nv = m.positions.size(), nf = m.indices.size() / 3;
  float r2 = 0.0f;
  for (const glm::vec3& p : m.positions) r2 = std::max(r2, glm::dot(p, p));
  for (const std::vector<glm::vec3>* marks : {&m.dots, &m.segments})  // a file's points and lines are drawn too
    for (const glm::vec3& p : *marks) r2 = std::max(r2, glm::dot(p, p));
  m.radius = r2 > 0.0f ? std::sqrt(r2) : 1.0f;
  m.faceCentroids.resize(nf);
  m.faceNormals.resize(nf);
  // Vertices split for texture coordinates or materials share one normal: accumulate on the
  // file's vertex.
  const bool split = m.sourceVertex.size() == nv;
  auto slot = [&](std::uint32_t v) -> std::size_t { return split ? m.sourceVertex[v] : v; };
  std::size_t slots = nv;
  if (split) {
    slots = 0;
    for (std::uint32_t s : m.sourceVertex) slots = std::max<std::size_t>(slots, std::size_t(s) + 1);
  }
  std::vector<glm::dvec3> accum(slots, glm::dvec3(0.0));
  for (size_t fi = 0; fi < nf; ++fi) {
    const std::uint32_t* id = &m.indices[fi * 3];
    const glm::vec3 a = m.positions[id[0]], b = m.positions[id[1]], c = m.positions[id[2]];
    const glm::dvec3 cr = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));  // length = 2 x area
    const double len = glm::length(cr);
    m.faceCentroids[fi] = (a + b + c) / 3.0f;
    m.faceNormals[fi] = len > 0.0 && std::isfinite(len) ? glm::vec3(cr / len) : glm::vec3(0.0f);
    for (int k = 0; k < 3; ++k) accum[slot(id[k])] += cr;  // area weighting
  }
  m.normals.resize(nv);
  for (size_t i = 0; i < nv; ++i) {
    const glm::dvec3& a = accum[slot(static_cast<std::uint32_t>(i))];
    const double len = glm::length(a);
    // Vertices touching only zero-area faces (or none) get +Z: finite, and harmless to light.
    m.normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(a / len) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
  m.closed = closedSurface(m.positions, m.indices, m.sourceVertex);
  computeFaceTints(m);
  m.seeThrough = seeThrough(m);
  m.report.vertices = nv;
  m.report.triangles = nf;
}

}  // namespace npr
