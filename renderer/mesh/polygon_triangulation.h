// Ear-clipping triangulation of planar-ish polygons, in double precision: what the OBJ
// parser uses for faces with more than three corners (concave ones included).
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace npr {

// Returns indices into `poly`, 3 per triangle, n-2 triangles, preserving the polygon's
// winding. A polygon with no ear left (degenerate, self-intersecting) is finished as a fan.
std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly);

}  // namespace npr
