// Mesh building (see mesh_builder.h).
#include "renderer/mesh/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace npr {

// Adds triangles to the halfedge mesh; faces it refuses (complex edges, duplicates, flipped
// neighbours, repeated corners) are drawn on their own copies of the vertices and counted.
void buildTriMesh(const std::vector<glm::vec3>& verts, const std::vector<std::array<int, 3>>& tris, Mesh& m) {
  TriMesh& mesh = m.mesh;
  mesh.reserve(verts.size(), tris.size() * 3 / 2 + 16, tris.size());
  std::vector<TriMesh::VertexHandle> vh(verts.size());
  for (size_t i = 0; i < verts.size(); ++i) vh[i] = mesh.add_vertex(TriMesh::Point(verts[i].x, verts[i].y, verts[i].z));
  std::size_t refused = 0;
  // OpenMesh prints an error line for each refused face; we count them in the report instead.
  auto& errlog = omerr();
  errlog.disable();
  for (const auto& t : tris) {
    const auto fh = mesh.add_face(vh[static_cast<size_t>(t[0])], vh[static_cast<size_t>(t[1])], vh[static_cast<size_t>(t[2])]);
    if (fh.is_valid()) continue;
    ++refused;
    TriMesh::VertexHandle c[3];
    for (int k = 0; k < 3; ++k) {
      const TriMesh::Point p = mesh.point(vh[static_cast<size_t>(t[k])]);  // a copy: add_vertex may reallocate the points
      c[k] = mesh.add_vertex(p);
    }
    mesh.add_face(c[0], c[1], c[2]);
  }
  errlog.enable();
  m.report.non_manifold_faces = refused;
  if (refused)
    m.report.warnings.push_back(std::to_string(refused) +
                                " faces were refused by the halfedge structure (non-manifold edge, duplicate or "
                                "inconsistently oriented face); they are drawn on copied vertices");
}

// Centres the model on its bounding-box centre and scales it into the unit sphere, in double
// precision, before anything becomes float.
std::vector<glm::vec3> normalizePositions(const std::vector<glm::dvec3>& in, const std::vector<char>* valid, LoadReport& report) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (size_t i = 0; i < in.size(); ++i) {
    if (valid && !(*valid)[i]) continue;
    lo = glm::min(lo, in[i]);
    hi = glm::max(hi, in[i]);
  }
  if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);
  const glm::dvec3 centre = (lo + hi) * 0.5;
  double radius = 0.0;
  for (size_t i = 0; i < in.size(); ++i)
    if (!valid || (*valid)[i]) radius = std::max(radius, glm::length(in[i] - centre));
  const double scale = radius > 0.0 && std::isfinite(1.0 / radius) ? 1.0 / radius : 1.0;
  report.original_centre = centre;
  report.original_scale = scale;
  std::vector<glm::vec3> out(in.size());
  for (size_t i = 0; i < in.size(); ++i) out[i] = glm::vec3((in[i] - centre) * scale);
  return out;
}

}  // namespace npr
