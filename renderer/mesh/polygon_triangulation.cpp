// Ear clipping (see polygon_triangulation.h).
#include "renderer/mesh/polygon_triangulation.h"

namespace npr {
namespace {

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool pointInTriangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double d1 = cross2(a, b, p), d2 = cross2(b, c, p), d3 = cross2(c, a, p);
  return d1 >= 0 && d2 >= 0 && d3 >= 0;
}

}  // namespace

std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly) {
  TriangulationBudget unlimited{INT64_MAX};
  return triangulatePolygon(poly, unlimited);
}

std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly, TriangulationBudget& budget) {
  const int n = static_cast<int>(poly.size());
  std::vector<int> tris;
  if (n < 3) return tris;
  tris.reserve(static_cast<size_t>(n - 2) * 3);
  if (n == 3) return {0, 1, 2};
  // Newell normal gives the polygon's plane even for concave polygons; drop its largest axis.
  glm::dvec3 nrm(0.0);
  for (int i = 0; i < n; ++i) {
    const glm::dvec3& a = poly[i];
    const glm::dvec3& b = poly[(i + 1) % n];
    nrm.x += (a.y - b.y) * (a.z + b.z);
    nrm.y += (a.z - b.z) * (a.x + b.x);
    nrm.z += (a.x - b.x) * (a.y + b.y);
  }
  const glm::dvec3 an = glm::abs(nrm);
  const int drop = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = nrm[drop] >= 0 ? 1.0 : -1.0;  // makes the projected polygon counter-clockwise
  std::vector<glm::dvec2> p(n);
  for (int i = 0; i < n; ++i) p[i] = {poly[i][u], poly[i][v] * sign};

  // The ring as a doubly linked list; `reflex` lists the corners that are not strictly convex
  // (the only ones that can lie inside an ear), compacted lazily as corners turn convex or go.
  std::vector<int> prev(n), next(n);
  for (int i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  std::vector<char> isReflex(n), removed(n, 0);
  std::vector<int> reflex;
  for (int i = 0; i < n; ++i) {
    isReflex[i] = cross2(p[prev[i]], p[i], p[next[i]]) <= 0;
    if (isReflex[i]) reflex.push_back(i);
  }
  auto isEar = [&](int i1) {
    const int i0 = prev[i1], i2 = next[i1];
    if (isReflex[i1]) return false;
    std::size_t kept = 0;
    bool inside = false;
    for (std::size_t k = 0; k < reflex.size(); ++k) {
      const int j = reflex[k];
      if (removed[j] || !isReflex[j]) continue;  // compact as we go
      reflex[kept++] = j;
      if (inside || j == i0 || j == i2) continue;
      --budget.tests;
      inside = pointInTriangle(p[j], p[i0], p[i1], p[i2]);
    }
    reflex.resize(kept);
    return !inside;
  };
  int remaining = n, cur = 0, sinceClip = 0;
  while (remaining > 3 && sinceClip < remaining && !budget.exhausted()) {
    if (!isEar(cur)) {
      cur = next[cur];
      ++sinceClip;
      continue;
    }
    const int i0 = prev[cur], i2 = next[cur];
    tris.insert(tris.end(), {i0, cur, i2});
    removed[cur] = 1;
    next[i0] = i2;
    prev[i2] = i0;
    --remaining;
    for (int j : {i0, i2}) {
      const bool was = isReflex[j];
      isReflex[j] = cross2(p[prev[j]], p[j], p[next[j]]) <= 0;
      if (isReflex[j] && !was) reflex.push_back(j);  // only in self-intersecting polygons
    }
    cur = i0;
    sinceClip = 0;
  }
  // What is left (a triangle, or a polygon with no ear) is fanned so coverage stays n-2 triangles.
  const int first = cur;
  for (int k = next[first]; next[k] != first; k = next[k]) tris.insert(tris.end(), {first, k, next[k]});
  return tris;
}

}  // namespace npr
