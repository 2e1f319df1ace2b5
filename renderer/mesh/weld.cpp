// Welding by exact position (see weld.h).
#include "renderer/mesh/weld.h"

#include <cstring>
#include <unordered_map>

namespace npr {
namespace {

struct PositionKey {
  std::uint32_t x, y, z;
  bool operator==(const PositionKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    return (size_t(k.x) * 0x9E3779B97F4A7C15ull) ^ (size_t(k.y) * 0xC2B2AE3D27D4EB4Full) ^ (size_t(k.z) * 0x165667B19E3779F9ull);
  }
};
std::uint32_t bits(float f) {
  if (f == 0.0f) f = 0.0f;  // -0 and +0 weld
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

}  // namespace

WeldedPositions weldPositions(const std::vector<glm::vec3>& positions) {
  WeldedPositions w;
  std::unordered_map<PositionKey, std::uint32_t, PositionHash> ids;
  ids.reserve(positions.size());
  w.remap.resize(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3& p = positions[i];
    auto [it, inserted] = ids.emplace(PositionKey{bits(p.x), bits(p.y), bits(p.z)}, std::uint32_t(w.positions.size()));
    if (inserted) w.positions.push_back(p);
    w.remap[i] = it->second;
  }
  return w;
}

}  // namespace npr
