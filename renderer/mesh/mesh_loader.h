// Loading meshes from files: OBJ through our own parser feeding OpenMesh (it keeps double
// precision, ear-clips polygons and reports every face it cannot use), PLY/OFF/STL/OM
// through OpenMesh's readers. Nothing is dropped without a warning in the report.
#pragma once

#include <string>

#include "renderer/mesh/mesh.h"
#include "renderer/core/result.h"

namespace npr {

Result<Mesh> loadMesh(const std::string& path);

// Ear-clipping triangulation of a planar-ish polygon (exposed for tests). Returns indices
// into `poly`, 3 per triangle, n-2 triangles, preserving the polygon's winding.
std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly);

}  // namespace npr
