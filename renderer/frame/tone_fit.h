// The automatic tone range (--tone-range auto|per-object): the palettes' levels fitted onto the
// lit tones the view shows, each frame from its own view and pose, for the whole scene and, per object, for each
// model (its tracker, target and matcher slot live on the model: scene/model.h).
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/tone_range.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/render_settings.h"

namespace npr {

class ToneFit {
 public:
  // Samples the scene's lit tones through `camera` and moves the range toward them (none with
  // a fixed range or cel bands, which also reset every tracker).
  void update(Scene& scene, const LightingState& lighting, const CameraMatrices& camera, const RenderSettings& settings, FrameStats& stats);
  // The scene's range on the query axis (0..3), or none.
  std::optional<glm::vec2> target() const { return target_; }

 private:
  static void fitGround(Model& ground, const LightingState& lighting, const CameraMatrices& camera, const RenderSettings& s, int slot);

  ToneRangeTracker tracker_;
  std::optional<glm::vec2> target_;
  std::vector<ToneSample> samples_;
};

}  // namespace npr
