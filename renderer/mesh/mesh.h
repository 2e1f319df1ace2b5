// The mesh as the renderer sees it: flat arrays ready for the GPU and for per-triangle
// lighting, and the load report. OpenMesh's halfedge structure is built while loading (it
// decides which faces must be drawn on copied vertices, mesh_builder.h) and by the feature
// lines on a welded copy, but not kept: nothing draws from it, it held a third of a large
// mesh's memory, and without it a Mesh is plain arrays that move cheaply and cache to disk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <glm/glm.hpp>

namespace npr {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct LoadReport {
  std::string file;
  std::size_t vertices = 0;
  std::size_t triangles = 0;              // every triangle that will be drawn
  std::size_t polygons_triangulated = 0;  // faces with more than 3 corners
  std::size_t skipped_faces = 0;          // faces that could not be drawn at all
  std::size_t repeated_corner_faces = 0;  // faces that named a vertex twice in a row; drawn without the repeat
  std::size_t degenerate_triangles = 0;   // triangles (of faces or their triangulation) naming one vertex twice: not drawn
  std::size_t non_manifold_faces = 0;     // refused by the halfedge structure, drawn on copied vertices
  std::vector<std::string> warnings;
  double load_ms = 0.0;
  bool from_cache = false;          // read from the mesh cache (mesh_cache.h), not parsed
  glm::dvec3 original_centre{0.0};  // the model was translated by -centre ...
  double original_scale = 1.0;      // ... then scaled by this to fit a unit sphere
  std::string toJson() const;
};

struct Mesh {
  // Structure of arrays, for upload and for cache-friendly per-triangle work.
  std::vector<glm::vec3> positions;       // per vertex, centred and scaled
  std::vector<glm::vec3> normals;         // per vertex, unit length (never NaN)
  std::vector<std::uint32_t> indices;     // 3 per triangle, counter-clockwise
  std::vector<glm::vec3> faceCentroids;   // per triangle
  std::vector<glm::vec3> faceNormals;     // per triangle; zero for zero-area triangles
  float radius = 1.0f;                    // bounding sphere radius about the origin
  LoadReport report;

  std::size_t triangleCount() const { return indices.size() / 3; }
};

// Fills the radius, centroids and normals from `positions` and `indices` (used by the loader
// and by meshes built in code, e.g. the benchmark's generated icosphere).
void finalizeMesh(Mesh& m);

}  // namespace npr
