// What the scene builds and uploads beyond adding models (see scene.h): the models' own
// palettes and the ground plane.
#include "renderer/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/mesh/ground_plane.h"

namespace npr {

Status Scene::setPalette(ModelId id, const Palette& palette) {
  Model* m = find(id);
  if (!m) return Error{"no model " + std::to_string(id) + " in the scene"};
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  m->setPalette(std::move(*uploaded));
  stats_.bufferUploads += 1;
  batchesFor_ = ~0u;  // it is drawn alone now
  return okStatus();
}

bool Scene::setDetail(ModelId id, float detail) {
  Model* m = find(id);
  if (m) m->setDetail(std::isfinite(detail) ? std::clamp(detail, 0.0f, 1.0f) : 0.0f);
  batchesFor_ = ~0u;  // batches keep one detail each
  return m != nullptr;
}

std::size_t Scene::strokeCount() {
  std::size_t n = 0;
  forEach([&](Model& m) { n += m.strokes().strokes(); });
  return n;
}

double Scene::strokeSeedMs() {
  double ms = 0.0;
  forEach([&](Model& m) { ms += m.strokes().seedMs(); });
  return ms;
}

void Scene::updateBatches() {
  if (batchesFor_ == layoutVersion_) return;
  batchesFor_ = layoutVersion_;
  batches_.clear();
  std::vector<Entry*> candidates;
  std::vector<const Model*> models;
  for (Entry& e : models_) {
    e.batched = false;
    if (e.visible && !e.moving && batchable(*e.model)) {
      candidates.push_back(&e);
      models.push_back(e.model.get());
    }
  }
  if (models.size() < kMinBatchedObjects) return;
  for (const std::vector<std::size_t>& group : groupIntoBatches(models)) {
    std::vector<const Model*> members;
    for (std::size_t i : group) members.push_back(models[i]);
    glm::mat4 placement(1.0f);
    Batch b;
    std::vector<glm::vec4> spheres;
    b.mesh = std::make_unique<Mesh>(mergeObjects(members, placement, &spheres));
    b.model = std::make_unique<Model>(*b.mesh, placement, stats_);
    b.model->setMemberSpheres(std::move(spheres));
    b.model->setDetail(members.front()->detail());
    for (std::size_t i : group) candidates[i]->batched = true;
    batches_.push_back(std::move(b));
  }
}

Model* Scene::ground() {
  if (empty()) return nullptr;
  if (ground_ && groundVersion_ == layoutVersion_) return ground_.get();
  // Under the scene's lowest point, about the origin, holding every model.
  float lowest = std::numeric_limits<float>::infinity();
  forEach([&](const Model& m) {
    if (m.transform() == glm::mat4(1.0f)) {
      for (const glm::vec3& p : m.mesh().positions) lowest = std::min(lowest, p.y);
    } else {
      for (const glm::vec3& p : m.mesh().positions) lowest = std::min(lowest, (m.transform() * glm::vec4(p, 1.0f)).y);
    }
  });
  const glm::vec4 b = bounds();
  groundMesh_ = groundPlane(std::isfinite(lowest) ? lowest : -1.0f, glm::length(glm::vec3(b)) + b.w);
  ground_ = std::make_unique<Model>(groundMesh_, glm::mat4(1.0f), stats_, false);
  groundVersion_ = layoutVersion_;
  return ground_.get();
}

}  // namespace npr
