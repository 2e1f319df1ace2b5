// Object-space feature lines from OpenMesh's halfedge adjacency: silhouettes (one adjacent
// face towards the eye, the other away; recomputed when the view changes), creases (dihedral
// angle above a threshold) and boundaries (one adjacent face).
//
// Files are often polygon soups, so adjacency is built on a welded copy: vertices at the same
// position are merged (seams in the file then join, and never draw creases), doubled faces are
// dropped, and faces the halfedge structure still refuses (an edge shared by more than two
// faces, or a neighbour with the opposite winding) are kept aside: their edges are "junctions",
// drawn with the boundaries, since a surface there is not a simple sheet.
#pragma once

#include "renderer/programs/shader_limits.h"

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

// Intersections are the scene's, not one mesh's (lines/intersection_lines.h).
// Suggestive contours are view-dependent curves across faces (lines/suggestive_contours.h).
enum class EdgeKind : std::uint8_t { Silhouette = 0, Crease = 1, Boundary = 2, Material = 3, Intersection = 4, Suggestive = 5 };
inline constexpr int kEdgeKinds = gl::kEdgeKinds;

// A line's faces' materials (Mesh::materials) where it has them: line sets select by them.
inline constexpr std::uint16_t kNoMaterial = 0xFFFF;

// What a line carries besides its ends: one value per segment (or per end), kept with the
// segment when lines are chained (line_chains.h) and streamed to lines.vert as it is laid out
// here (line_pass.cpp's kLineStreams). A new per-line value is a field here, set where lines are
// found, a row in kLineStreams and an input in lines.vert.
struct LineAttributes {
  // The materials of the faces on either side (a silhouette's front face first; a boundary's
  // one face twice); kNoMaterial where the mesh has none or the line is not on a face's edge
  // (suggestive contours, intersections).
  glm::u16vec2 materials{kNoMaterial, kNoMaterial};
  // The surface's curvature at a and b: the larger principal curvature's magnitude, times the
  // mesh's radius (1 on a sphere the size of the model); 0 where not estimated (only lines of
  // meshes whose FeatureEdges estimated it carry it, for line sets' curvature=GAIN).
  glm::vec2 curvature{0.0f};
  // How much of the line's ink it draws (0..1): suggestive contours fade in from their
  // threshold (suggestive_contours.h), so they do not pop as the view turns; 1 for the others.
  float ink = 1.0f;
  // The surface's normal there (the front face's for a silhouette, the two faces' mean for a
  // crease; zero where unknown): what a line set with colour=tone is lit with.
  glm::vec3 normal{0.0f};
};

struct FeatureLine {
  glm::vec3 a, b;
  float kind;  // EdgeKind
  LineAttributes attributes = {};
};

class FeatureEdges {
 public:
  // How the adjacency is found. Auto: an oriented manifold (manifold_fans.h) is paired by a hash
  // of its edges, in the order and orientation the halfedge structure would give; anything
  // else goes through OpenMesh, which decides which faces a non-manifold mesh refuses.
  // Halfedges: always OpenMesh (what tests hold Auto to).
  enum class Topology { Auto, Halfedges };
  explicit FeatureEdges(const Mesh& mesh, Topology topology = Topology::Auto);
  // `mesh` (the one built from, deformed since: same vertices and faces) moved: positions and
  // face planes follow; the edges, their adjacency and kinds stay.
  void updatePositions(const Mesh& mesh);

  // Creases, then boundaries, then material boundaries (interior edges between faces of
  // different materials): computed once per mesh (and when the threshold changes).
  const std::vector<FeatureLine>& staticLines(float creaseAngleDegrees);
  // Silhouettes seen from `eye` (object space), recomputed in parallel over faces and edges.
  const std::vector<FeatureLine>& silhouettes(const glm::vec3& eye);

  // Estimates the surface's curvature at each vertex (orientation/principal_curvature.h), once:
  // the lines found afterwards carry it (FeatureLine::curvature). `mesh` is the one built from.
  void estimateCurvature(const Mesh& mesh);
  bool hasCurvature() const { return !curvature_.empty(); }
  // The median over the vertices (a line set's curvature=GAIN widens lines where the surface
  // is more curved than that); 1 before estimateCurvature.
  float medianCurvature() const { return medianCurvature_; }

  std::size_t weldedVertices() const { return positions_.size(); }
  std::size_t manifoldEdges() const { return manifoldFaces_.size() / 2; }
  std::size_t duplicateFaces() const { return duplicateFaces_; }
  std::size_t junctionEdges() const { return junctionCount_; }

 private:
  void updatePlanes();  // face normals and planes from positions_
  void pairEdges(const std::vector<std::array<int, 3>>& faces, std::vector<std::uint16_t>& materialOf);
  void buildHalfedges(const std::vector<std::array<int, 3>>& faces, const std::vector<std::uint16_t>& materialOf);

  std::vector<glm::vec3> positions_;       // welded
  std::vector<std::uint32_t> remap_;       // mesh vertex -> welded
  std::vector<std::uint32_t> faceVertices_;  // 3 welded vertices per welded face
  std::vector<std::uint16_t> faceMaterial_;  // per welded face (empty: the mesh has one material)
  std::vector<glm::vec3> faceNormals_;     // per welded face
  std::vector<glm::vec4> facePlanes_;      // normal, -dot(normal, centroid)
  std::vector<std::uint32_t> manifoldEnds_;   // 2 welded vertices per interior edge
  std::vector<std::uint32_t> manifoldFaces_;  // its 2 faces
  std::vector<std::uint32_t> boundary_;       // 2 welded vertices per boundary or junction edge
  std::vector<std::uint32_t> boundaryFace_;   // its one face (kNoFace: a refused face's edge)
  static constexpr std::uint32_t kNoFace = 0xFFFFFFFFu;
  glm::u16vec2 materialsOf(std::uint32_t f0, std::uint32_t f1) const;
  std::size_t duplicateFaces_ = 0, junctionCount_ = 0;
  float creaseAngle_ = -1.0f;
  std::vector<FeatureLine> static_, silhouettes_;
  std::vector<float> curvature_;  // per welded vertex (empty: not estimated)
  float medianCurvature_ = 1.0f;
  FeatureLine line(std::uint32_t v0, std::uint32_t v1, EdgeKind kind, glm::u16vec2 materials, const glm::vec3& normal) const {
    FeatureLine l{positions_[v0], positions_[v1], float(kind), {materials}};
    if (!curvature_.empty()) l.attributes.curvature = {curvature_[v0], curvature_[v1]};
    const float n = glm::length(normal);
    if (n > 0.0f) l.attributes.normal = normal / n;
    return l;
  }
  glm::vec3 normalOf(std::uint32_t face) const { return face < faceNormals_.size() ? faceNormals_[face] : glm::vec3(0.0f); }
  std::vector<std::uint8_t> facing_;
};

}  // namespace npr
