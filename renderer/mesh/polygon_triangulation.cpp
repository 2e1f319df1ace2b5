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

  std::vector<int> ring(n);
  for (int i = 0; i < n; ++i) ring[i] = i;
  int guard = 0;
  while (ring.size() > 3 && guard < n * n) {
    ++guard;
    bool clipped = false;
    const int m = static_cast<int>(ring.size());
    for (int k = 0; k < m; ++k) {
      const int i0 = ring[(k + m - 1) % m], i1 = ring[k], i2 = ring[(k + 1) % m];
      if (cross2(p[i0], p[i1], p[i2]) <= 0) continue;  // reflex or degenerate corner
      bool inside = false;
      for (int j : ring) {
        if (j == i0 || j == i1 || j == i2) continue;
        if (pointInTriangle(p[j], p[i0], p[i1], p[i2])) { inside = true; break; }
      }
      if (inside) continue;
      tris.insert(tris.end(), {i0, i1, i2});
      ring.erase(ring.begin() + k);
      clipped = true;
      break;
    }
    if (!clipped) break;  // degenerate or self-intersecting: finish with a fan below
  }
  // What is left (a triangle, or a polygon with no ear) is fanned so coverage stays n-2 triangles.
  for (size_t k = 1; k + 1 < ring.size(); ++k) tris.insert(tris.end(), {ring[0], ring[k], ring[k + 1]});
  return tris;
}

}  // namespace npr
