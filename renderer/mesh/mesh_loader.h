// Loading meshes from files: OBJ through our own parser feeding OpenMesh (it keeps double
// precision, ear-clips polygons and reports every face it cannot use), PLY/OFF/STL/OM
// through OpenMesh's readers. Nothing is dropped without a warning in the report.
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"

namespace npr {

[[nodiscard]] Result<Mesh> loadMesh(const std::string& path);
// What the command line and the viewer accept as a model: a generated mesh's name
// ("generated:torus-871k", see mesh_generators.h) or a file for loadMesh.
[[nodiscard]] Result<Mesh> loadModel(const std::string& nameOrPath);

// Ear-clipping triangulation of a planar-ish polygon (exposed for tests). Returns indices
// into `poly`, 3 per triangle, n-2 triangles, preserving the polygon's winding.
std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly);

}  // namespace npr
