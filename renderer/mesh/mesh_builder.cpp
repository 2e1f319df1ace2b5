// Mesh building (see mesh_builder.h).
#include "renderer/mesh/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "renderer/mesh/manifold_fans.h"
#include "renderer/mesh/silenced_omerr.h"

namespace npr {

// Adds triangles to the halfedge mesh. OpenMesh asserts (and so aborts the viewer) on a face
// that names one vertex twice or a vertex that does not exist, so those never reach it: they
// are dropped here and counted, whichever reader produced them. Faces it refuses for other
// reasons (complex edges, duplicates, flipped neighbours) are drawn on their own copies of the
// vertices and counted. Triangles that form manifold fans (manifold_fans.h) are refused
// nowhere, so for them the structure is not built: the output is the input, faces in order
// and corners in order (OpenMesh keeps both: a face starts at its first corner).
void buildTriMesh(std::vector<glm::vec3> verts, std::vector<std::array<int, 3>> tris, Mesh& m,
                  std::vector<std::uint32_t>* vertexOrigin, std::vector<std::uint32_t>* faceOrigin) {
  const long nv = static_cast<long>(verts.size());
  std::size_t degenerate = 0, kept = 0;
  if (faceOrigin) faceOrigin->clear();
  for (std::size_t ti = 0; ti < tris.size(); ++ti) {
    const auto& t = tris[ti];
    const bool inRange = t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && t[0] < nv && t[1] < nv && t[2] < nv;
    if (!inRange || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++degenerate;
      continue;
    }
    if (faceOrigin) faceOrigin->push_back(static_cast<std::uint32_t>(ti));
    tris[kept++] = t;
  }
  tris.resize(kept);
  if (vertexOrigin) {
    vertexOrigin->resize(static_cast<std::size_t>(nv));
    for (std::size_t i = 0; i < vertexOrigin->size(); ++i) (*vertexOrigin)[i] = static_cast<std::uint32_t>(i);
  }
  std::size_t refused = 0;
  if (formsManifoldFans(tris, verts.size())) {
    m.positions = std::move(verts);
    m.indices.resize(tris.size() * 3);
    for (std::size_t f = 0; f < tris.size(); ++f)
      for (std::size_t k = 0; k < 3; ++k) m.indices[f * 3 + k] = static_cast<std::uint32_t>(tris[f][k]);
  } else {
    TriMesh mesh;
    mesh.reserve(verts.size(), tris.size() * 3 / 2 + 16, tris.size());
    std::vector<TriMesh::VertexHandle> vh(verts.size());
    for (size_t i = 0; i < verts.size(); ++i) vh[i] = mesh.add_vertex(TriMesh::Point(verts[i].x, verts[i].y, verts[i].z));
    verts = {};
    {
      // OpenMesh prints an error line for each refused face; we count them in the report instead.
      const SilencedOmerr silenced;
      for (const auto& t : tris) {
        const auto fh = mesh.add_face(vh[static_cast<size_t>(t[0])], vh[static_cast<size_t>(t[1])], vh[static_cast<size_t>(t[2])]);
        if (fh.is_valid()) continue;
        ++refused;
        TriMesh::VertexHandle c[3];
        for (int k = 0; k < 3; ++k) {
          const TriMesh::Point p = mesh.point(vh[static_cast<size_t>(t[k])]);  // a copy: add_vertex may reallocate the points
          c[k] = mesh.add_vertex(p);
          if (vertexOrigin) vertexOrigin->push_back(static_cast<std::uint32_t>(t[k]));
        }
        mesh.add_face(c[0], c[1], c[2]);
      }
    }
    tris = {};
    // The arrays the renderer draws: every vertex (copies for refused faces included) and each
    // face's corners in the halfedge structure's order, a cyclic rotation of the file's (the
    // winding is kept).
    const auto* pts = mesh.points();
    m.positions.resize(mesh.n_vertices());
    for (size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = glm::vec3(pts[i][0], pts[i][1], pts[i][2]);
    m.indices.resize(mesh.n_faces() * 3);
    for (auto f : mesh.faces()) {
      auto h = mesh.halfedge_handle(f);
      for (int k = 0; k < 3; ++k) {
        m.indices[static_cast<size_t>(f.idx()) * 3 + static_cast<size_t>(k)] = static_cast<std::uint32_t>(mesh.to_vertex_handle(h).idx());
        h = mesh.next_halfedge_handle(h);
      }
    }
  }
  m.report.non_manifold_faces = refused;
  m.report.degenerate_triangles += degenerate;
  if (degenerate)
    m.report.warnings.push_back(std::to_string(degenerate) +
                                " triangles named one vertex twice (a polygon touching itself, or a vertex that does not exist) and were not drawn");
  if (refused)
    m.report.warnings.push_back(std::to_string(refused) +
                                " faces were refused by the halfedge structure (non-manifold edge, duplicate or "
                                "inconsistently oriented face); they are drawn on copied vertices");
}

// Centres the model on its bounding-box centre and scales it into the unit sphere, in double
// precision, before anything becomes float. Coordinates near the double range (1e308) must not
// overflow: the centre is taken as lo/2 + hi/2, offsets are halved before subtracting, and the
// radius is a length computed relative to the largest component, so every intermediate stays
// finite for any finite input.
std::vector<glm::vec3> normalizePositions(const std::vector<glm::dvec3>& in, const std::vector<char>* valid, LoadReport& report) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (size_t i = 0; i < in.size(); ++i) {
    if (valid && !(*valid)[i]) continue;
    lo = glm::min(lo, in[i]);
    hi = glm::max(hi, in[i]);
  }
  if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);
  const glm::dvec3 halfCentre = lo * 0.25 + hi * 0.25;  // centre / 2
  auto halfOffset = [&](const glm::dvec3& p) { return p * 0.5 - halfCentre; };  // (p - centre) / 2, finite
  auto safeLength = [](const glm::dvec3& d) {
    const double big = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (!(big > 0.0)) return 0.0;
    return big * glm::length(d / big);
  };
  double halfRadius = 0.0;
  for (size_t i = 0; i < in.size(); ++i)
    if (!valid || (*valid)[i]) halfRadius = std::max(halfRadius, safeLength(halfOffset(in[i])));
  // Dividing by the radius (not multiplying by its inverse) keeps tiny models finite too.
  const bool usable = halfRadius > 0.0 && std::isfinite(halfRadius);
  report.original_centre = halfCentre * 2.0;
  report.original_scale = usable ? 0.5 / halfRadius : 1.0;
  std::vector<glm::vec3> out(in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    // Unusable vertices (no face draws them) go to the centre, so they cannot widen the bounds.
    if (valid && !(*valid)[i]) continue;
    const glm::dvec3 d = halfOffset(in[i]);
    out[i] = glm::vec3(usable ? d / halfRadius : d * 2.0);
  }
  return out;
}

}  // namespace npr
