// The manifold check (see manifold_fans.h).
#include "renderer/mesh/manifold_fans.h"

#include <cstdint>

namespace npr {

bool formsManifoldFans(const std::vector<std::array<int, 3>>& triangles, std::size_t vertexCount) {
  // Each vertex's corners, grouped by vertex (a CSR table): the corner (triangle * 3 + k), the
  // vertex its outgoing edge runs to and the vertex before it in its triangle.
  std::vector<std::uint32_t> first(vertexCount + 1, 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (++first[static_cast<std::size_t>(t[static_cast<std::size_t>(k)]) + 1] > kMaxFanDegree) return false;
  for (std::size_t v = 0; v < vertexCount; ++v) first[v + 1] += first[v];
  const std::size_t n = triangles.size() * 3;
  std::vector<std::uint32_t> corner(n), to(n), from(n), fill(first.begin(), first.end() - 1);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t slot = fill[static_cast<std::size_t>(triangles[f][k])]++;
      corner[slot] = static_cast<std::uint32_t>(f * 3 + k);
      to[slot] = static_cast<std::uint32_t>(triangles[f][(k + 1) % 3]);
      from[slot] = static_cast<std::uint32_t>(triangles[f][(k + 2) % 3]);
    }
  // The slot of the corner at `a` whose edge runs to `b`; -1 when none.
  auto edge = [&](std::uint32_t a, std::uint32_t b) -> std::int64_t {
    for (std::uint32_t i = first[a]; i < first[a + 1]; ++i)
      if (to[i] == b) return i;
    return -1;
  };
  // The slot of corner c's triangle's next corner (at the vertex c's edge runs to).
  std::vector<std::uint32_t> slotOf(n);
  for (std::uint32_t i = 0; i < n; ++i) slotOf[corner[i]] = i;
  for (std::uint32_t v = 0; v < vertexCount; ++v) {
    const std::uint32_t begin = first[v], end = first[v + 1];
    if (begin == end) continue;
    // Every directed edge once: no two corners at v run to the same vertex.
    for (std::uint32_t i = begin; i < end; ++i)
      for (std::uint32_t j = i + 1; j < end; ++j)
        if (to[i] == to[j]) return false;
    // One fan: walk from a corner with no triangle before it (the fan's open side), or from
    // any when the fan closes, to the triangle across each corner's outgoing edge; the walk
    // must meet every corner at v. A corner's predecessor holds the edge v -> (its previous
    // vertex); its successor the edge (its next vertex) -> v.
    std::uint32_t start = begin;
    for (std::uint32_t i = begin; i < end; ++i)
      if (edge(v, from[i]) < 0) {
        start = i;
        break;
      }
    std::uint32_t s = start, met = 0;
    do {
      ++met;
      const std::int64_t across = edge(to[s], v);  // the slot of the corner at the next vertex
      if (across < 0) break;
      const std::uint32_t c = corner[static_cast<std::size_t>(across)];
      s = slotOf[c / 3 * 3 + (c % 3 + 1) % 3];  // its triangle's corner at v
    } while (s != start && met <= end - begin);
    if (met != end - begin) return false;
  }
  return true;
}

}  // namespace npr
