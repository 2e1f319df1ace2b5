// Mesh subsets (see mesh_subset.h).
#include "renderer/mesh/mesh_subset.h"

namespace npr {

Mesh meshSubset(const Mesh& m, const std::vector<char>& keep) {
  Mesh s;
  s.positions = m.positions;
  s.normals = m.normals;
  s.colours = m.colours;
  s.texcoords = m.texcoords;
  s.sourceVertex = m.sourceVertex;
  s.materials = m.materials;  // every one, so face materials stay valid; the maps are not copied:
                              // a part draws through the whole's (Model::Part)
  s.radius = m.radius;
  s.seeThrough = m.seeThrough;  // as the whole: a part draws through the whole's materials
  s.report = m.report;
  const std::size_t nf = m.triangleCount();
  const bool mats = m.faceMaterials.size() == nf, tints = m.faceTints.size() == nf;
  for (std::size_t f = 0; f < nf && f < keep.size(); ++f) {
    if (!keep[f]) continue;
    s.indices.insert(s.indices.end(), m.indices.begin() + static_cast<std::ptrdiff_t>(f * 3),
                     m.indices.begin() + static_cast<std::ptrdiff_t>(f * 3 + 3));
    s.faceCentroids.push_back(m.faceCentroids[f]);
    s.faceNormals.push_back(m.faceNormals[f]);
    if (mats) s.faceMaterials.push_back(m.faceMaterials[f]);
    if (tints) s.faceTints.push_back(m.faceTints[f]);
  }
  s.report.triangles = s.triangleCount();
  return s;
}

}  // namespace npr
