// The palettes a scene is drawn with besides the models' own (scene/model.h): the main one,
// one per material name, and the control-image palettes blended in where shadows fall or in
// crevices. Each is uploaded once when set (on failure the one in place stays) and brought up
// to the frame's match settings and tone range before it draws (updateMatchers).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/lighting/control_weights.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/palette/palette.h"
#include "renderer/settings/render_settings.h"

namespace npr {

class PaletteSet {
 public:
  explicit PaletteSet(FrameStats& stats) : stats_(stats) {}

  // The main palette: every surface without a palette of its own.
  [[nodiscard]] Status setMain(const Palette& palette);
  const GpuPalette* main() const { return main_.get(); }
  GpuPalette* main() { return main_.get(); }
  // The main palette's matcher as the last frame made it (null before a palette is set).
  const PaletteMatcher* matcher() const { return main_ ? main_->matcher() : nullptr; }

  // Faces of the material named `material` are drawn with `palette` (every path; matched with
  // its own matcher), in whichever mesh has a material of that name.
  [[nodiscard]] Status setMaterial(const std::string& material, const Palette& palette);
  void clearMaterial(const std::string& material);
  const GpuPalette* material(const std::string& material) const;
  // Faces of the material named `material` take `detail` (clamped to [0, 1]; not finite: 0)
  // in place of their model's, for a palette with `axis detail`.
  void setMaterialDetail(const std::string& material, float detail);
  std::optional<float> materialDetail(const std::string& material) const;
  // Whether the material palettes or details changed since the last call (the models' parts
  // are split again then).
  bool takeMaterialsChanged() { return std::exchange(materialsChanged_, false); }

  // Control-image palettes (passes/control_palette_pass.h), matched with the main palette's
  // match mode and range scale.
  [[nodiscard]] Status setControl(ControlParameter parameter, const Palette& palette);
  void clearControl(ControlParameter parameter);
  const GpuPalette* control(ControlParameter parameter) const {
    return parameter == ControlParameter::Shadow ? shadow_.get() : occlusion_.get();
  }
  bool hasControl(ControlParameter parameter) const { return control(parameter) != nullptr; }

  // Every palette of the set: the main one, per-material, then control palettes.
  template <class Fn>
  void forEach(Fn&& fn) {
    if (main_) fn(*main_);
    for (auto& [name, p] : materials_) fn(*p);
    if (shadow_) fn(*shadow_);
    if (occlusion_) fn(*occlusion_);
  }
  template <class Fn>
  void forEach(Fn&& fn) const {
    const_cast<PaletteSet*>(this)->forEach([&](GpuPalette& p) { fn(static_cast<const GpuPalette&>(p)); });
  }

  // Brings every palette's matcher up to `settings` and the scene's tone range `target` (the
  // main palette's cel bands, when given, take its place), and scales their depth axes by the
  // scene's radius so a palette with rows suits any model's units.
  [[nodiscard]] Status updateMatchers(const RenderSettings& settings, std::optional<glm::vec2> target, float sceneRadius);
  // The matchers of one object's own tone range (slot >= 1): the palettes that can draw it, that
  // is `own` (its palette, or the main one; null: none) and the material palettes.
  [[nodiscard]] Status updateSlot(GpuPalette* own, const RenderSettings& settings, std::optional<glm::vec2> target, int slot);
  // Every palette draws with the matchers of `slot` (GpuPalette::useMatcher) until told again.
  void useSlot(int slot) const;

 private:
  FrameStats& stats_;
  std::unique_ptr<GpuPalette> main_;
  std::map<std::string, std::unique_ptr<GpuPalette>> materials_;
  std::map<std::string, float> details_;
  std::unique_ptr<GpuPalette> shadow_, occlusion_;
  bool materialsChanged_ = false;
};

}  // namespace npr
