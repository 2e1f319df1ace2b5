// Morphing and skinning on the CPU (see deformation.h).
#include "renderer/animation/deformation.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/parallel.h"

namespace npr {

namespace {

// What a pose needs per vertex: the targets with a weight and whether the skin applies.
struct PoseInputs {
  const Mesh& rest;
  const std::vector<glm::mat4>& joints;
  const std::vector<float>& weights;
  std::vector<std::size_t> active;
  bool skinned;
  PoseInputs(const Mesh& r, const std::vector<glm::mat4>& j, const std::vector<float>& w) : rest(r), joints(j), weights(w) {
    const MeshDeformation& d = r.deformation;
    // Only the targets with a weight: a 64-target face moving three of them pays for three.
    for (std::size_t t = 0; t < d.targets() && t < w.size(); ++t)
      if (w[t] != 0.0f && std::isfinite(w[t])) active.push_back(t);
    const std::size_t nv = r.positions.size();
    skinned = d.skinned() && d.joints.size() == nv && d.weights.size() == nv && !j.empty();
  }
  // Vertex `i` posed: its position, unit normal and (carried by the skin alone) `tangent`.
  void vertex(std::size_t i, glm::vec3& p, glm::vec3& n, glm::vec3* tangent) const {
    const MeshDeformation& d = rest.deformation;
    p = rest.positions[i];
    n = rest.normals[i];
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
        if (tangent) *tangent = glm::mat3(m) * *tangent;
      }
    }
    const float len = glm::length(n);
    n = len > 0.0f && std::isfinite(len) ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  }
};

}  // namespace

void deformMesh(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights, Mesh& posed,
                const std::vector<glm::vec3>* restTangents, std::vector<glm::vec3>* posedTangents) {
  const std::size_t nv = rest.positions.size();
  posed.positions.resize(nv);
  posed.normals.resize(nv);
  const PoseInputs in(rest, joints, weights);
  const bool tangents = restTangents && posedTangents && restTangents->size() == nv;
  if (tangents) posedTangents->resize(nv);
  const int chunks = workerCount();
  std::vector<float> radius2(static_cast<std::size_t>(chunks), 0.0f);
  parallelChunks(nv, chunks, [&](std::size_t b, std::size_t e, int c) {
    float r2 = 0.0f;
    for (std::size_t i = b; i < e; ++i) {
      glm::vec3 tangent = tangents ? (*restTangents)[i] : glm::vec3(0.0f);
      in.vertex(i, posed.positions[i], posed.normals[i], tangents ? &tangent : nullptr);
      if (tangents) (*posedTangents)[i] = tangent;
      r2 = std::max(r2, glm::dot(posed.positions[i], posed.positions[i]));
    }
    radius2[static_cast<std::size_t>(c)] = r2;
  });
  if (posed.indices.size() != rest.indices.size()) posed.indices = rest.indices;
  updateFaceGeometry(posed);
  const float r2 = *std::max_element(radius2.begin(), radius2.end());
  posed.radius = r2 > 0.0f && std::isfinite(r2) ? std::sqrt(r2) : rest.radius;
}

void deformFaces(const Mesh& rest, const std::vector<glm::mat4>& joints, const std::vector<float>& weights, Mesh& posed, std::size_t first,
                 std::size_t stride) {
  const std::size_t nf = rest.triangleCount();
  if (stride == 0 || posed.positions.size() != rest.positions.size() || posed.indices.size() != rest.indices.size() ||
      posed.faceCentroids.size() != nf || posed.faceNormals.size() != nf)
    return;
  const PoseInputs in(rest, joints, weights);
  for (std::size_t f = first; f < nf; f += stride) {
    const std::uint32_t* v = &rest.indices[3 * f];
    for (int k = 0; k < 3; ++k) in.vertex(v[k], posed.positions[v[k]], posed.normals[v[k]], nullptr);
    const glm::vec3 a = posed.positions[v[0]], b = posed.positions[v[1]], c = posed.positions[v[2]];
    const glm::vec3 cr = glm::cross(b - a, c - a);
    const float len = glm::length(cr);
    posed.faceCentroids[f] = (a + b + c) / 3.0f;
    posed.faceNormals[f] = len > 0.0f && std::isfinite(len) ? cr / len : glm::vec3(0.0f);
  }
}

}  // namespace npr
