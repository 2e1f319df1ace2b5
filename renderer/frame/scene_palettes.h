// The scene's palettes made ready for a frame: the models split into parts by the material
// palettes and details, every palette's depth axis scaled to the scene, every matcher brought
// up to the frame's match settings and tone range (the scene's, and each object's own), and
// while a model draws, the matchers of its own tone range selected.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/palette/palette_set.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// Fails, with the palette named, where a matcher cannot be made; `target`: the scene's tone
// range (frame/tone_fit.h).
[[nodiscard]] Status preparePalettes(Scene& scene, PaletteSet& palettes, const RenderSettings& settings, std::optional<glm::vec2> target,
                                     FrameStats& stats);

// The palettes that draw `model` use the matchers of its own tone range while this lives (slot
// 0, the scene's, again after).
class ToneSlotScope {
 public:
  ToneSlotScope(const Model& model, const PaletteSet& palettes);
  ~ToneSlotScope();
  ToneSlotScope(const ToneSlotScope&) = delete;
  ToneSlotScope& operator=(const ToneSlotScope&) = delete;

 private:
  const GpuPalette* own_;
  const PaletteSet& palettes_;
};

}  // namespace npr
