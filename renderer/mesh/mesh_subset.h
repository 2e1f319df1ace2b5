// Some of a mesh's triangles, for drawing parts of a model with different palettes
// (per-material palettes) without copying its vertices: the chosen triangles' vertex indices,
// which still point into the whole's vertex arrays, their per-face arrays in order, and every
// material (face materials stay valid). The vertex arrays and texture maps stay the whole's:
// the per-triangle work reads vertices there (TriangleShadingCache::setMesh's `vertices`) and a
// part draws through the whole's streams and maps (Model::Part).
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/mesh/mesh.h"

namespace npr {

struct MeshFaces {
  // indices, faceCentroids, faceNormals, faceMaterials, faceTints and materials; no vertices.
  Mesh faces;
  std::vector<std::uint32_t> ofWhole;  // per face: the whole's triangle it is
};

// `keep` has one flag per triangle of `mesh`.
MeshFaces meshFaces(const Mesh& mesh, const std::vector<char>& keep);
// The faces' centroids and normals again from the whole's, which moved (a posed mesh).
void copyFaceGeometry(const Mesh& whole, MeshFaces& part);

}  // namespace npr
