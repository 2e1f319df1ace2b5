// The posed copy of a deforming mesh (glTF morph targets and skins), made on the CPU whenever
// the pose changes, so that every render path, the feature lines, the shadows and the SVG
// export draw the same posed surface. Morph targets first (positions and normals plus the
// weighted deltas), then linear blend skinning: each vertex by the weighted sum of its four
// joints' matrices, normals by the same sum's linear part, renormalised (exact for rigid and
// uniformly scaled joints). Runs over the vertices and faces in parallel.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

// Writes `posed`'s positions, normals, face centroids, face normals and radius from `rest`
// (whose copy `posed` is, arrays sized alike) deformed by morph `weights` (one per target;
// missing ones zero) and, for a skinned mesh, `joints`: per skin joint, the mesh's rest space
// to its posed space. Vertices whose weights are all zero keep their morphed rest position.
// `restTangents` (per vertex, optional: the hatching direction field) are carried by the same
// skin into `posedTangents`, so the strokes stay across the surface as it bends.
void deformMesh(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights, Mesh& posed,
                const std::vector<glm::vec3>* restTangents = nullptr, std::vector<glm::vec3>* posedTangents = nullptr);

// Poses only triangles `first`, `first + stride`, ... of `posed` (a copy of `rest`): their
// vertices, centroids and normals, as deformMesh would. The tone sampler's triangles, while the
// GPU holds the whole pose (gpu_deformation.h).
void deformFaces(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights, Mesh& posed, std::size_t first,
                 std::size_t stride);

}  // namespace npr
