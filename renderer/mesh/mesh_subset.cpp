// Some of a mesh's triangles (see mesh_subset.h).
#include "renderer/mesh/mesh_subset.h"

namespace npr {

MeshFaces meshFaces(const Mesh& m, const std::vector<char>& keep) {
  MeshFaces part;
  Mesh& s = part.faces;
  s.materials = m.materials;  // every one, so face materials stay valid
  s.radius = m.radius;
  s.seeThrough = m.seeThrough;  // as the whole: a part draws through the whole's materials
  s.report = m.report;
  const std::size_t nf = m.triangleCount();
  const bool mats = m.faceMaterials.size() == nf, tints = m.faceTints.size() == nf;
  for (std::size_t f = 0; f < nf && f < keep.size(); ++f) {
    if (!keep[f]) continue;
    part.ofWhole.push_back(static_cast<std::uint32_t>(f));
    s.indices.insert(s.indices.end(), m.indices.begin() + static_cast<std::ptrdiff_t>(f * 3),
                     m.indices.begin() + static_cast<std::ptrdiff_t>(f * 3 + 3));
    s.faceCentroids.push_back(m.faceCentroids[f]);
    s.faceNormals.push_back(m.faceNormals[f]);
    if (mats) s.faceMaterials.push_back(m.faceMaterials[f]);
    if (tints) s.faceTints.push_back(m.faceTints[f]);
  }
  s.report.triangles = s.triangleCount();
  return part;
}

void copyFaceGeometry(const Mesh& whole, MeshFaces& part) {
  Mesh& s = part.faces;
  if (whole.faceCentroids.size() != whole.triangleCount() || whole.faceNormals.size() != whole.triangleCount()) return;
  for (std::size_t f = 0; f < part.ofWhole.size() && f < s.faceCentroids.size(); ++f) {
    s.faceCentroids[f] = whole.faceCentroids[part.ofWhole[f]];
    s.faceNormals[f] = whole.faceNormals[part.ofWhole[f]];
  }
  s.radius = whole.radius;
}

}  // namespace npr
