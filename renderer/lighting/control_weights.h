// Control-image palettes (seed 003, after Akleman et al. 2016): besides the main palette, chosen
// by the lit tone, a shadow palette drawn where cast shadows fall and an occlusion palette drawn
// in crevices, each blended in by its own parameter. The weights are a partition of unity by
// construction, with shadow taking precedence over occlusion and occlusion over the main
// palette:
//   w_shadow = s,   w_occlusion = o (1 - s),   w_main = (1 - s)(1 - o)
// where s is the share of the diffuse light that shadows block and o = 1 - the occlusion
// factor. A parameter whose palette is not loaded counts as 0 (its weight stays with the
// palettes below it). The renderer draws the main palette, then the occlusion palette blended
// over it with alpha o, then the shadow palette with alpha s: the same weights
// (passes/control_palette_pass.h). This is the CPU statement of that rule, for tests and tools.
#pragma once

#include <algorithm>
#include <cmath>

namespace npr {

enum class ControlParameter { Shadow, Occlusion };

struct ControlWeights {
  float main = 1.0f, occlusion = 0.0f, shadow = 0.0f;
};

// A parameter as a weight: clamped to [0, 1], NaN counting as 0 (nothing blocked).
inline float controlAmount(float x) { return std::isnan(x) ? 0.0f : std::clamp(x, 0.0f, 1.0f); }

inline ControlWeights controlWeights(float shadowShare, float occlusionAmount, bool shadowPalette, bool occlusionPalette) {
  const float s = shadowPalette ? controlAmount(shadowShare) : 0.0f;
  const float o = occlusionPalette ? controlAmount(occlusionAmount) : 0.0f;
  ControlWeights w;
  w.shadow = s;
  w.occlusion = o * (1.0f - s);
  w.main = (1.0f - s) * (1.0f - o);
  return w;
}

}  // namespace npr
