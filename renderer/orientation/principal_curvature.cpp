// Per-face curvature fits accumulated at the vertices (see principal_curvature.h).
#include "renderer/orientation/principal_curvature.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/parallel.h"

namespace npr {
namespace {

// A face's second fundamental form in its own frame (u, v): II = [[a, b], [b, c]].
struct FaceForm {
  glm::vec3 u{0.0f}, v{0.0f}, n{0.0f};
  float a = 0, b = 0, c = 0, area = 0;
};

glm::vec3 safeNormalize(const glm::vec3& x) {
  const float l = glm::length(x);
  return l > 1e-30f && std::isfinite(l) ? x / l : glm::vec3(0.0f);
}

// Least squares for II from the three edges: II e = dn in the face frame, two equations per
// edge, three unknowns.
FaceForm fitFace(const glm::vec3 p[3], const glm::vec3 n[3]) {
  FaceForm f;
  const glm::vec3 e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};
  const glm::vec3 cr = glm::cross(e[0], e[1]);
  f.area = 0.5f * glm::length(cr);
  f.n = safeNormalize(cr);
  f.u = safeNormalize(e[0]);
  if (!(f.area > 0.0f) || f.n == glm::vec3(0.0f) || f.u == glm::vec3(0.0f)) {
    f.area = 0.0f;
    return f;
  }
  f.v = glm::cross(f.n, f.u);
  const glm::vec3 dn[3] = {n[2] - n[1], n[0] - n[2], n[1] - n[0]};
  double m00 = 0, m01 = 0, m11 = 0, m12 = 0, m22 = 0, r0 = 0, r1 = 0, r2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double eu = glm::dot(e[i], f.u), ev = glm::dot(e[i], f.v);
    const double nu = glm::dot(dn[i], f.u), nv = glm::dot(dn[i], f.v);
    // rows (eu, ev, 0) x = nu and (0, eu, ev) x = nv
    m00 += eu * eu;
    m01 += eu * ev;
    m11 += eu * eu + ev * ev;
    m12 += eu * ev;
    m22 += ev * ev;
    r0 += eu * nu;
    r1 += ev * nu + eu * nv;
    r2 += ev * nv;
  }
  // Symmetric 3x3 [[m00, m01, 0], [m01, m11, m12], [0, m12, m22]] by Cramer's rule.
  const double det = m00 * (m11 * m22 - m12 * m12) - m01 * (m01 * m22);
  const double scale = m00 * m11 * m22;
  if (!(std::fabs(det) > 1e-12 * std::max(scale, 1e-300))) {
    f.area = 0.0f;
    return f;
  }
  const double x0 = (r0 * (m11 * m22 - m12 * m12) - m01 * (r1 * m22 - m12 * r2)) / det;
  const double x1 = (m00 * (r1 * m22 - m12 * r2) - r0 * (m01 * m22)) / det;
  const double x2 = (m00 * (m11 * r2 - m12 * r1) - m01 * m01 * r2 + r0 * m01 * m12) / det;
  f.a = float(x0);
  f.b = float(x1);
  f.c = float(x2);
  if (!std::isfinite(f.a) || !std::isfinite(f.b) || !std::isfinite(f.c)) f.area = 0.0f;
  return f;
}

// Turns a tangent vector x of the plane with normal `from` into the plane with normal `to`
// by the smallest rotation taking one normal to the other.
glm::vec3 rotateTangent(const glm::vec3& x, const glm::vec3& from, const glm::vec3& to) {
  const float d = glm::dot(from, to);
  if (d <= -0.9999f) return -x;
  return x - (glm::dot(to, x) / (1.0f + d)) * (from + to);
}

}  // namespace

void tangentBasis(const glm::vec3& n, glm::vec3& t1, glm::vec3& t2) {
  const glm::vec3 helper = std::fabs(n.x) < 0.8f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t1 = safeNormalize(glm::cross(helper, n));
  if (t1 == glm::vec3(0.0f)) t1 = glm::vec3(1, 0, 0);
  t2 = glm::cross(n, t1);
}

PrincipalCurvatures estimatePrincipalCurvatures(const Mesh& m) {
  PrincipalCurvatures pc;
  pc.weld = weldPositions(m.positions);
  const std::vector<glm::vec3>& P = pc.weld.positions;
  const std::size_t nv = P.size();
  pc.triangles.reserve(m.triangleCount());
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const std::array<std::uint32_t, 3> f = {pc.weld.remap[m.indices[t * 3]], pc.weld.remap[m.indices[t * 3 + 1]],
                                            pc.weld.remap[m.indices[t * 3 + 2]]};
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
    const float area2 = glm::length(glm::cross(P[f[1]] - P[f[0]], P[f[2]] - P[f[0]]));
    if (area2 > 0.0f && std::isfinite(area2)) pc.triangles.push_back(f);
  }
  const std::size_t nf = pc.triangles.size();

  // Faces around each vertex and edge neighbours, as compressed rows.
  std::vector<std::uint32_t> faceStart(nv + 1, 0), faces(nf * 3);
  for (const auto& f : pc.triangles)
    for (std::uint32_t v : f) ++faceStart[v + 1];
  for (std::size_t v = 0; v < nv; ++v) faceStart[v + 1] += faceStart[v];
  {
    std::vector<std::uint32_t> fill(faceStart.begin(), faceStart.end() - 1);
    for (std::size_t t = 0; t < nf; ++t)
      for (std::uint32_t v : pc.triangles[t]) faces[fill[v]++] = std::uint32_t(t);
  }
  pc.neighbourStart.assign(nv + 1, 0);
  {
    std::vector<std::uint32_t> scratch;
    pc.neighbours.reserve(nf * 3 + 16);
    for (std::size_t v = 0; v < nv; ++v) {
      scratch.clear();
      for (std::uint32_t k = faceStart[v]; k < faceStart[v + 1]; ++k)
        for (std::uint32_t w : pc.triangles[faces[k]])
          if (w != v) scratch.push_back(w);
      std::sort(scratch.begin(), scratch.end());
      scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
      pc.neighbours.insert(pc.neighbours.end(), scratch.begin(), scratch.end());
      pc.neighbourStart[v + 1] = std::uint32_t(pc.neighbours.size());
    }
  }

  // Area-weighted vertex normals (the unnormalised cross product is twice the area).
  pc.normals.assign(nv, glm::vec3(0.0f));
  const int workers = workerCount();
  parallelChunks(nv, workers, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t v = b; v < e; ++v) {
      glm::vec3 s(0.0f);
      for (std::uint32_t k = faceStart[v]; k < faceStart[v + 1]; ++k) {
        const auto& f = pc.triangles[faces[k]];
        s += glm::cross(P[f[1]] - P[f[0]], P[f[2]] - P[f[0]]);
      }
      pc.normals[v] = safeNormalize(s);
    }
  });

  std::vector<FaceForm> forms(nf);
  parallelChunks(nf, workers, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t t = b; t < e; ++t) {
      const auto& f = pc.triangles[t];
      const glm::vec3 p[3] = {P[f[0]], P[f[1]], P[f[2]]};
      const glm::vec3 n[3] = {pc.normals[f[0]], pc.normals[f[1]], pc.normals[f[2]]};
      forms[t] = fitFace(p, n);
    }
  });

  pc.maxDirection.assign(nv, glm::vec3(0.0f));
  pc.kMax.assign(nv, 0.0f);
  pc.kMin.assign(nv, 0.0f);
  parallelChunks(nv, workers, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t v = b; v < e; ++v) {
      const glm::vec3 n = pc.normals[v];
      if (n == glm::vec3(0.0f)) continue;
      glm::vec3 t1, t2;
      tangentBasis(n, t1, t2);
      double A = 0, B = 0, C = 0, W = 0;
      for (std::uint32_t k = faceStart[v]; k < faceStart[v + 1]; ++k) {
        const FaceForm& f = forms[faces[k]];
        if (f.area <= 0.0f) continue;
        const glm::vec3 u = rotateTangent(f.u, f.n, n), w = rotateTangent(f.v, f.n, n);
        // II(x, y) for x, y in the vertex frame, through the face frame.
        const double u1 = glm::dot(u, t1), u2 = glm::dot(u, t2), w1 = glm::dot(w, t1), w2 = glm::dot(w, t2);
        A += f.area * (f.a * u1 * u1 + 2.0 * f.b * u1 * w1 + f.c * w1 * w1);
        B += f.area * (f.a * u1 * u2 + f.b * (u1 * w2 + w1 * u2) + f.c * w1 * w2);
        C += f.area * (f.a * u2 * u2 + 2.0 * f.b * u2 * w2 + f.c * w2 * w2);
        W += f.area;
      }
      if (!(W > 0.0)) continue;
      A /= W;
      B /= W;
      C /= W;
      const double mean = 0.5 * (A + C), half = std::sqrt(0.25 * (A - C) * (A - C) + B * B);
      const double l1 = mean + half, l2 = mean - half;
      double angle = 0.5 * std::atan2(2.0 * B, A - C);  // eigenvector of l1
      double kmax = l1, kmin = l2;
      if (std::fabs(l2) > std::fabs(l1)) {
        angle += 0.5 * M_PI;
        kmax = l2;
        kmin = l1;
      }
      if (!std::isfinite(angle) || !std::isfinite(kmax) || !std::isfinite(kmin)) continue;
      pc.maxDirection[v] = safeNormalize(float(std::cos(angle)) * t1 + float(std::sin(angle)) * t2);
      pc.kMax[v] = float(kmax);
      pc.kMin[v] = float(kmin);
    }
  });
  return pc;
}

}  // namespace npr
