// Vertices at identical positions merged into one: files are often polygon soups (every face
// with its own corners, seams split for texture coordinates), and whatever needs a surface's
// adjacency (feature lines, the direction field) works on the welded copy.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace npr {

struct WeldedPositions {
  std::vector<glm::vec3> positions;   // one per distinct position, in order of first use
  std::vector<std::uint32_t> remap;   // per input vertex: its welded vertex
};

// Exact comparison of the coordinates' bits (+0 and -0 are one point): a tolerance would
// join distinct vertices of fine meshes and is the loader's business, not the adjacency's.
WeldedPositions weldPositions(const std::vector<glm::vec3>& positions);

}  // namespace npr
