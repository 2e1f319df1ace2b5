// Morphing and skinning on the CPU (see deformation.h).
#include "renderer/animation/deformation.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/parallel.h"

namespace npr {

void deformMesh(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights, Mesh& posed,
                const std::vector<glm::vec3>* restTangents, std::vector<glm::vec3>* posedTangents) {
  const MeshDeformation& d = rest.deformation;
  const std::size_t nv = rest.positions.size();
  posed.positions.resize(nv);
  posed.normals.resize(nv);
  // Only the targets with a weight: a 64-target face moving three of them pays for three.
  std::vector<std::size_t> active;
  for (std::size_t t = 0; t < d.targets() && t < weights.size(); ++t)
    if (weights[t] != 0.0f && std::isfinite(weights[t])) active.push_back(t);
  const bool skinned = d.skinned() && d.joints.size() == nv && d.weights.size() == nv && !joints.empty();
  const bool tangents = restTangents && posedTangents && restTangents->size() == nv;
  if (tangents) posedTangents->resize(nv);
  const int chunks = workerCount();
  std::vector<float> radius2(static_cast<std::size_t>(chunks), 0.0f);
  parallelChunks(nv, chunks, [&](std::size_t b, std::size_t e, int c) {
    float r2 = 0.0f;
    for (std::size_t i = b; i < e; ++i) {
      glm::vec3 p = rest.positions[i], n = rest.normals[i];
      glm::vec3 tangent = tangents ? (*restTangents)[i] : glm::vec3(0.0f);
      for (std::size_t t : active) {
        p += weights[t] * d.targetPositions[t][i];
        n += weights[t] * d.targetNormals[t][i];
      }
      if (skinned) {
        const glm::vec4& w = d.weights[i];
        if (w.x + w.y + w.z + w.w > 0.0f) {
          const glm::u16vec4& j = d.joints[i];
          const auto at = [&](std::uint16_t k) -> const glm::mat4& { return joints[std::min<std::size_t>(k, joints.size() - 1)]; };
          const glm::mat4 m = w.x * at(j.x) + w.y * at(j.y) + w.z * at(j.z) + w.w * at(j.w);
          p = glm::vec3(m * glm::vec4(p, 1.0f));
          n = glm::mat3(m) * n;
          tangent = glm::mat3(m) * tangent;
        }
      }
      if (tangents) (*posedTangents)[i] = tangent;
      const float len = glm::length(n);
      posed.positions[i] = p;
      posed.normals[i] = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
      r2 = std::max(r2, glm::dot(p, p));
    }
    radius2[static_cast<std::size_t>(c)] = r2;
  });
  if (posed.indices.size() != rest.indices.size()) posed.indices = rest.indices;
  updateFaceGeometry(posed);
  const float r2 = *std::max_element(radius2.begin(), radius2.end());
  posed.radius = r2 > 0.0f && std::isfinite(r2) ? std::sqrt(r2) : rest.radius;
}

}  // namespace npr
