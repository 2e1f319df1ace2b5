// Ray-cast reference (see ray_reference.h).
#include "app/benchmark/ray_reference.h"

#include <algorithm>
#include <cmath>

namespace npr {
namespace {

constexpr std::uint32_t kLeafSize = 4;

// Moller-Trumbore in double precision: the hit's t, or -1.
double hitT(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::fabs(det) < 1e-300) return -1.0;
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return glm::dot(e2, q) * inv;
}

// Slab test against a box, for t in (0, maxT).
bool crossesBox(const glm::dvec3& o, const glm::dvec3& invDir, const glm::vec3& lo, const glm::vec3& hi, double maxT) {
  double t0 = 0.0, t1 = maxT;
  for (int k = 0; k < 3; ++k) {
    double ta = (double(lo[k]) - o[k]) * invDir[k], tb = (double(hi[k]) - o[k]) * invDir[k];
    if (ta > tb) std::swap(ta, tb);
    if (std::isnan(ta) || std::isnan(tb)) continue;  // 0 x inf: the ray lies in the slab's plane
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

RayScene::RayScene(const Mesh& mesh) {
  const std::size_t n = mesh.triangleCount();
  order_.resize(n);
  centroid_.resize(n);
  triLo_.resize(n);
  triHi_.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    order_[t] = std::uint32_t(t);
    const glm::vec3 a = mesh.positions[mesh.indices[t * 3]], b = mesh.positions[mesh.indices[t * 3 + 1]], c = mesh.positions[mesh.indices[t * 3 + 2]];
    centroid_[t] = (a + b + c) / 3.0f;
    triLo_[t] = glm::min(a, glm::min(b, c));
    triHi_[t] = glm::max(a, glm::max(b, c));
  }
  if (n > 0) {
    nodes_.reserve(2 * n / kLeafSize + 1);
    (void)build(0, std::uint32_t(n), 0);
  }
  a_.resize(n);
  b_.resize(n);
  c_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t t = order_[i];
    a_[i] = glm::dvec3(mesh.positions[mesh.indices[t * 3]]);
    b_[i] = glm::dvec3(mesh.positions[mesh.indices[t * 3 + 1]]);
    c_[i] = glm::dvec3(mesh.positions[mesh.indices[t * 3 + 2]]);
  }
  centroid_ = {};
  triLo_ = {};
  triHi_ = {};
  const float r = mesh.radius > 0.0f && std::isfinite(mesh.radius) ? mesh.radius : 1.0f;
  offset_ = 1e-4 * double(r);
}

std::uint32_t RayScene::build(std::uint32_t first, std::uint32_t count, int depth) {
  const std::uint32_t index = std::uint32_t(nodes_.size());
  nodes_.push_back({});
  // The node bounds its triangles; their centroids' bounds choose the split.
  glm::vec3 lo(INFINITY), hi(-INFINITY), clo(INFINITY), chi(-INFINITY);
  for (std::uint32_t i = first; i < first + count; ++i) {
    const std::uint32_t t = order_[i];
    lo = glm::min(lo, triLo_[t]);
    hi = glm::max(hi, triHi_[t]);
    clo = glm::min(clo, centroid_[t]);
    chi = glm::max(chi, centroid_[t]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  if (count <= kLeafSize || depth > 48) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  const glm::vec3 extent = chi - clo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](std::uint32_t x, std::uint32_t y) { return centroid_[x][axis] < centroid_[y][axis]; });
  const std::uint32_t left = build(first, mid - first, depth + 1);
  const std::uint32_t right = build(mid, first + count - mid, depth + 1);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

bool RayScene::blocked(const glm::dvec3& o, const glm::dvec3& d, double maxT) const {
  if (nodes_.empty()) return false;
  const glm::dvec3 inv = 1.0 / d;
  std::uint32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!crossesBox(o, inv, node.lo, node.hi, maxT)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const double t = hitT(o, d, a_[i], b_[i], c_[i]);
        if (t > 1e-9 && t < maxT) return true;
      }
    } else if (top + 2 <= 128) {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return false;
}

double RayScene::openness(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::vec3>& directions) const {
  double seen = 0.0, total = 0.0;
  const glm::dvec3 o = p + n * offset_;
  for (const glm::vec3& dir : directions) {
    const glm::dvec3 d(dir);
    const double c = glm::dot(n, d);
    if (!(c > 0.0)) continue;
    total += c;
    if (!blocked(o, d, INFINITY)) seen += c;
  }
  return total > 0.0 ? seen / total : 1.0;
}

}  // namespace npr
