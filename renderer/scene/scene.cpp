// What the scene builds and uploads beyond adding models (see scene.h): the models' own
// palettes and the ground plane.
#include "renderer/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/mesh/ground_plane.h"

namespace npr {

namespace {

// A palette's content (its file, entries' images and mips, background and axis), FNV-1a: the
// same palette given to several models is uploaded once.
std::uint64_t fingerprint(const Palette& p) {
  std::uint64_t h = 14695981039346656037ull;
  auto bytes = [&](const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  auto text = [&](const std::string& s) { bytes(s.data(), s.size()), bytes("\0", 1); };
  auto image = [&](const ImageRGBA8& img) {
    bytes(&img.width, sizeof img.width), bytes(&img.height, sizeof img.height);
    bytes(img.pixels.data(), img.pixels.size());
  };
  text(p.file), text(p.name);
  for (const PaletteEntry& e : p.entries) {
    text(e.path), image(e.image);
    for (const ImageRGBA8& m : e.mips) image(m);
  }
  bytes(&p.backgroundColour, sizeof p.backgroundColour);
  if (p.backgroundImage) image(*p.backgroundImage);
  bytes(&p.axis.kind, sizeof p.axis.kind), bytes(&p.axis.from, sizeof p.axis.from), bytes(&p.axis.to, sizeof p.axis.to);
  bytes(&p.axis.rows, sizeof p.axis.rows);
  return h;
}

}  // namespace

Status Scene::setPalette(ModelId id, const Palette& palette) {
  Model* m = find(id);
  if (!m) return Error{"no model " + std::to_string(id) + " in the scene"};
  const std::uint64_t key = fingerprint(palette);
  std::shared_ptr<GpuPalette> shared;
  for (auto it = sharedPalettes_.begin(); it != sharedPalettes_.end();) {
    if (it->second.expired()) {
      it = sharedPalettes_.erase(it);
      continue;
    }
    if (it->first == key) shared = it->second.lock();
    ++it;
  }
  if (!shared) {
    Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
    if (!uploaded) return Error{uploaded.error()};
    shared = std::move(*uploaded);
    sharedPalettes_.push_back({key, shared});
    stats_.bufferUploads += 1;
  }
  m->setPalette(std::move(shared));
  remakeBatches();  // it moves to a batch of its palette
  return okStatus();
}

bool Scene::setDetail(ModelId id, float detail) {
  Model* m = find(id);
  if (m) m->setDetail(std::isfinite(detail) ? std::clamp(detail, 0.0f, 1.0f) : 0.0f);
  remakeBatches();  // batches keep one detail each
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
    b.model->setPalette(members.front()->sharedPalette());
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
