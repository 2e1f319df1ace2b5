// The ground grid (see ground_plane.h).
#include "renderer/mesh/ground_plane.h"

#include <algorithm>
#include <cmath>

namespace npr {

Mesh groundPlane(const Mesh& model, float extent, int cells) {
  float lowest = model.positions.empty() ? -1.0f : model.positions.front().y;
  for (const glm::vec3& p : model.positions) lowest = std::min(lowest, p.y);
  return groundPlane(lowest, model.radius, extent, cells);
}

Mesh groundPlane(float lowest, float radius, float extent, int cells) {
  Mesh g;
  cells = std::clamp(cells, 1, 1024);
  const float r = radius > 0.0f && std::isfinite(radius) ? radius : 1.0f;
  const float y = lowest - 0.002f * r, half = extent * r;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i)
      g.positions.push_back(glm::vec3(-half + 2.0f * half * float(i) / float(cells), y, -half + 2.0f * half * float(j) / float(cells)));
  auto at = [&](int i, int j) { return std::uint32_t(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {  // counter-clockwise seen from above (+y)
      g.indices.insert(g.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      g.indices.insert(g.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  finalizeMesh(g);
  g.report.file = "ground plane";
  return g;
}

}  // namespace npr
