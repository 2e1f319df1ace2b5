// Suggestive contours from the radial curvature's zeros (see suggestive_contours.h).
#include "renderer/lines/suggestive_contours.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/parallel.h"

namespace npr {

SuggestiveContours::SuggestiveContours(const Mesh& mesh) : mesh_(&mesh), radius_(std::max(mesh.radius, 1e-6f)) {}

const std::vector<FeatureLine>& SuggestiveContours::lines(const glm::vec3& eye, float threshold) {
  if (!curvature_) curvature_ = std::make_unique<PrincipalCurvatures>(estimatePrincipalCurvatures(*mesh_));
  const PrincipalCurvatures& pc = *curvature_;
  const std::vector<glm::vec3>& pos = pc.weld.positions;
  const std::size_t nv = pos.size(), nf = pc.triangles.size();
  radial_.assign(nv, 0.0f);
  facing_.assign(nv, 0.0f);
  tangentView_.assign(nv, glm::vec3(0.0f));
  const int chunks = workerCount();
  // Per vertex: n.v, w (the view vector in the tangent plane) and kappa_r = k1 cos^2 + k2 sin^2
  // of w's angle to the first principal direction.
  parallelChunks(nv, chunks, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t v = b; v < e; ++v) {
      const float ln = glm::length(pc.normals[v]);
      const glm::vec3 toEye = eye - pos[v];
      const float d = glm::length(toEye);
      if (!(ln > 0.0f) || !(d > 0.0f)) continue;
      const glm::vec3 n = pc.normals[v] / ln;
      const glm::vec3 view = toEye / d;
      const glm::vec3 w = view - glm::dot(view, n) * n;
      const glm::vec3 e1 = pc.maxDirection[v], e2 = glm::cross(n, e1);
      const float u1 = glm::dot(w, e1), u2 = glm::dot(w, e2), ww = u1 * u1 + u2 * u2;
      facing_[v] = glm::dot(n, view);
      tangentView_[v] = w;
      radial_[v] = ww > 1e-12f ? (pc.kMax[v] * u1 * u1 + pc.kMin[v] * u2 * u2) / ww : 0.0f;
    }
  });
  const float minDerivative = threshold / (radius_ * radius_);
  std::vector<std::vector<FeatureLine>> parts(static_cast<std::size_t>(chunks));
  parallelChunks(nf, chunks, [&](std::size_t b, std::size_t e, int c) {
    auto& out = parts[static_cast<std::size_t>(c)];
    for (std::size_t f = b; f < e; ++f) {
      const auto& t = pc.triangles[f];
      const float k[3] = {radial_[t[0]], radial_[t[1]], radial_[t[2]]};
      // A zero of kappa_r crosses the face: signs differ (a vertex exactly at zero counts as positive).
      const bool pos0 = k[0] >= 0.0f, pos1 = k[1] >= 0.0f, pos2 = k[2] >= 0.0f;
      if (pos0 == pos1 && pos1 == pos2) continue;
      if ((facing_[t[0]] + facing_[t[1]] + facing_[t[2]]) / 3.0f < kMinFacing) continue;
      const glm::vec3 p0 = pos[t[0]], p1 = pos[t[1]], p2 = pos[t[2]];
      // The face's gradient of kappa_r (linear over it), along w at its centre.
      const glm::vec3 e1 = p1 - p0, e2 = p2 - p0, normal = glm::cross(e1, e2);
      const float area2 = glm::dot(normal, normal);
      if (!(area2 > 0.0f)) continue;
      const glm::vec3 gradient = ((k[1] - k[0]) * glm::cross(e2, normal) + (k[2] - k[0]) * glm::cross(normal, e1)) / area2;
      const glm::vec3 w = tangentView_[t[0]] + tangentView_[t[1]] + tangentView_[t[2]];
      const float lw = glm::length(w);
      const float derivative = lw > 0.0f ? glm::dot(gradient, w) / lw : 0.0f;
      if (!(derivative > minDerivative)) continue;
      // Faded in over the threshold's first doubling, and near the silhouette over the facing
      // limit's: a contour appears at no ink as the view turns, rather than popping in whole
      // (DeCarlo, Finkelstein and Rusinkiewicz 2004).
      const float facing = (facing_[t[0]] + facing_[t[1]] + facing_[t[2]]) / 3.0f;
      const float ink = std::clamp(derivative / minDerivative - 1.0f, 0.0f, 1.0f) * std::clamp(facing / kMinFacing - 1.0f, 0.0f, 1.0f);
      // The two edges whose ends differ in sign, cut where kappa_r interpolates to zero.
      glm::vec3 ends[2];
      int found = 0;
      const glm::vec3 p[3] = {p0, p1, p2};
      const bool s[3] = {pos0, pos1, pos2};
      for (int a = 0; a < 3 && found < 2; ++a) {
        const int bEnd = (a + 1) % 3;
        if (s[a] == s[bEnd]) continue;
        const float along = k[a] / (k[a] - k[bEnd]);
        ends[found++] = p[a] + (p[bEnd] - p[a]) * std::clamp(along, 0.0f, 1.0f);
      }
      if (found == 2 && ink > 0.0f) {
        FeatureLine l{ends[0], ends[1], float(EdgeKind::Suggestive)};
        l.attributes.ink = ink;
        l.attributes.normal = normal / std::sqrt(area2);
        out.push_back(l);
      }
    }
  });
  lines_.clear();
  for (auto& part : parts) lines_.insert(lines_.end(), part.begin(), part.end());
  return lines_;
}

}  // namespace npr
