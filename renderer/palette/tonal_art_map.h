// Tonal art maps (after Praun et al. 2001, "Real-Time Hatching"): palettes drawn stroke by
// stroke. Strokes (slightly curved, tapered, with varying width and pressure, or a user's
// stroke image) are added one at a time until each tone level reaches its target tone, measured
// after every stroke in the palette analysis's convention (composited over the paper, averaged
// in linear light). Levels nest across tones (a darker level keeps every stroke of the lighter
// ones) and across resolutions (a stroke placed in a coarser mip level is also drawn in every
// finer one, at the same width in texels), so neither a change of tone nor a change of scale
// makes strokes pop. Strokes wrap around the tile, so it tiles without seams. Stipple is the
// same machinery with dots placed in a blue-noise order (Mitchell's best candidate).
// Used by the shipped palettes' generator (palettes/) and the palette maker (--make-palette).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

// One family of strokes: its direction and its marks' shape. Lengths are fractions of the
// tile; widths are texels at every mip level (marks keep their width on screen).
struct StrokeFamily {
  float degrees = 45.0f;       // direction in the image (counter-clockwise from +x, y up)
  float degreesJitter = 4.0f;  // each stroke turned by up to this much
  float length = 0.35f;        // of the tile side
  float lengthJitter = 0.35f;  // each stroke's length scaled by 1 +- this
  float width = 1.6f;          // texels
  float widthJitter = 0.35f;
  float bend = 0.04f;          // the midpoint's sideways offset, as a fraction of the length, up to
  float pressure = 0.9f;       // peak opacity
  float pressureJitter = 0.15f;
  float joinsAt = 0.0f;        // first drawn once the target darkness (0 paper .. 1 ink) passes this
  float grain = 0.0f;          // 0..1: how much the paper's tooth (TamSpec::tooth) keeps ink out of its valleys
};

struct TamSpec {
  int size = 256;            // level 0's side (a power of two)
  int strokeLevels = 3;      // mip levels drawn with strokes: size, size/2, ...
  int tones = 10;            // palette levels, the first bare paper
  float darkest = 0.8f;      // the last level's darkness: its tone is paper + darkest (ink - paper)
  std::vector<StrokeFamily> families;  // hatching; empty with `dots`
  bool dots = false;         // stipple: round dots in blue-noise order
  float dotRadius = 1.4f;    // texels
  glm::vec3 ink{0.06f, 0.05f, 0.08f};  // encoded colour
  std::optional<ImageRGBA8> stamp;  // a user's stroke image (ink = darkness x alpha), stretched along each stroke
  // The paper's tooth (grey, size x size; bright = a peak that catches ink), for strokes with
  // grain: charcoal and pencil skip over the valleys.
  std::optional<ImageRGBA8> tooth;
  std::uint32_t seed = 1;
  int maxMarksPerLevel = 60000;  // a level that cannot reach its tone stops here (and says so)
};

struct TamLevel {
  std::vector<ImageRGBA8> mips;  // straight-alpha ink over transparency: size, size/2, ...
  std::vector<float> tone;       // measured intensity (sum of channels, 0..3) of each mip over the paper's
  int marks = 0;                 // strokes or dots in level 0
};

struct TonalArtMap {
  std::vector<TamLevel> levels;
  std::vector<float> targets;        // the intensity each level aimed at
  std::vector<std::string> notes;    // levels that stopped short of their tone
};

// Builds the map over `paper` (opaque, spec.size a side; its reduced levels are the
// background the tone is measured against at each mip). `progress` (may be empty) is told the
// fraction done. Fails on a spec it cannot draw (sizes, counts, no families).
[[nodiscard]] Result<TonalArtMap> buildTonalArtMap(const TamSpec& spec, const ImageRGBA8& paper,
                                                   const std::function<void(double)>& progress = {});

}  // namespace npr
