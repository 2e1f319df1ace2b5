// Stroke particle seeding (see stroke_seeding.h).
#include "renderer/strokes/stroke_seeding.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <unordered_map>

#include "renderer/core/elapsed.h"

namespace npr {
namespace {

struct Candidate {
  glm::vec3 position, normal, direction;
  StrokeAnchor anchor;
};

// The particle's place on the surface at (face, u, v): what seeding and re-placing share.
void placeAt(const Mesh& mesh, const std::vector<glm::vec3>& directions, const StrokeAnchor& a, glm::vec3& position, glm::vec3& normal,
             glm::vec3& direction);

// Cells of a uniform grid, hashed: the accepted points near a candidate.
class PointGrid {
 public:
  explicit PointGrid(float cell) : cell_(cell) {}
  void add(const glm::vec3& p) { cells_[key(cellOf(p))].push_back(p); }
  bool anyWithin(const glm::vec3& p, float radius) const {
    const glm::ivec3 c = cellOf(p);
    const float r2 = radius * radius;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(key(c + glm::ivec3(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (const glm::vec3& q : it->second)
            if (glm::dot(q - p, q - p) < r2) return true;
        }
    return false;
  }

 private:
  glm::ivec3 cellOf(const glm::vec3& p) const { return glm::ivec3(glm::floor(p / cell_)); }
  static std::uint64_t key(const glm::ivec3& c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1FFFFF) << 42) | (std::uint64_t(std::uint32_t(c.y) & 0x1FFFFF) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1FFFFF);
  }
  float cell_;
  std::unordered_map<std::uint64_t, std::vector<glm::vec3>> cells_;
};

glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
  const float len = glm::length(v);
  return len > 1e-12f && std::isfinite(len) ? v / len : fallback;
}

}  // namespace

namespace {
void placeAt(const Mesh& mesh, const std::vector<glm::vec3>& directions, const StrokeAnchor& a, glm::vec3& position, glm::vec3& normal,
             glm::vec3& direction) {
  const float u = a.u, v = a.v, w = 1.0f - u - v;
  const std::uint32_t i0 = mesh.indices[3 * a.face], i1 = mesh.indices[3 * a.face + 1], i2 = mesh.indices[3 * a.face + 2];
  position = w * mesh.positions[i0] + u * mesh.positions[i1] + v * mesh.positions[i2];
  const glm::vec3 faceNormal = glm::cross(mesh.positions[i1] - mesh.positions[i0], mesh.positions[i2] - mesh.positions[i0]);
  normal = unitOr(w * mesh.normals[i0] + u * mesh.normals[i1] + v * mesh.normals[i2], unitOr(faceNormal, glm::vec3(0, 0, 1)));
  direction = glm::vec3(0.0f);
  if (directions.size() == mesh.positions.size()) {
    // The nearest corner's direction: a cross field's neighbours may disagree in sign, so
    // directions are not averaged.
    const std::uint32_t nearest = w >= u && w >= v ? i0 : (u >= v ? i1 : i2);
    const glm::vec3 d = directions[nearest];
    direction = unitOr(d - normal * glm::dot(d, normal), glm::vec3(0.0f));
  }
}
}  // namespace

void placeStrokes(const Mesh& mesh, const std::vector<glm::vec3>& directions, const std::vector<StrokeAnchor>& anchors,
                  std::vector<StrokeParticle>& particles) {
  for (std::size_t i = 0; i < particles.size() && i < anchors.size(); ++i) {
    if (3 * std::size_t(anchors[i].face) + 2 >= mesh.indices.size()) continue;
    placeAt(mesh, directions, anchors[i], particles[i].position, particles[i].normal, particles[i].direction);
  }
}

StrokeSeeding seedStrokes(const Mesh& mesh, float density, int budget, const std::vector<glm::vec3>& directions) {
  const auto t0 = std::chrono::steady_clock::now();
  StrokeSeeding out;
  const std::size_t triangles = mesh.triangleCount();
  std::vector<double> cumulative(triangles);
  double area = 0;
  for (std::size_t t = 0; t < triangles; ++t) {
    const glm::vec3 &a = mesh.positions[mesh.indices[3 * t]], &b = mesh.positions[mesh.indices[3 * t + 1]],
                    &c = mesh.positions[mesh.indices[3 * t + 2]];
    const double ta = 0.5 * double(glm::length(glm::cross(b - a, c - a)));
    area += std::isfinite(ta) ? ta : 0.0;
    cumulative[t] = area;
  }
  out.area = float(area);
  const double wanted = std::min(double(std::max(budget, 0)), std::max(0.0, double(density)) * area);
  if (!(area > 0.0) || wanted < 1.0) return out;
  const std::size_t count = std::size_t(wanted);
  // Dart throwing with 6 candidates per stroke takes about 0.5 A / r^2 points at radius r on
  // the sphere; r is set for `count`, and passes of 2 and sqrt(2) times r come first. Should the
  // candidates run out first, passes at r / sqrt(2) and then at no radius at all make up the
  // count (taking the remaining candidates in their random order).
  const float radius = float(std::sqrt(0.5 * area / double(count)));
  std::mt19937 rng(0x5eed);
  std::uniform_real_distribution<double> pick(0.0, area);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Candidate> candidates(count * 6);
  for (Candidate& cand : candidates) {
    const std::size_t t = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick(rng)) - cumulative.begin());
    const std::size_t tri = std::min(t, triangles - 1);
    float u = unit(rng), v = unit(rng);
    if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
    cand.anchor = {static_cast<std::uint32_t>(tri), u, v};
    // placeAt reads `directions` only when it has one per vertex (a conditional here would copy
    // the whole field per candidate).
    placeAt(mesh, directions, cand.anchor, cand.position, cand.normal, cand.direction);
  }
  PointGrid grid(radius * 2.0f);
  const float passRadius[] = {2.0f * radius, std::sqrt(2.0f) * radius, radius, radius / std::sqrt(2.0f), 0.0f};
  std::vector<char> taken(candidates.size(), 0);
  for (int pass = 0; pass < 5 && out.particles.size() < count; ++pass)
    for (std::size_t i = 0; i < candidates.size() && out.particles.size() < count; ++i) {
      if (taken[i] || (passRadius[pass] > 0.0f && grid.anyWithin(candidates[i].position, passRadius[pass]))) continue;
      taken[i] = 1;
      grid.add(candidates[i].position);
      const Candidate& c = candidates[i];
      out.particles.push_back({c.position, c.normal, c.direction, 0.0f, unit(rng)});
      out.anchors.push_back(c.anchor);
    }
  // Ranks in the order taken: coarse passes first, random within a pass (the candidates are),
  // so the strokes below any rank k are a fraction k of all and spread evenly.
  for (std::size_t i = 0; i < out.particles.size(); ++i) out.particles[i].rank = (float(i) + 0.5f) / float(out.particles.size());
  out.ms = msSince(t0);
  return out;
}

}  // namespace npr
