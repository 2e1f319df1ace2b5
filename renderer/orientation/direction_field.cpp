// Cross-field smoothing and combing of the principal directions (see direction_field.h).
#include "renderer/orientation/direction_field.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <queue>

#include "renderer/core/elapsed.h"
#include "renderer/core/parallel.h"
#include "renderer/orientation/principal_curvature.h"

namespace npr {
namespace {

// A tangent direction as the 4-way symmetric value z^4 in the frame (t1, t2): a direction
// and its quarter turns give the same value. Zero for a vector normal to the plane.
glm::vec2 crossValue(const glm::vec3& d, const glm::vec3& t1, const glm::vec3& t2) {
  const float x = glm::dot(d, t1), y = glm::dot(d, t2);
  const float r2 = x * x + y * y;
  if (!(r2 > 1e-12f)) return glm::vec2(0.0f);
  // z^2 / |z|^2, squared again
  const float a = (x * x - y * y) / r2, b = 2.0f * x * y / r2;
  return glm::vec2(a * a - b * b, 2.0f * a * b);
}

// A guide for vertices curvature does not decide: the model's up axis (else its x axis) laid
// into the tangent plane, calm and continuous away from the two poles.
glm::vec3 guideDirection(const glm::vec3& n) {
  glm::vec3 g = glm::vec3(0, 1, 0) - n.y * n;
  if (glm::dot(g, g) < 0.01f) g = glm::vec3(1, 0, 0) - n.x * n;
  const float l = glm::length(g);
  return l > 0.0f ? g / l : glm::vec3(0.0f);
}

}  // namespace

DirectionField computeDirectionField(const Mesh& mesh, const DirectionFieldOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  const PrincipalCurvatures pc = estimatePrincipalCurvatures(mesh);
  const std::size_t nv = pc.weld.positions.size();
  const int workers = workerCount();

  std::vector<float> confidence(nv, 0.0f);
  std::vector<glm::vec3> t1(nv), t2(nv), d(nv, glm::vec3(0.0f));
  parallelChunks(nv, workers, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t v = b; v < e; ++v) {
      const glm::vec3 n = pc.normals[v];
      if (n == glm::vec3(0.0f)) continue;
      tangentBasis(n, t1[v], t2[v]);
      const float k1 = std::fabs(pc.kMax[v]), k2 = std::fabs(pc.kMin[v]);
      const float anisotropy = (k1 - k2) / (k1 + k2 + 1e-20f);
      confidence[v] = glm::smoothstep(1.0f / 3.0f, 0.6f, anisotropy) * glm::smoothstep(opt.flatCurvature, 6.0f * opt.flatCurvature, k1 - k2);
      d[v] = confidence[v] >= 0.5f ? pc.maxDirection[v] : guideDirection(n);
    }
  });

  // Jacobi iterations of the cross field: each vertex takes the mean of its neighbours' cross
  // values plus its own curvature direction weighted by its confidence (and curvatureWeight:
  // held too hard, noisy directions pin pairs of singular points that smoothing would cancel).
  std::vector<glm::vec2> anchor(nv);
  for (std::size_t v = 0; v < nv; ++v) anchor[v] = crossValue(pc.maxDirection[v], t1[v], t2[v]);
  std::vector<glm::vec3> next(nv);
  for (int it = 0; it < opt.smoothingIterations; ++it) {
    parallelChunks(nv, workers, [&](std::size_t b, std::size_t e, int) {
      for (std::size_t v = b; v < e; ++v) {
        next[v] = d[v];
        if (pc.normals[v] == glm::vec3(0.0f)) continue;
        const std::uint32_t n0 = pc.neighbourStart[v], n1 = pc.neighbourStart[v + 1];
        glm::vec2 s = anchor[v] * (opt.curvatureWeight * float(n1 - n0) * confidence[v]);
        for (std::uint32_t k = n0; k < n1; ++k) s += crossValue(d[pc.neighbours[k]], t1[v], t2[v]);
        if (!(glm::dot(s, s) > 1e-20f)) continue;
        const float angle = 0.25f * std::atan2(s.y, s.x);
        next[v] = std::cos(angle) * t1[v] + std::sin(angle) * t2[v];
      }
    });
    d.swap(next);
  }

  // Combing: flood from the most confident vertices, each vertex taking the one of its four
  // directions (d, -d, and the quarter turns) nearest its neighbour's. A seed takes the one
  // nearest its largest-curvature direction, so strokes wrap around the form.
  std::vector<std::uint32_t> order(nv);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return confidence[a] > confidence[b]; });
  std::vector<char> combed(nv, 0);
  std::priority_queue<std::pair<float, std::uint32_t>> queue;
  auto nearestOf4 = [&](std::uint32_t v, const glm::vec3& target) {
    const glm::vec3 q = glm::cross(pc.normals[v], d[v]);
    const float a = glm::dot(d[v], target), b = glm::dot(q, target);
    if (std::fabs(a) >= std::fabs(b)) return a >= 0.0f ? d[v] : -d[v];
    return b >= 0.0f ? q : -q;
  };
  for (std::uint32_t seed : order) {
    if (combed[seed] || pc.normals[seed] == glm::vec3(0.0f)) continue;
    combed[seed] = 1;
    if (pc.maxDirection[seed] != glm::vec3(0.0f)) d[seed] = nearestOf4(seed, pc.maxDirection[seed]);
    queue.push({confidence[seed], seed});
    while (!queue.empty()) {
      const std::uint32_t v = queue.top().second;
      queue.pop();
      for (std::uint32_t k = pc.neighbourStart[v]; k < pc.neighbourStart[v + 1]; ++k) {
        const std::uint32_t w = pc.neighbours[k];
        if (combed[w] || pc.normals[w] == glm::vec3(0.0f)) continue;
        combed[w] = 1;
        d[w] = nearestOf4(w, d[v]);
        queue.push({confidence[w], w});
      }
    }
  }

  DirectionField field;
  field.weldedVertices = nv;
  field.directions.resize(mesh.positions.size());
  field.confidence.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const std::uint32_t w = pc.weld.remap[i];
    const glm::vec3 x = d[w];
    field.directions[i] = std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) ? x : glm::vec3(0.0f);
    field.confidence[i] = confidence[w];
  }
  field.ms = msSince(start);
  return field;
}

}  // namespace npr
