// The painterly strokes' brushes (see brush_shapes.h).
#include "renderer/strokes/brush_shapes.h"

#include <cmath>
#include <cstddef>
#include <random>

#include <glm/glm.hpp>

namespace npr {

// Flat brushes: bristles as rows of their own darkness, each starting and ending at its own
// place (a dry, ragged start and end), the edges across the stroke soft. A fixed seed: the
// same brushes in every run.
std::vector<std::uint8_t> brushCoverage() {
  std::vector<std::uint8_t> px(std::size_t(kBrushLength * kBrushes * kBrushWidth));
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int b = 0; b < kBrushes; ++b)
    for (int y = 0; y < kBrushWidth; ++y) {
      const float ink = 0.55f + 0.45f * u(rng);
      const float start = 0.02f + 0.18f * u(rng), end = 0.8f + 0.18f * u(rng);
      const float v = (float(y) + 0.5f) / kBrushWidth * 2.0f - 1.0f;
      const float edge = 1.0f - glm::smoothstep(0.6f, 1.0f, std::abs(v));
      for (int x = 0; x < kBrushLength; ++x) {
        const float s = (float(x) + 0.5f) / kBrushLength;
        const float along = glm::smoothstep(start, start + 0.15f, s) * (1.0f - glm::smoothstep(end - 0.1f, end, s));
        px[std::size_t(y * kBrushLength * kBrushes + b * kBrushLength + x)] = std::uint8_t(std::lround(255.0f * ink * edge * along));
      }
    }
  return px;
}

}  // namespace npr
