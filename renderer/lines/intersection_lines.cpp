// Intersection lines (see intersection_lines.h). A bounding volume hierarchy over the scene's
// triangles, traversed against itself: it keeps large and small triangles apart as a uniform
// grid cannot (a ground of two triangles beside a million-triangle statue).
#include "renderer/lines/intersection_lines.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/core/parallel.h"

namespace npr {
namespace {

using WorldTriangle = std::array<glm::vec3, 3>;

struct Box {
  glm::vec3 lo{INFINITY}, hi{-INFINITY};
  void add(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void add(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  bool overlaps(const Box& b) const { return glm::all(glm::lessThanEqual(lo, b.hi)) && glm::all(glm::lessThanEqual(b.lo, hi)); }
};

struct Node {
  Box box;
  std::uint32_t first = 0, count = 0;  // a leaf's triangles in `order`
  std::uint32_t left = 0, right = 0;   // an inner node's children (count == 0)
  bool leaf() const { return count > 0; }
};

constexpr std::uint32_t kLeafSize = 4;

class Hierarchy {
 public:
  explicit Hierarchy(const std::vector<WorldTriangle>& tris) : tris_(tris) {
    boxes_.resize(tris.size());
    centres_.resize(tris.size());
    order_.resize(tris.size());
    for (std::size_t i = 0; i < tris.size(); ++i) {
      for (const glm::vec3& p : tris[i]) boxes_[i].add(p);
      centres_[i] = 0.5f * (boxes_[i].lo + boxes_[i].hi);
      order_[i] = std::uint32_t(i);
    }
    nodes_.reserve(2 * tris.size() / kLeafSize + 2);
    if (!tris.empty()) build(0, std::uint32_t(tris.size()));
  }

  // Pairs of nodes whose boxes overlap, expanded until there are enough to share between
  // threads: each is then searched on its own.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> tasks(std::size_t wanted) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    if (nodes_.empty()) return out;
    out.push_back({0, 0});
    for (int round = 0; round < 12 && out.size() < wanted; ++round) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> next;
      for (auto [a, b] : out) split(a, b, next);
      if (next.size() == out.size()) break;
      out = std::move(next);
    }
    return out;
  }

  // Every crossing segment under the node pair (a, b).
  // `tested` counts triangle pairs; the search stops once it reaches `limit`.
  void search(std::uint32_t a, std::uint32_t b, std::vector<FeatureLine>& out, std::size_t& tested, std::size_t limit) const {
    if (tested >= limit) return;
    const Node& na = nodes_[a];
    const Node& nb = nodes_[b];
    if (a != b && !na.box.overlaps(nb.box)) return;
    if (na.leaf() && nb.leaf()) {
      for (std::uint32_t i = 0; i < na.count; ++i)
        for (std::uint32_t j = a == b ? i + 1 : 0; j < nb.count; ++j) {
          const std::uint32_t ti = order_[na.first + i], tj = order_[nb.first + j];
          if (!boxes_[ti].overlaps(boxes_[tj])) continue;
          if (++tested > limit) return;
          glm::vec3 from, to;
          if (triangleIntersection(tris_[ti].data(), tris_[tj].data(), from, to)) {
            // Lit (colour=tone) as the mean of the two surfaces that meet there.
            const auto unitNormal = [&](std::uint32_t t) {
              const glm::vec3 n = glm::cross(tris_[t][1] - tris_[t][0], tris_[t][2] - tris_[t][0]);
              const float l = glm::length(n);
              return l > 0.0f ? n / l : glm::vec3(0.0f);
            };
            FeatureLine l{from, to, float(EdgeKind::Intersection)};
            const glm::vec3 n = unitNormal(ti) + unitNormal(tj);
            if (glm::length(n) > 1e-6f) l.attributes.normal = glm::normalize(n);
            out.push_back(l);
          }
        }
      return;
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> children;
    split(a, b, children);
    for (auto [c, d] : children) search(c, d, out, tested, limit);
  }

 private:
  std::uint32_t build(std::uint32_t first, std::uint32_t count) {
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    Box box, centres;
    for (std::uint32_t i = first; i < first + count; ++i) {
      box.add(boxes_[order_[i]]);
      centres.add(centres_[order_[i]]);
    }
    nodes_[index].box = box;
    const glm::vec3 extent = centres.hi - centres.lo;
    if (count <= kLeafSize || !(glm::max(extent.x, glm::max(extent.y, extent.z)) > 0.0f)) {
      nodes_[index].first = first;
      nodes_[index].count = count;
      return index;
    }
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::uint32_t half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](std::uint32_t p, std::uint32_t q) { return centres_[p][axis] < centres_[q][axis]; });
    const std::uint32_t left = build(first, half);
    const std::uint32_t right = build(first + half, count - half);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  // The child pairs of (a, b) to search: a node against itself is its children against
  // themselves and each other; two nodes split the one that is not a leaf, the larger first.
  void split(std::uint32_t a, std::uint32_t b, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const {
    const Node& na = nodes_[a];
    const Node& nb = nodes_[b];
    if (a != b && !na.box.overlaps(nb.box)) return;
    if (na.leaf() && nb.leaf()) {
      out.push_back({a, b});
      return;
    }
    if (a == b) {
      out.push_back({na.left, na.left});
      out.push_back({na.right, na.right});
      out.push_back({na.left, na.right});
      return;
    }
    const bool splitA = nb.leaf() || (!na.leaf() && volume(na.box) >= volume(nb.box));
    if (splitA) {
      out.push_back({na.left, b});
      out.push_back({na.right, b});
    } else {
      out.push_back({a, nb.left});
      out.push_back({a, nb.right});
    }
  }

  static float volume(const Box& b) {
    const glm::vec3 e = b.hi - b.lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;  // half the surface: what decides overlaps
  }

  const std::vector<WorldTriangle>& tris_;
  std::vector<Box> boxes_;
  std::vector<glm::vec3> centres_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

// Where a triangle meets a plane, from its corners' signed distances to it (zero: on it).
int meetPlane(const glm::dvec3 t[3], const double d[3], glm::dvec3 out[3]) {
  int n = 0;
  for (int i = 0; i < 3; ++i)
    if (d[i] == 0.0) out[n++] = t[i];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if ((d[i] < 0.0 && d[j] > 0.0) || (d[i] > 0.0 && d[j] < 0.0)) out[n++] = t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j]));
  }
  return n;
}

// Signed distances (scaled by the normal's length) of `t`'s corners to the plane of `p`, those
// within rounding of it set to zero. False when all lie on one side.
bool planeDistances(const glm::dvec3 t[3], const glm::dvec3 p[3], double tolerance, double d[3], glm::dvec3& normal) {
  normal = glm::cross(p[1] - p[0], p[2] - p[0]);
  const double length = glm::length(normal);
  if (!(length > 0.0)) return false;
  int above = 0, below = 0;
  for (int i = 0; i < 3; ++i) {
    d[i] = glm::dot(normal, t[i] - p[0]);
    if (std::abs(d[i]) <= tolerance * length) d[i] = 0.0;
    above += d[i] > 0.0;
    below += d[i] < 0.0;
  }
  return !(above == 3 || below == 3 || (above == 0 && below == 0));
}

}  // namespace

bool triangleIntersection(const glm::vec3 a[3], const glm::vec3 b[3], glm::vec3& from, glm::vec3& to) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[i] == b[j]) return false;  // neighbours on one surface meet along what they share
  const glm::dvec3 ta[3] = {a[0], a[1], a[2]}, tb[3] = {b[0], b[1], b[2]};
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) scale = std::max({scale, glm::length(ta[(i + 1) % 3] - ta[i]), glm::length(tb[(i + 1) % 3] - tb[i])});
  // Distances below a millionth of the triangles' size are rounding: float corners stored in
  // world space carry about 1e-7 of it.
  const double tolerance = 1e-6 * scale;
  double da[3], db[3];
  glm::dvec3 na, nb;
  if (!planeDistances(ta, tb, tolerance, da, nb) || !planeDistances(tb, ta, tolerance, db, na)) return false;
  glm::dvec3 pa[3], pb[3];
  if (meetPlane(ta, da, pa) < 2 || meetPlane(tb, db, pb) < 2) return false;
  // Both meeting segments lie on the planes' common line: what they share is the answer.
  const glm::dvec3 line = glm::cross(na, nb);
  auto order = [&](glm::dvec3 p[2], double t[2]) {
    t[0] = glm::dot(line, p[0]);
    t[1] = glm::dot(line, p[1]);
    if (t[0] > t[1]) {
      std::swap(t[0], t[1]);
      std::swap(p[0], p[1]);
    }
  };
  double sa[2], sb[2];
  order(pa, sa);
  order(pb, sb);
  const glm::dvec3 start = sa[0] > sb[0] ? pa[0] : pb[0];
  const glm::dvec3 end = sa[1] < sb[1] ? pa[1] : pb[1];
  if (std::min(sa[1], sb[1]) - std::max(sa[0], sb[0]) <= tolerance * glm::length(line)) return false;  // a point
  from = glm::vec3(start);
  to = glm::vec3(end);
  return true;
}

std::vector<FeatureLine> intersectionLines(const std::vector<IntersectionObject>& objects, IntersectionCounts* counts, std::size_t maxPairs) {
  std::vector<WorldTriangle> tris;
  std::size_t total = 0;
  for (const IntersectionObject& o : objects) total += o.mesh ? o.mesh->triangleCount() : 0;
  tris.reserve(total);
  for (const IntersectionObject& o : objects) {
    if (!o.mesh) continue;
    const Mesh& m = *o.mesh;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
      WorldTriangle tri;
      for (int k = 0; k < 3; ++k) tri[std::size_t(k)] = glm::vec3(o.transform * glm::vec4(m.positions[m.indices[3 * t + std::size_t(k)]], 1.0f));
      // Zero-area and non-finite triangles cross nothing.
      const glm::vec3 n = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
      if (std::isfinite(n.x + n.y + n.z) && glm::dot(n, n) > 0.0f) tris.push_back(tri);
    }
  }
  const Hierarchy bvh(tris);
  const int workers = workerCount();
  const auto tasks = bvh.tasks(std::size_t(64 * workers));
  std::vector<std::vector<FeatureLine>> parts(static_cast<std::size_t>(workers));
  std::vector<std::size_t> tested(static_cast<std::size_t>(workers), 0);
  // Each thread's share of the pair budget: piles of coincident triangles (a doubled or
  // degenerate file) overlap all with all, and must not hang the frame.
  const std::size_t share = std::max<std::size_t>(1, maxPairs / std::size_t(workers));
  parallelChunks(
      tasks.size(), workers,
      [&](std::size_t b, std::size_t e, int c) {
        for (std::size_t i = b; i < e; ++i) bvh.search(tasks[i].first, tasks[i].second, parts[std::size_t(c)], tested[std::size_t(c)], share);
      },
      1);
  std::vector<FeatureLine> out;
  std::size_t pairs = 0;
  bool stopped = false;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    out.insert(out.end(), parts[c].begin(), parts[c].end());
    pairs += std::min(tested[c], share);
    stopped = stopped || tested[c] > share;
  }
  if (counts) *counts = {tris.size(), tasks.size(), pairs, out.size(), stopped};
  return out;
}

}  // namespace npr
