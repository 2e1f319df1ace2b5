// The scene's palettes besides the models' own (see palette_set.h).
#include "renderer/palette/palette_set.h"

#include <algorithm>
#include <cmath>

namespace npr {
namespace {

Status upload(const Palette& palette, std::unique_ptr<GpuPalette>& into, FrameStats& stats) {
  Result<std::unique_ptr<GpuPalette>> uploaded = GpuPalette::upload(palette);
  if (!uploaded) return Error{uploaded.error()};
  into = std::move(*uploaded);
  stats.bufferUploads += 1;
  return okStatus();
}

}  // namespace

Status PaletteSet::setMain(const Palette& palette) { return upload(palette, main_, stats_); }

Status PaletteSet::setMaterial(const std::string& material, const Palette& palette) {
  std::unique_ptr<GpuPalette> uploaded;
  if (Status st = upload(palette, uploaded, stats_); !st) return st;
  materials_[material] = std::move(uploaded);
  materialsChanged_ = true;
  return okStatus();
}

void PaletteSet::clearMaterial(const std::string& material) {
  if (materials_.erase(material)) materialsChanged_ = true;
}

const GpuPalette* PaletteSet::material(const std::string& material) const {
  const auto it = materials_.find(material);
  return it == materials_.end() ? nullptr : it->second.get();
}

void PaletteSet::setMaterialDetail(const std::string& material, float detail) {
  const float d = std::isfinite(detail) ? std::clamp(detail, 0.0f, 1.0f) : 0.0f;
  const auto it = details_.find(material);
  if (it != details_.end() && it->second == d) return;
  details_[material] = d;
  materialsChanged_ = true;
}

std::optional<float> PaletteSet::materialDetail(const std::string& material) const {
  const auto it = details_.find(material);
  return it == details_.end() ? std::nullopt : std::optional<float>(it->second);
}

Status PaletteSet::setControl(ControlParameter parameter, const Palette& palette) {
  return upload(palette, parameter == ControlParameter::Shadow ? shadow_ : occlusion_, stats_);
}

void PaletteSet::clearControl(ControlParameter parameter) { (parameter == ControlParameter::Shadow ? shadow_ : occlusion_).reset(); }

Status PaletteSet::updateMatchers(const RenderSettings& s, std::optional<glm::vec2> target, float sceneRadius) {
  forEach([&](GpuPalette& p) { p.setAxisScale(sceneRadius); });
  for (auto& [name, p] : materials_)
    if (Status st = p->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"palette of material '" + name + "': " + st.error()};
  if (shadow_)
    if (Status st = shadow_->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"shadow palette: " + st.error()};
  if (occlusion_)
    if (Status st = occlusion_->updateMatcher(s.match, s.rangeScale, {}, stats_, target); !st) return Error{"occlusion palette: " + st.error()};
  // Cel bands belong to the main palette (they are one fewer than its tones) and replace the range.
  if (main_)
    if (Status st = main_->updateMatcher(s.match, s.rangeScale, s.bands, stats_, s.bands.empty() ? target : std::nullopt); !st) return st;
  return okStatus();
}

Status PaletteSet::updateSlot(GpuPalette* own, const RenderSettings& s, std::optional<glm::vec2> target, int slot) {
  if (own)
    if (Status st = own->updateMatcher(s.match, s.rangeScale, {}, stats_, target, slot); !st) return st;
  for (auto& [name, p] : materials_)
    if (Status st = p->updateMatcher(s.match, s.rangeScale, {}, stats_, target, slot); !st) return st;
  return okStatus();
}

void PaletteSet::useSlot(int slot) const {
  forEach([&](const GpuPalette& p) { p.useMatcher(slot); });
}

}  // namespace npr
