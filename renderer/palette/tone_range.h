// The automatic tone range (--tone-range auto): which lit tones the visible surfaces show, so
// the palette's levels can be fitted onto them (PaletteMatcher's tone target). A dark model
// (albedo 0.2) lit by the default light shows tones in the bottom fifth of the range, where a
// fixed crosshatch palette has only its darkest levels: a solid ink silhouette.
//
// The estimate samples up to a budget of triangles per model, evenly through the mesh, lit
// on the CPU exactly as the per-triangle paths light them (the lighting model, the model's
// materials, vertex colours and texture averages), keeps the front-facing ones inside the
// view, and weights each by its area on screen: a histogram of the picture's tones without
// reading anything back from the GPU. Occlusion between surfaces is not seen (a hidden front
// face counts); the percentiles make that matter little. The tracker quantises the range so
// the matcher's lookup tables are rebuilt only when it moves (and can smooth it over frames;
// the frame's fit does not, so any frame renders alike alone or in a sequence).
#pragma once

#include <algorithm>

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh.h"
#include "renderer/palette/palette.h"

namespace npr {

struct ToneSample {
  float query;   // the match mode's query: 3 max(r,g,b) (intensity), r + g + b (order, colours)
  float weight;  // the triangle's area on screen (normalised device units)
};

// The triangles sampleTones reads: every `toneSampleStride`-th from half of it.
inline std::size_t toneSampleStride(std::size_t triangles, std::size_t budget) { return budget == 0 ? 1 : std::max<std::size_t>(1, triangles / budget); }

// Adds the samples of one model seen through `modelView` and `projection`.
void sampleTones(const Mesh& mesh, const LightingState& lighting, const glm::mat4& modelView, const glm::mat4& projection,
                 bool materials, MatchMode mode, std::size_t budget, std::vector<ToneSample>& out);

// The weighted `low` and `high` percentiles (0..100) of the samples' queries, widened to at
// least `minSpan` about their middle (a flat-lit model must not stretch one tone over the whole
// palette); none without samples of positive weight. Reorders `samples`.
std::optional<glm::vec2> percentileRange(std::vector<ToneSample>& samples, float low, float high, float minSpan);

class ToneRangeTracker {
 public:
  // Quantisation of the range on the query axis (0..3): 1/128.
  static constexpr float kStep = 3.0f / 384.0f;
  // The range this frame: the first estimate as it is, then each frame `rate` of the way to
  // the new one (1: no smoothing), quantised to kStep. None while there has been no estimate.
  std::optional<glm::vec2> update(std::optional<glm::vec2> estimate, float rate);
  void reset() { smoothed_.reset(); }
  std::optional<glm::vec2> current() const { return quantised_; }

 private:
  std::optional<glm::vec2> smoothed_, quantised_;
};

}  // namespace npr
