// Region tracing (see region_trace.h): each pixel gives the directed edges of its sides that
// border another label; a label's edges close into loops, walked from any unused edge. Where
// two of a label's pixels touch only at a corner, two loops meet at that vertex and either
// pairing of its edges covers the same pixels under the nonzero rule.
#include "renderer/lines/region_trace.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace npr {

std::vector<std::vector<RegionLoop>> traceRegions(const std::vector<int>& labels, int width, int height, int labelCount) {
  std::vector<std::vector<RegionLoop>> out(static_cast<std::size_t>(std::max(labelCount, 0)));
  if (width <= 0 || height <= 0 || labels.size() != std::size_t(width) * std::size_t(height)) return out;
  auto label = [&](int x, int y) { return x < 0 || y < 0 || x >= width || y >= height ? -1 : labels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; };
  const auto vertex = [&](int x, int y) { return std::uint64_t(y) * std::uint64_t(width + 1) + std::uint64_t(x); };
  // Per label: edges as (from, to) vertices, clockwise around the label's pixels (y down).
  std::vector<std::vector<std::pair<std::uint64_t, std::uint64_t>>> edges(out.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int l = label(x, y);
      if (l < 0 || l >= labelCount) continue;
      auto& e = edges[std::size_t(l)];
      if (label(x, y - 1) != l) e.push_back({vertex(x, y), vertex(x + 1, y)});              // top, rightwards
      if (label(x + 1, y) != l) e.push_back({vertex(x + 1, y), vertex(x + 1, y + 1)});      // right, down
      if (label(x, y + 1) != l) e.push_back({vertex(x + 1, y + 1), vertex(x, y + 1)});      // bottom, leftwards
      if (label(x - 1, y) != l) e.push_back({vertex(x, y + 1), vertex(x, y)});              // left, up
    }
  for (std::size_t l = 0; l < edges.size(); ++l) {
    const auto& e = edges[l];
    if (e.empty()) continue;
    // Outgoing edges per vertex: one, or two where the label's pixels touch at a corner.
    std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> from;
    from.reserve(e.size());
    constexpr std::uint32_t kNone = 0xFFFFFFFFu;
    for (std::uint32_t i = 0; i < e.size(); ++i) {
      auto [it, added] = from.try_emplace(e[i].first, i, kNone);
      if (!added) it->second.second = i;
    }
    std::vector<char> used(e.size(), 0);
    auto corner = [&](std::uint64_t v) { return glm::ivec2(int(v % std::uint64_t(width + 1)), int(v / std::uint64_t(width + 1))); };
    for (std::uint32_t start = 0; start < e.size(); ++start) {
      if (used[start]) continue;
      std::vector<glm::ivec2> points;
      std::uint32_t at = start;
      while (at != kNone && !used[at]) {
        used[at] = 1;
        points.push_back(corner(e[at].first));
        const auto& next = from.at(e[at].second);
        at = !used[next.first] ? next.first : (next.second != kNone && !used[next.second] ? next.second : kNone);
      }
      // Corners only: a point where the direction does not change is dropped.
      RegionLoop loop;
      const std::size_t n = points.size();
      for (std::size_t i = 0; i < n; ++i) {
        const glm::ivec2 a = points[(i + n - 1) % n], b = points[i], c = points[(i + 1) % n];
        if ((b - a) != (c - b)) loop.push_back(b);
      }
      if (loop.size() >= 4) out[l].push_back(std::move(loop));
    }
  }
  return out;
}

}  // namespace npr
