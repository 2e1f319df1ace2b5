// Objects merged into batches for the surface passes (see scene_batches.h).
#include "renderer/scene/scene_batches.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/model.h"

namespace npr {
namespace {

bool sameMaterial(const MeshMaterial& a, const MeshMaterial& b) {
  return a.name == b.name && a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular && a.emission == b.emission &&
         a.shininess == b.shininess && a.opacity == b.opacity && a.illum == b.illum && a.alpha == b.alpha && a.alphaCutoff == b.alphaCutoff &&
         a.diffuseMap == b.diffuseMap && a.opacityMap == b.opacityMap && a.fromLightingState == b.fromLightingState;
}

// What must agree within a batch: the vertex streams drawn, the palette row's detail, the
// material where the object has one, its own palette (shared: Scene::setPalette) (a batch of one material is fitted one tone range, as its
// objects would be each: frame/tone_fit.h), and whether it is closed and opaque (a batch drops
// its back faces only where every object may).
struct BatchKey {
  bool colours, texcoords, closed;
  std::size_t materials;
  const MeshMaterial* material;
  const GpuPalette* palette;
  float detail;
  bool operator!=(const BatchKey& o) const {
    return colours != o.colours || texcoords != o.texcoords || closed != o.closed || materials != o.materials || palette != o.palette ||
           detail != o.detail ||
           (material && o.material ? !sameMaterial(*material, *o.material) : material != o.material);
  }
};
BatchKey keyOf(const Model& m) {
  const Mesh& mesh = m.mesh();
  return {!mesh.colours.empty(), !mesh.texcoords.empty(), mesh.closed && !mesh.seeThrough, mesh.materials.size(), mesh.materials.size() == 1 ? &mesh.materials[0] : nullptr,
          m.palette(), m.detail()};
}

// Interleaves the bits of three 10-bit coordinates.
std::uint32_t morton(glm::uvec3 c) {
  auto spread = [](std::uint32_t v) {
    v &= 1023u;
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
  };
  return spread(c.x) | (spread(c.y) << 1) | (spread(c.z) << 2);
}

}  // namespace

bool batchable(const Model& model) {
  const Mesh& mesh = model.mesh();
  if (mesh.triangleCount() == 0 || mesh.triangleCount() > kMaxBatchedObjectTriangles) return false;
  if (!mesh.deformation.empty() || !mesh.textures.empty() || !model.parts().empty()) return false;
  for (const MeshMaterial& m : mesh.materials)
    if (m.diffuseMap >= 0 || m.opacityMap >= 0) return false;
  // A mirroring transform would turn its faces inside out once merged.
  const float det = glm::determinant(glm::mat3(model.transform()));
  return std::isfinite(det) && det > 0.0f;
}

std::vector<std::vector<std::size_t>> groupIntoBatches(const std::vector<const Model*>& models) {
  if (models.empty()) return {};
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const Model* m : models) {
    const glm::vec3 c(m->transform()[3]);
    lo = glm::min(lo, c), hi = glm::max(hi, c);
  }
  const glm::vec3 extent = glm::max(hi - lo, glm::vec3(1e-20f));
  // Grouped by key, then along the curve within each group.
  std::vector<BatchKey> keys;
  std::vector<std::tuple<std::size_t, std::uint32_t, std::size_t>> order;
  order.reserve(models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    const BatchKey key = keyOf(*models[i]);
    std::size_t group = 0;
    while (group < keys.size() && keys[group] != key) ++group;
    if (group == keys.size()) keys.push_back(key);
    const glm::vec3 t = glm::clamp((glm::vec3(models[i]->transform()[3]) - lo) / extent, 0.0f, 1.0f);
    order.push_back({group, morton(glm::uvec3(t * 1023.0f)), i});
  }
  std::sort(order.begin(), order.end());
  std::vector<std::vector<std::size_t>> batches;
  std::vector<std::size_t> current;
  std::size_t triangles = 0;
  auto close = [&] {
    if (current.size() > 1) batches.push_back(current);
    current.clear();
    triangles = 0;
  };
  std::size_t currentGroup = 0;
  for (const auto& [group, code, i] : order) {
    const std::size_t t = models[i]->mesh().triangleCount();
    if (!current.empty() && (triangles + t > kBatchTriangles || group != currentGroup)) close();
    currentGroup = group;
    current.push_back(i);
    triangles += t;
  }
  close();
  return batches;
}

Mesh mergeObjects(const std::vector<const Model*>& models, glm::mat4& placement, std::vector<glm::vec4>* spheres) {
  Mesh out;
  std::size_t vertices = 0, triangles = 0;
  for (const Model* m : models) vertices += m->mesh().positions.size(), triangles += m->mesh().triangleCount();
  out.positions.reserve(vertices);
  out.normals.reserve(vertices);
  out.indices.reserve(3 * triangles);
  out.faceCentroids.reserve(triangles);
  out.faceNormals.reserve(triangles);
  bool closed = true;
  for (const Model* m : models) {
    const Mesh& mesh = m->mesh();
    const glm::mat4& t = m->transform();
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(t)));
    auto direction = [&](const glm::vec3& n) {
      const glm::vec3 d = normalMatrix * n;
      const float l = glm::length(d);
      return l > 0.0f && std::isfinite(l) ? d / l : glm::vec3(0.0f);
    };
    const auto base = static_cast<std::uint32_t>(out.positions.size());
    for (const glm::vec3& p : mesh.positions) out.positions.push_back(glm::vec3(t * glm::vec4(p, 1.0f)));
    for (const glm::vec3& n : mesh.normals) out.normals.push_back(direction(n));
    for (std::uint32_t i : mesh.indices) out.indices.push_back(base + i);
    for (const glm::vec3& c : mesh.faceCentroids) out.faceCentroids.push_back(glm::vec3(t * glm::vec4(c, 1.0f)));
    for (const glm::vec3& n : mesh.faceNormals) out.faceNormals.push_back(glm::dot(n, n) > 0.0f ? direction(n) : glm::vec3(0.0f));
    out.colours.insert(out.colours.end(), mesh.colours.begin(), mesh.colours.end());
    out.texcoords.insert(out.texcoords.end(), mesh.texcoords.begin(), mesh.texcoords.end());
    if (!mesh.sourceVertex.empty())
      for (std::uint32_t s : mesh.sourceVertex) out.sourceVertex.push_back(base + s);
    else
      for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) out.sourceVertex.push_back(base + v);
    // Its materials, each kept once.
    std::vector<std::uint16_t> slot(mesh.materials.size());
    for (std::size_t k = 0; k < mesh.materials.size(); ++k) {
      auto same = std::find_if(out.materials.begin(), out.materials.end(), [&](const MeshMaterial& o) { return sameMaterial(o, mesh.materials[k]); });
      slot[k] = static_cast<std::uint16_t>(same - out.materials.begin());
      if (same == out.materials.end()) out.materials.push_back(mesh.materials[k]);
    }
    for (std::uint16_t f : mesh.faceMaterials) out.faceMaterials.push_back(f < slot.size() ? slot[f] : 0);
    closed = closed && mesh.closed;
    out.seeThrough = out.seeThrough || mesh.seeThrough;
  }
  // Into the unit sphere about the origin, as the loader leaves every mesh.
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : out.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 centre = out.positions.empty() ? glm::vec3(0.0f) : 0.5f * (lo + hi);
  float radius = 0.0f;
  for (const glm::vec3& p : out.positions) radius = std::max(radius, glm::length(p - centre));
  const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
  for (glm::vec3& p : out.positions) p = (p - centre) * scale;
  for (glm::vec3& c : out.faceCentroids) c = (c - centre) * scale;
  out.radius = radius > 0.0f ? 1.0f : 0.0f;
  // Each object closed: so is the whole, as the back-face culling reads it (every back face
  // lies behind a front face of its own object).
  out.closed = closed;
  placement = glm::translate(glm::mat4(1.0f), centre) * glm::scale(glm::mat4(1.0f), glm::vec3(radius > 0.0f ? radius : 1.0f));
  if (spheres) {
    spheres->clear();
    for (const Model* m : models)
      spheres->push_back(glm::vec4((glm::vec3(m->transform()[3]) - centre) * scale, m->sceneRadius() * scale));
  }
  return out;
}

}  // namespace npr
