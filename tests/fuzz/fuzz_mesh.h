// What every mesh harness checks on a mesh a reader accepted: the invariants the renderer
// relies on (finite positions and normals inside the unit sphere, indices in range). A
// violation traps, so libFuzzer reports it like a crash.
#pragma once

#include <cmath>

#include "renderer/core/result.h"
#include "renderer/mesh/mesh.h"

namespace npr::fuzz {

inline void checkMesh(Result<Mesh>& m) {
  if (!m) {
    if (m.error().empty()) __builtin_trap();  // every refusal says why
    return;
  }
  finalizeMesh(*m);
  const std::size_t nv = m->positions.size();
  if (m->indices.size() != m->triangleCount() * 3 || m->normals.size() != nv) __builtin_trap();
  for (std::uint32_t i : m->indices)
    if (i >= nv) __builtin_trap();
  for (std::size_t i = 0; i < nv; ++i) {
    const glm::vec3& p = m->positions[i];
    const glm::vec3& n = m->normals[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) __builtin_trap();
    if (glm::length(p) > 1.0f + 1e-3f) __builtin_trap();
  }
  // Something to draw: faces, or a file's points and lines, finite and in the unit sphere, the
  // lines' ends in pairs.
  if (m->indices.empty() && !m->hasMarks()) __builtin_trap();
  if (m->segments.size() % 2) __builtin_trap();
  for (const std::vector<glm::vec3>* marks : {&m->dots, &m->segments})
    for (const glm::vec3& p : *marks)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || glm::length(p) > 1.0f + 1e-3f) __builtin_trap();
  // The appearance (OBJ): every array empty or one entry per vertex / triangle, every index in
  // range, texture coordinates finite.
  const std::size_t nf = m->triangleCount();
  if (!m->colours.empty() && m->colours.size() != nv) __builtin_trap();
  if (!m->texcoords.empty() && m->texcoords.size() != nv) __builtin_trap();
  if (!m->sourceVertex.empty() && m->sourceVertex.size() != nv) __builtin_trap();
  if (!m->faceMaterials.empty() && m->faceMaterials.size() != nf) __builtin_trap();
  if (!m->faceTints.empty() && m->faceTints.size() != nf) __builtin_trap();
  for (std::uint16_t f : m->faceMaterials)
    if (f >= m->materials.size()) __builtin_trap();
  for (const glm::vec2& t : m->texcoords)
    if (!std::isfinite(t.x) || !std::isfinite(t.y)) __builtin_trap();
  for (const glm::vec3& t : m->faceTints)
    if (!(t.r >= 0.0f && t.r <= 1.0f && t.g >= 0.0f && t.g <= 1.0f && t.b >= 0.0f && t.b <= 1.0f)) __builtin_trap();
}

}  // namespace npr::fuzz
