// The benchmark's ray-cast reference for shadows and ambient occlusion: rays through the mesh
// on the CPU in double precision, independent of the shadow maps and the occlusion bake they
// check. A bounding-volume hierarchy over the triangles keeps a ray at a few dozen triangle
// tests, so the reference can light every pixel of every benchmark frame.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/mesh/mesh.h"

namespace npr {

class RayScene {
 public:
  explicit RayScene(const Mesh& mesh);

  // Whether the ray origin + t dir (dir unit, 0 < t < maxT) hits a triangle.
  bool blocked(const glm::dvec3& origin, const glm::dvec3& dir, double maxT) const;
  // The occlusion bake's quantity at a point: the cosine-weighted share of `directions` (unit,
  // toward the sky) in which a ray from the point leaves the mesh. 1 where nothing is above.
  double openness(const glm::dvec3& point, const glm::dvec3& normal, const std::vector<glm::vec3>& directions) const;
  // How far off the surface rays start: far enough that a triangle does not shadow itself
  // through rounding, small against the mesh.
  double offset() const { return offset_; }

 private:
  struct Node {
    glm::vec3 lo, hi;
    std::uint32_t first = 0, count = 0;  // leaf: triangles [first, first + count); inner: count 0
    std::uint32_t left = 0, right = 0;
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count, int depth);
  std::vector<glm::dvec3> a_, b_, c_;  // triangle corners, in the order the leaves index
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
  std::vector<glm::vec3> centroid_, triLo_, triHi_;  // while building
  double offset_ = 1e-4;
};

}  // namespace npr
