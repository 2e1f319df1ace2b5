// The scene: the models the renderer draws, each with its own transform and derived caches
// (model.h). The API adds, removes, moves, hides and shows them; a hidden model keeps its
// caches and is skipped by every pass (forEach, placed, bounds and first see only the shown).
// With batching on, the surface passes draw small static models merged into batches
// (scene_batches.h; forEachSurface, placed); everything else sees the models themselves.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/scene/model.h"
#include "renderer/scene/scene_batches.h"
#include "renderer/mesh/placed_mesh.h"

namespace npr {

using ModelId = std::uint32_t;

class Scene {
 public:
  // Uploads are counted in `stats` (the renderer's).
  explicit Scene(FrameStats& stats) : stats_(stats) {}
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // A model of `mesh` placed by `transform`, uploaded now. The scene keeps a pointer to the
  // mesh: remove the model (or clear the scene) before the mesh is destroyed.
  ModelId add(const Mesh& mesh, const glm::mat4& transform = glm::mat4(1.0f)) {
    models_.push_back({nextId_, std::make_unique<Model>(mesh, transform, stats_)});
    ++version_;
    ++layoutVersion_;
    return nextId_++;
  }
  // A temporary would be gone before the first frame.
  ModelId add(Mesh&& mesh, const glm::mat4& transform = glm::mat4(1.0f)) = delete;
  // A scene of one model showing `mesh`, untransformed: the present model reused when there is
  // exactly one (its own palette dropped). Null or an empty mesh: an empty scene.
  void setOnly(const Mesh* mesh) {
    if (!mesh || (mesh->indices.empty() && !mesh->hasMarks())) return clear();
    if (models_.size() != 1) {
      clear();
      add(*mesh);
      return;
    }
    models_.front().model->reset(*mesh, glm::mat4(1.0f), stats_);
    ground_.reset();
    ++version_;
    ++layoutVersion_;
  }
  // The model's own palette (Model::palette), uploaded now, or shared with the models given the
  // same palette before (the same content: their batches can take them together); on
  // failure, or for no such model, nothing changes.
  [[nodiscard]] Status setPalette(ModelId id, const Palette& palette);
  void clearPalette(ModelId id) {
    if (Model* m = find(id)) m->setPalette(nullptr);
    remakeBatches();
  }
  // The object's name, for line sets that select objects. False when there is no such model.
  bool setName(ModelId id, const std::string& name) {
    Model* m = find(id);
    if (m) m->setName(name);
    return m != nullptr;
  }
  // The model's detail in [0, 1] (clamped; not finite: 0), which a palette with `axis detail`
  // picks its row by. False when there is no such model.
  bool setDetail(ModelId id, float detail);
  // Poses a model whose mesh deforms (Mesh::deformation): morph `weights` and skin `joints`
  // (per joint, the mesh's rest space to its posed space; animation/deformation.h), made by
  // the next frame where it reads them. False when there is no such model; a mesh that does
  // not deform ignores it.
  bool deform(ModelId id, const std::vector<glm::mat4>& joints, const std::vector<float>& weights) {
    Model* m = find(id);
    if (!m) return false;
    m->deform(joints, weights);
    touch();
    return true;
  }
  // The ground plane under the shown models (--ground), drawn like one more model: built the
  // first time a frame asks for it, again when the layout changed. Null for an empty scene.
  Model* ground();
  // The painterly strokes seeded on the shown models, and the time seeding them took (0 until
  // a frame draws strokes).
  std::size_t strokeCount();
  double strokeSeedMs();
  bool remove(ModelId id) {
    for (auto it = models_.begin(); it != models_.end(); ++it)
      if (it->id == id) {
        models_.erase(it);
        ++version_;
        ++layoutVersion_;
        return true;
      }
    return false;
  }
  void clear() {
    models_.clear();
    ground_.reset();
    ++version_;
    ++layoutVersion_;
  }
  Model* find(ModelId id) {
    for (auto& m : models_)
      if (m.id == id) return m.model.get();
    return nullptr;
  }
  const Model* find(ModelId id) const { return const_cast<Scene*>(this)->find(id); }
  bool setTransform(ModelId id, const glm::mat4& transform) {
    Model* m = find(id);
    if (!m) return false;
    m->setTransform(transform);
    ++version_;
    ++layoutVersion_;
    return true;
  }
  // A move of the animation: as setTransform, but the scene's layout (what the ground is
  // sized and placed by) stays, so the ground does not follow a jumping character.
  bool pose(ModelId id, const glm::mat4& transform) {
    for (auto& e : models_) {
      if (e.id != id) continue;
      if (e.model->transform() == transform) return true;
      e.model->setTransform(transform);
      ++version_;
      // A model that moves is drawn alone from now on: its batch is made again without it.
      if (!e.moving && e.batched) remakeBatches();
      e.moving = true;
      return true;
    }
    return false;
  }
  // A model's geometry changed in place (animation): what covers the whole scene (shadow
  // maps) is drawn again; the layout stays.
  void touch() { ++version_; }
  // False when there is no such model.
  bool setVisible(ModelId id, bool visible) {
    for (auto& m : models_)
      if (m.id == id) {
        if (m.visible != visible) ++version_, ++layoutVersion_;
        m.visible = visible;
        return true;
      }
    return false;
  }
  // Whether no model is shown.
  bool empty() const {
    for (const auto& m : models_)
      if (m.visible) return false;
    return true;
  }
  std::size_t size() const { return models_.size(); }
  // Changes whenever a model is added, removed, shown, hidden or moved (for the caches of the
  // whole scene: shadow maps).
  unsigned version() const { return version_; }
  // Changes as version() does except for animation's moves (pose).
  unsigned layoutVersion() const { return layoutVersion_; }
  // Calls fn(Model&) for every shown model, in the order they were added.
  template <class Fn>
  void forEach(Fn&& fn) {
    for (auto& m : models_)
      if (m.visible) fn(*m.model);
  }
  template <class Fn>
  void forEach(Fn&& fn) const {
    for (const auto& m : models_)
      if (m.visible) fn(static_cast<const Model&>(*m.model));
  }
  // Hidden ones too (what must hold for every model when it is shown again).
  template <class Fn>
  void forEachIncludingHidden(Fn&& fn) {
    for (auto& m : models_) fn(*m.model);
  }
  // Whether the surface passes draw batches (scene_batches.h): the frame turns it off where it
  // reads what only the objects themselves hold (their own tone ranges, patterns, bakes).
  void setBatching(bool on) { batching_ = on; }
  bool batching() const { return batching_; }
  // Calls fn(Model&) for every surface the surface passes draw: the batches, then every shown
  // model not in one (all shown models when batching is off). Batches are made the first time
  // after the layout changed.
  template <class Fn>
  void forEachSurface(Fn&& fn) {
    if (batching_) {
      updateBatches();
      for (auto& b : batches_) fn(*b.model);
    }
    for (auto& m : models_)
      if (m.visible && !(batching_ && m.batched)) fn(*m.model);
  }
  // The batches drawn now (0 with batching off or none made).
  std::size_t batchCount() const { return batching_ ? batches_.size() : 0; }
  // What batches are keyed by changed (a model's parts, palette or detail; a model began to
  // move): they are made again by the next surface pass.
  void remakeBatches() { batchesFor_ = ~0u; }
  // Every surface's mesh with the camera placed by its transform (passes that see the whole scene).
  std::vector<PlacedMesh> placed(const CameraMatrices& camera) {
    std::vector<PlacedMesh> meshes;
    forEachSurface([&](Model& m) { meshes.push_back({&m.gpu(), m.placed(camera), &m.materials()}); });
    return meshes;
  }
  // The first shown model (null when none is).
  Model* first() {
    for (auto& m : models_)
      if (m.visible) return m.model.get();
    return nullptr;
  }
  const Model* first() const { return const_cast<Scene*>(this)->first(); }
  // A sphere holding every model (scene space).
  glm::vec4 bounds() const {
    glm::vec3 centre(0.0f);
    float radius = -1.0f;
    for (const auto& e : models_) {
      if (!e.visible) continue;
      const glm::vec3 c(e.model->transform()[3]);
      const float r = e.model->sceneRadius();
      if (radius < 0.0f) {
        centre = c, radius = r;
        continue;
      }
      const float d = glm::length(c - centre);
      if (d + r <= radius) continue;
      if (d + radius <= r) {
        centre = c, radius = r;
        continue;
      }
      const float grown = 0.5f * (d + r + radius);
      centre += (c - centre) * ((grown - radius) / d);
      radius = grown;
    }
    return glm::vec4(centre, std::max(radius, 0.0f));
  }

 private:
  FrameStats& stats_;
  struct Entry {
    ModelId id;
    std::unique_ptr<Model> model;
    bool visible = true;
    bool batched = false;  // drawn in a batch (while batching is on)
    bool moving = false;   // posed by animation: never batched
  };
  std::vector<Entry> models_;
  // Small static models merged for the surface passes (scene_batches.h), made for layout
  // version batchesFor_.
  struct Batch {
    std::unique_ptr<Mesh> mesh;
    std::unique_ptr<Model> model;
  };
  void updateBatches();
  std::vector<Batch> batches_;
  // The palettes models were given, by content (Scene::setPalette shares them).
  std::vector<std::pair<std::uint64_t, std::weak_ptr<GpuPalette>>> sharedPalettes_;
  bool batching_ = false;
  unsigned batchesFor_ = ~0u;
  ModelId nextId_ = 1;
  unsigned version_ = 0, layoutVersion_ = 0;
  Mesh groundMesh_;
  std::unique_ptr<Model> ground_;
  unsigned groundVersion_ = 0;  // the layout version it was built for
};

}  // namespace npr
