// The scene's palettes made ready for a frame (see scene_palettes.h).
#include "renderer/frame/scene_palettes.h"

namespace npr {

Status preparePalettes(Scene& scene, PaletteSet& palettes, const RenderSettings& s, std::optional<glm::vec2> target, FrameStats& stats) {
  if (palettes.takeMaterialsChanged()) {
    auto paletteOf = [&](const std::string& material) { return palettes.material(material); };
    auto detailOf = [&](const std::string& material) { return palettes.materialDetail(material); };
    scene.forEachIncludingHidden([&](Model& m) { m.splitByMaterial(paletteOf, detailOf, stats); });
    scene.remakeBatches();
  }
  // A depth axis counts in scene radii, so a palette with rows suits any model's units.
  const float sceneRadius = scene.empty() ? 1.0f : scene.bounds().w;
  Status status = okStatus();
  scene.forEachIncludingHidden([&](Model& m) {
    GpuPalette* own = m.palette();
    if (!own || !status) return;
    own->setAxisScale(sceneRadius);
    if (Status st = own->updateMatcher(s.match, s.rangeScale, {}, stats, target); !st) status = Error{"an object's palette: " + st.error()};
  });
  if (!status) return status;
  if (Status st = palettes.updateMatchers(s, target, sceneRadius); !st) return st;
  // Each surface fitted to its own tones (an object, or a batch of one material: frame/
  // tone_fit.h): its palettes get a matcher for its range, in its slot.
  scene.forEachSurface([&](Model& m) {
    if (!status || m.toneSlot == 0) return;
    status = palettes.updateSlot(m.palette() ? m.palette() : palettes.main(), s, m.toneTarget, m.toneSlot);
  });
  // The ground's, set apart from the objects' (frame/tone_fit.cpp).
  if (Model* ground = s.ground ? scene.ground() : nullptr; status && ground && ground->toneSlot != 0)
    status = palettes.updateSlot(palettes.main(), s, ground->toneTarget, ground->toneSlot);
  return status;
}

ToneSlotScope::ToneSlotScope(const Model& model, const PaletteSet& palettes) : own_(model.palette()), palettes_(palettes) {
  palettes_.useSlot(model.toneSlot);
  if (own_) own_->useMatcher(model.toneSlot);
}

ToneSlotScope::~ToneSlotScope() {
  palettes_.useSlot(0);
  if (own_) own_->useMatcher(0);
}

}  // namespace npr
