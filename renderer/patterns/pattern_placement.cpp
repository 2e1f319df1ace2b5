// The frame's pattern placement (see pattern_placement.h).
#include "renderer/patterns/pattern_placement.h"

#include <algorithm>
#include <cmath>

namespace npr {
namespace {
// The dissolve runs over the middle half of the octave only: in the outer quarters one octave
// shows alone (marks within 2^0.25 of the pattern scale), which costs a scaled pattern's single
// lookup and no hash, so an orbiting or panning camera, whose scale stays near 1, never pays for
// it; zooms pay while they cross the middle.
constexpr float kFadeBegin = 0.25f, kFadeEnd = 0.75f;
}  // namespace

OctaveSplit PatternPlacement::octaves() const {
  if (!frame) return {};
  const float l = std::log2(frame->scale);
  const float octave = l - std::floor(l);
  return {octave, std::clamp((octave - kFadeBegin) / (kFadeEnd - kFadeBegin), 0.0f, 1.0f)};
}

gl::PatternMapping PatternPlacement::mapping() const {
  if (object) return gl::PatternMapping::Object;
  if (frame) {
    const float fade = octaves().fade;
    // One octave alone is a fixed scale through the frame (GpuPalette::bindPattern folds it in).
    return fade > 0.0f && fade < 1.0f ? gl::PatternMapping::Anchored : gl::PatternMapping::Scaled;
  }
  return scale != 1.0f ? gl::PatternMapping::Scaled : gl::PatternMapping::Screen;
}

}  // namespace npr
