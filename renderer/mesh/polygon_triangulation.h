// Ear-clipping triangulation of planar-ish polygons, in double precision: what the OBJ
// parser uses for faces with more than three corners (concave ones included).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace npr {

// How much ear-clipping work one file may cost (point-in-triangle tests). A single hostile
// polygon of a few thousand corners must not keep the loader busy for seconds; once the budget
// is spent, the remaining polygons are fanned and the caller reports it.
struct TriangulationBudget {
  std::int64_t tests = 100'000'000;  // about half a second on this project's CI machine
  bool exhausted() const { return tests <= 0; }
};

// Returns indices into `poly`, 3 per triangle, n-2 triangles, preserving the polygon's
// winding. A polygon with no ear left (degenerate, self-intersecting), or one met after the
// budget ran out, is finished as a fan. Only reflex corners can lie inside an ear, so each ear
// test checks those alone; the scan resumes where the last ear was cut: O(n r) for r reflex
// corners in practice instead of the O(n^3) of restarting the scan after each cut.
std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly, TriangulationBudget& budget);
std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly);

}  // namespace npr
