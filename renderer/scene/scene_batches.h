// Small static objects merged into batches for the surface passes. At thousands of objects a
// draw per object (its programs' state, uniforms, the path's per-object work, the per-triangle
// paths' buckets) costs far more than its few triangles. Objects that differ in nothing a
// surface pass reads but their transform (the same palette, no per-material parts of their
// own, no deformation, no texture maps, not mirrored, not moved by animation) are merged, in spatial
// order so each batch stays compact for culling, into meshes of up to kBatchTriangles placed in
// the scene, and each batch is drawn as one model. The objects stay in the scene for everything
// else: lines, strokes, names, the tone fit, export (scene.h: forEachSurface).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

class Model;

inline constexpr std::size_t kMaxBatchedObjectTriangles = 4096;  // a larger object is drawn alone
inline constexpr std::size_t kBatchTriangles = 65536;            // a batch's most
inline constexpr std::size_t kMinBatchedObjects = 16;            // fewer such objects: none merged

// Whether `model` may be merged with others (see above).
bool batchable(const Model& model);

// `models` (batchable) grouped into batches: those alike in their vertex streams (colours,
// texture coordinates, materials or none), palette, detail, one material, and closed or not together, in the order of a
// Morton curve through their centres, cut where the next would pass kBatchTriangles. Indices into `models`; a
// group of one is left alone (not returned).
std::vector<std::vector<std::size_t>> groupIntoBatches(const std::vector<const Model*>& models);

// The merged mesh of `models` in the scene's space, then centred and scaled into the unit sphere
// as every mesh is; `placement` is the transform that puts it back. Materials equal in every
// field are kept once.
// `spheres` gets each object's bounding sphere in the merged mesh's space (centre, radius).
Mesh mergeObjects(const std::vector<const Model*>& models, glm::mat4& placement, std::vector<glm::vec4>* spheres = nullptr);

}  // namespace npr
