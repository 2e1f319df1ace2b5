// Feature line extraction (see feature_edges.h).
#include "renderer/lines/feature_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "renderer/core/parallel.h"
#include "renderer/mesh/manifold_fans.h"
#include "renderer/mesh/silenced_omerr.h"
#include "renderer/mesh/weld.h"
#include "renderer/orientation/principal_curvature.h"

namespace npr {
namespace {

struct FaceKey {
  std::uint32_t a, b, c;  // sorted
  bool operator==(const FaceKey& o) const { return a == o.a && b == o.b && c == o.c; }
};
struct FaceHash {
  size_t operator()(const FaceKey& k) const {
    return (size_t(k.a) * 0x9E3779B97F4A7C15ull) ^ (size_t(k.b) * 0xC2B2AE3D27D4EB4Full) ^ (size_t(k.c) * 0x165667B19E3779F9ull);
  }
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

}  // namespace

FeatureEdges::FeatureEdges(const Mesh& m, Topology topology) {
  WeldedPositions weld = weldPositions(m.positions);
  positions_ = std::move(weld.positions);
  remap_ = std::move(weld.remap);
  const std::vector<std::uint32_t>& remap = remap_;
  // The welded faces, doubled and degenerate ones dropped.
  std::vector<std::array<int, 3>> faces;
  std::vector<std::uint16_t> materialOf;
  faces.reserve(m.triangleCount());
  {
    std::unordered_set<FaceKey, FaceHash> seen;
    seen.reserve(m.triangleCount());
    const bool materials = m.faceMaterials.size() == m.triangleCount();
    for (size_t t = 0; t < m.triangleCount(); ++t) {
      std::array<std::uint32_t, 3> f = {remap[m.indices[t * 3]], remap[m.indices[t * 3 + 1]], remap[m.indices[t * 3 + 2]]};
      if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
      std::array<std::uint32_t, 3> s = f;
      std::sort(s.begin(), s.end());
      if (!seen.insert(FaceKey{s[0], s[1], s[2]}).second) {
        ++duplicateFaces_;
        continue;
      }
      faces.push_back({int(f[0]), int(f[1]), int(f[2])});
      if (materials) materialOf.push_back(m.faceMaterials[t]);
    }
  }
  if (topology == Topology::Auto && formsManifoldFans(faces, positions_.size())) pairEdges(faces, materialOf);
  else buildHalfedges(faces, materialOf);
  updatePlanes();
}

// An oriented manifold: every face is taken, and each edge is made by the first face that has
// it, running as that face runs (OpenMesh's order and orientation, so the lines come out the
// same); its second face, if any, runs it the other way.
void FeatureEdges::pairEdges(const std::vector<std::array<int, 3>>& faces, std::vector<std::uint16_t>& materialOf) {
  faceMaterial_ = std::move(materialOf);
  faceVertices_.resize(3 * faces.size());
  struct Edge {
    std::uint32_t from, to, face0, face1;
  };
  std::vector<Edge> edges;
  edges.reserve(faces.size() * 3 / 2 + 1);
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  index.reserve(faces.size() * 3 / 2 + 1);
  for (size_t f = 0; f < faces.size(); ++f)
    for (size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = std::uint32_t(faces[f][k]), b = std::uint32_t(faces[f][(k + 1) % 3]);
      faceVertices_[3 * f + k] = a;
      const auto [it, made] = index.try_emplace(edgeKey(a, b), std::uint32_t(edges.size()));
      if (made) edges.push_back({a, b, std::uint32_t(f), kNoFace});
      else edges[it->second].face1 = std::uint32_t(f);
    }
  for (const Edge& e : edges) {
    if (e.face1 == kNoFace) {
      boundary_.insert(boundary_.end(), {e.from, e.to});
      boundaryFace_.push_back(e.face0);
      continue;
    }
    manifoldEnds_.insert(manifoldEnds_.end(), {e.from, e.to});
    manifoldFaces_.insert(manifoldFaces_.end(), {e.face0, e.face1});
  }
}

// Anything else: OpenMesh's halfedge structure takes the faces in order and refuses those that
// would make an edge or a vertex non-manifold; their edges become junctions.
void FeatureEdges::buildHalfedges(const std::vector<std::array<int, 3>>& faces, const std::vector<std::uint16_t>& materialOf) {
  TriMesh welded;
  welded.reserve(positions_.size(), faces.size() * 3 / 2, faces.size());
  std::vector<TriMesh::VertexHandle> vh(positions_.size());
  for (size_t i = 0; i < positions_.size(); ++i) vh[i] = welded.add_vertex(TriMesh::Point(positions_[i].x, positions_[i].y, positions_[i].z));
  std::vector<std::array<std::uint32_t, 3>> refused;
  {
    const SilencedOmerr silenced;
    for (size_t t = 0; t < faces.size(); ++t) {
      const std::array<std::uint32_t, 3> f = {std::uint32_t(faces[t][0]), std::uint32_t(faces[t][1]), std::uint32_t(faces[t][2])};
      if (!welded.add_face(vh[f[0]], vh[f[1]], vh[f[2]]).is_valid()) refused.push_back(f);
      else if (!materialOf.empty()) faceMaterial_.push_back(materialOf[t]);
    }
  }

  faceVertices_.resize(3 * welded.n_faces());
  for (auto fh : welded.faces()) {
    int k = 0;
    for (auto fv : welded.fv_range(fh)) faceVertices_[3 * size_t(fh.idx()) + size_t(k++)] = std::uint32_t(fv.idx());
  }
  std::unordered_set<std::uint64_t> junction;
  for (const auto& f : refused)
    for (int k = 0; k < 3; ++k) junction.insert(edgeKey(f[size_t(k)], f[size_t((k + 1) % 3)]));
  for (auto e : welded.edges()) {
    const auto h0 = welded.halfedge_handle(e, 0);
    const std::uint32_t v0 = std::uint32_t(welded.from_vertex_handle(h0).idx()), v1 = std::uint32_t(welded.to_vertex_handle(h0).idx());
    const auto f0 = welded.face_handle(h0), f1 = welded.face_handle(welded.halfedge_handle(e, 1));
    const std::uint32_t face = f0.is_valid() ? std::uint32_t(f0.idx()) : f1.is_valid() ? std::uint32_t(f1.idx()) : kNoFace;
    if (junction.erase(edgeKey(v0, v1))) {
      boundary_.insert(boundary_.end(), {v0, v1});
      boundaryFace_.push_back(face);
      ++junctionCount_;
      if (!f0.is_valid() || !f1.is_valid()) continue;
    } else if (!f0.is_valid() || !f1.is_valid()) {
      boundary_.insert(boundary_.end(), {v0, v1});
      boundaryFace_.push_back(face);
      continue;
    }
    manifoldEnds_.insert(manifoldEnds_.end(), {v0, v1});
    manifoldFaces_.insert(manifoldFaces_.end(), {std::uint32_t(f0.idx()), std::uint32_t(f1.idx())});
  }
  // Edges of refused faces that the welded mesh does not have at all.
  for (std::uint64_t k : junction) {
    boundary_.insert(boundary_.end(), {std::uint32_t(k >> 32), std::uint32_t(k & 0xFFFFFFFFu)});
    boundaryFace_.push_back(kNoFace);
    ++junctionCount_;
  }
}


glm::u16vec2 FeatureEdges::materialsOf(std::uint32_t f0, std::uint32_t f1) const {
  const auto of = [&](std::uint32_t f) { return f < faceMaterial_.size() ? faceMaterial_[f] : kNoMaterial; };
  return {of(f0), of(f1)};
}

void FeatureEdges::updatePlanes() {
  const size_t nf = faceVertices_.size() / 3;
  faceNormals_.resize(nf);
  facePlanes_.resize(nf);
  parallelChunks(nf, workerCount(), [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) {
      const glm::vec3 a = positions_[faceVertices_[3 * f]], bb = positions_[faceVertices_[3 * f + 1]], c = positions_[faceVertices_[3 * f + 2]];
      const glm::vec3 cr = glm::cross(bb - a, c - a);
      const float len = glm::length(cr);
      const glm::vec3 n = len > 0.0f && std::isfinite(len) ? cr / len : glm::vec3(0.0f);
      faceNormals_[f] = n;
      facePlanes_[f] = glm::vec4(n, -glm::dot(n, (a + bb + c) / 3.0f));
    }
  });
}

void FeatureEdges::updatePositions(const Mesh& mesh) {
  if (mesh.positions.size() != remap_.size()) return;
  for (size_t i = 0; i < remap_.size(); ++i) positions_[remap_[i]] = mesh.positions[i];
  updatePlanes();
  creaseAngle_ = -1.0f;  // the static lines' ends moved
}

void FeatureEdges::estimateCurvature(const Mesh& mesh) {
  if (!curvature_.empty() || mesh.positions.size() != remap_.size()) return;
  const PrincipalCurvatures pc = estimatePrincipalCurvatures(mesh);
  curvature_.assign(positions_.size(), 0.0f);
  for (std::size_t v = 0; v < remap_.size(); ++v) {
    const std::uint32_t w = pc.weld.remap[v];
    curvature_[remap_[v]] = std::max(std::fabs(pc.kMax[w]), std::fabs(pc.kMin[w])) * mesh.radius;
  }
  std::vector<float> sorted(curvature_);
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  medianCurvature_ = sorted.empty() ? 1.0f : std::max(sorted[sorted.size() / 2], 1e-3f);
  creaseAngle_ = -1.0f;  // the static lines found again, with it
}

const std::vector<FeatureLine>& FeatureEdges::staticLines(float creaseAngleDegrees) {
  if (creaseAngleDegrees == creaseAngle_) return static_;
  creaseAngle_ = creaseAngleDegrees;
  static_.clear();
  const float cosLimit = std::cos(glm::radians(std::clamp(creaseAngleDegrees, 0.0f, 180.0f)));
  for (size_t e = 0; e < manifoldFaces_.size() / 2; ++e) {
    const glm::vec3& n0 = faceNormals_[manifoldFaces_[e * 2]];
    const glm::vec3& n1 = faceNormals_[manifoldFaces_[e * 2 + 1]];
    if (n0 == glm::vec3(0.0f) || n1 == glm::vec3(0.0f)) continue;
    // The dihedral angle between the faces is the angle between their normals.
    if (glm::dot(n0, n1) < cosLimit)
      static_.push_back(line(manifoldEnds_[e * 2], manifoldEnds_[e * 2 + 1], EdgeKind::Crease, materialsOf(manifoldFaces_[e * 2], manifoldFaces_[e * 2 + 1]), n0 + n1));
  }
  for (size_t e = 0; e < boundary_.size() / 2; ++e)
    static_.push_back(line(boundary_[e * 2], boundary_[e * 2 + 1], EdgeKind::Boundary, materialsOf(boundaryFace_[e], boundaryFace_[e]), normalOf(boundaryFace_[e])));
  if (faceMaterial_.size() == faceNormals_.size())
    for (size_t e = 0; e < manifoldFaces_.size() / 2; ++e)
      if (faceMaterial_[manifoldFaces_[e * 2]] != faceMaterial_[manifoldFaces_[e * 2 + 1]])
        static_.push_back(line(manifoldEnds_[e * 2], manifoldEnds_[e * 2 + 1], EdgeKind::Material, materialsOf(manifoldFaces_[e * 2], manifoldFaces_[e * 2 + 1]),
                               normalOf(manifoldFaces_[e * 2]) + normalOf(manifoldFaces_[e * 2 + 1])));
  return static_;
}

const std::vector<FeatureLine>& FeatureEdges::silhouettes(const glm::vec3& eye) {
  const size_t nf = facePlanes_.size(), ne = manifoldFaces_.size() / 2;
  facing_.resize(nf);
  const int chunks = workerCount();
  parallelChunks(nf, chunks, [&](size_t b, size_t e, int) {
    for (size_t f = b; f < e; ++f) facing_[f] = glm::dot(glm::vec3(facePlanes_[f]), eye) + facePlanes_[f].w > 0.0f;
  });
  std::vector<std::vector<FeatureLine>> parts(static_cast<size_t>(chunks));
  parallelChunks(ne, chunks, [&](size_t b, size_t e, int c) {
    auto& out = parts[static_cast<size_t>(c)];
    for (size_t i = b; i < e; ++i)
      if (facing_[manifoldFaces_[i * 2]] != facing_[manifoldFaces_[i * 2 + 1]]) {
        const std::uint32_t front = facing_[manifoldFaces_[i * 2]] ? manifoldFaces_[i * 2] : manifoldFaces_[i * 2 + 1];
        const std::uint32_t back = front == manifoldFaces_[i * 2] ? manifoldFaces_[i * 2 + 1] : manifoldFaces_[i * 2];
        out.push_back(line(manifoldEnds_[i * 2], manifoldEnds_[i * 2 + 1], EdgeKind::Silhouette, materialsOf(front, back), normalOf(front)));
      }
  });
  silhouettes_.clear();
  for (auto& p : parts) silhouettes_.insert(silhouettes_.end(), p.begin(), p.end());
  return silhouettes_;
}

}  // namespace npr
