// Intersection lines (`--lines intersection`): where surfaces cross, within one object (a
// character's belt through its coat) and between objects (a cup standing in a saucer), as the
// illustrator's line where two forms meet. Found in world space over the whole scene: a
// bounding volume hierarchy over all triangles is searched against itself (in parallel, over
// node pairs), and each crossing pair of triangles gives the segment they share. Triangles
// that share a corner (neighbours on one surface) and coplanar
// pairs (one surface doubled, not two crossing) give none. Computed once per pose: the
// caller keeps the result until the scene moves. No GL here.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/lines/feature_edges.h"
#include "renderer/mesh/mesh.h"

namespace npr {

// One object of the scene: its mesh as drawn (posed) and where it stands.
struct IntersectionObject {
  const Mesh* mesh;
  glm::mat4 transform;
};

struct IntersectionCounts {
  std::size_t triangles = 0;
  std::size_t tasks = 0;        // node pairs searched on their own (shared between threads)
  std::size_t pairsTested = 0;  // triangle pairs whose boxes overlap
  std::size_t segments = 0;
  bool stopped = false;  // the pair budget ran out: the lines are those found until then
};


// At most this many triangle pairs are tested per search (11M for two crossing copies of an
// 871K-triangle torus, about a second here; a pile of coincident triangles would test all with
// all, and stops here after a few seconds instead of minutes).
inline constexpr std::size_t kMaxIntersectionPairs = 64'000'000;

// The segments where the objects' surfaces cross, in world space, kind EdgeKind::Intersection.
std::vector<FeatureLine> intersectionLines(const std::vector<IntersectionObject>& objects, IntersectionCounts* counts = nullptr,
                                           std::size_t maxPairs = kMaxIntersectionPairs);

// The segment two triangles share, if they cross (exposed for the tests): false when they miss,
// touch at a point, share a corner or lie in one plane.
bool triangleIntersection(const glm::vec3 a[3], const glm::vec3 b[3], glm::vec3& from, glm::vec3& to);

}  // namespace npr
