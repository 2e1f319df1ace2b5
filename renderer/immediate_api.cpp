// The original renderer's immediate interface over the retained machinery (see immediate_api.h).
#include "renderer/immediate_api.h"

#include <cmath>

#include "renderer/palette/palette_matcher.h"

namespace npr {

Mesh meshFromTriangles(const std::vector<Triangle>& triangles) {
  Mesh m;
  m.report.file = "(immediate triangles)";
  const size_t n = triangles.size();
  m.positions.resize(n * 3);
  m.normals.resize(n * 3);
  m.indices.resize(n * 3);
  m.faceCentroids.resize(n);
  m.faceNormals.resize(n);
  float r2 = 0.0f;
  for (size_t t = 0; t < n; ++t) {
    const auto& v = triangles[t].v;
    const glm::vec3 c = glm::cross(v[1] - v[0], v[2] - v[0]);
    const float len = glm::length(c);
    const glm::vec3 fn = len > 0.0f && std::isfinite(len) ? c / len : glm::vec3(0.0f);
    m.faceNormals[t] = fn;
    m.faceCentroids[t] = (v[0] + v[1] + v[2]) / 3.0f;
    for (int k = 0; k < 3; ++k) {
      m.positions[t * 3 + size_t(k)] = v[size_t(k)];
      m.normals[t * 3 + size_t(k)] = fn == glm::vec3(0.0f) ? glm::vec3(0, 0, 1) : fn;
      m.indices[t * 3 + size_t(k)] = static_cast<std::uint32_t>(t * 3 + size_t(k));
      r2 = std::max(r2, glm::dot(v[size_t(k)], v[size_t(k)]));
    }
  }
  m.radius = r2 > 0.0f ? std::sqrt(r2) : 1.0f;
  m.report.vertices = n * 3;
  m.report.triangles = n;
  return m;
}

Status PaletteRenderer::IntensityRangeScale(float scale) {
  if (Status s = PaletteMatcher::validateRangeScale(scale); !s) return s;
  settings_.rangeScale = scale;
  return okStatus();
}

namespace {
bool sameMaterial(const Material& a, const Material& b) {
  return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular && a.emission == b.emission &&
         a.shininess == b.shininess;
}
}  // namespace

void PaletteRenderer::Begin() {
  pending_.clear();
  materials_.assign(1, renderer_.lighting().front());
  triangleMaterials_.clear();
  begun_ = true;
}

void PaletteRenderer::RenderTriangle(const Triangle& tri) {
  if (!begun_) return;
  // OpenGL's semantics: a Materialfv between triangles applies to the triangles after it.
  const Material& now = renderer_.lighting().front();
  if (!sameMaterial(now, materials_.back()) && materials_.size() < 0xFFFF) materials_.push_back(now);
  pending_.push_back(tri);
  triangleMaterials_.push_back(static_cast<std::uint16_t>(materials_.size() - 1));
}

Status PaletteRenderer::End(const CameraMatrices& camera, const glm::ivec4& viewport) {
  if (!begun_) return Error{"End() without Begin()"};
  begun_ = false;
  mesh_ = meshFromTriangles(pending_);
  if (materials_.size() > 1) {
    // Several materials were set while drawing: each triangle keeps the one current when it
    // was given (the mesh's own materials; its vertices are not shared, so one per vertex).
    for (const Material& m : materials_) {
      MeshMaterial mm;
      mm.name = "Materialfv " + std::to_string(mesh_.materials.size());
      mm.ambient = glm::vec3(m.ambient);
      mm.diffuse = glm::vec3(m.diffuse);
      mm.specular = glm::vec3(m.specular);
      mm.emission = glm::vec3(m.emission);
      mm.shininess = m.shininess;
      mesh_.materials.push_back(mm);
    }
    mesh_.faceMaterials = triangleMaterials_;
  }
  renderer_.scene().setOnly(&mesh_);
  RenderSettings s = settings_;
  s.materials = true;
  return renderer_.render(camera, s, viewport);
}

}  // namespace npr
