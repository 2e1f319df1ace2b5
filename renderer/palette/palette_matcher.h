// Choosing a palette entry for a lit colour: the original's three match modes and its
// IntensityRangeScale, with fixed tie-breaking and no linear scan per query.
//
//  MATCH_INTENSITY  query q = 3 x max(r,g,b); entry level = sum of its average's channels;
//                   the entry whose level is nearest q.
//  MATCH_ORDER      query q = r + g + b; entry t's level is (t + 1/2) x 3/N, so q indexes the
//                   palette order (floor(q N / 3)), brighter light to later entries.
//  MATCH_COLORS     the entry whose average colour is nearest in RGB (Euclidean).
//
// IntensityRangeScale S (finite, > 0) spreads the palette about its midpoint m: levels (or
// average colours) L become m + S (L - m), with m the midpoint of the palette's [min, max]
// (per channel for colours; 1.5 for order). S > 1 spreads a narrow palette over more of the
// lighting range; S < 1 narrows it. Queries are not scaled.
//
// A tone target [lo, hi] on the query axis (the automatic tone range, tone_range.h) first
// maps the palette's level range onto it: levels become c + S F (L - m) with c = (lo + hi) / 2
// and F = (hi - lo) / (max - min), so the lit tones the model shows span the whole palette
// (colours: every channel shifted by (c - the levels' midpoint) / 3). S then spreads about c.
//
// Ties (a query exactly between two levels, equal levels, equal distances) go to the lowest
// palette index. Lit colours are in [0,1]; non-finite channels are taken as 0.
#pragma once

#include "renderer/programs/shader_limits.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/palette/palette.h"
#include "renderer/core/result.h"

namespace npr {

struct PaletteBlend {
  int a = 0, b = 0;  // palette indices
  float t = 0.0f;    // weight of b; 0 shows a alone
};

class PaletteMatcher {
 public:
  static constexpr int kLut1DSize = gl::kLut1DSize;  // samples of the 1D tone over q in [0, 3]
  static constexpr int kLut3DSize = gl::kLut3DSize;    // samples per axis of the colour cube

  // `bands` (1D modes, optional): cel-style band thresholds on the query axis, ascending, one
  // fewer than the palette's distinct levels. Entry k of the sorted levels then covers
  // [bands[k-1], bands[k]) instead of the span nearest its level; `smooth` blends only within
  // kBandEdge of a threshold, which antialiases the hard band edges (the 1D-ramp technique).
  static Result<PaletteMatcher> create(const std::vector<glm::vec3>& averages, MatchMode mode, float rangeScale,
                                       const std::vector<float>& bands = {}, std::optional<glm::vec2> toneTarget = std::nullopt);
  static constexpr float kBandEdge = 0.03f;
  static Status validateRangeScale(float s);

  int match(const glm::vec3& lit) const;            // in [0, N)
  // match() for colours already known to be finite and in [0,1] (lit colours are), as a small
  // value the per-triangle loop keeps in registers: a loop that stores bytes must otherwise
  // assume each store may change the matcher's members and reload them.
  struct UnitLookup {
    const PaletteMatcher* matcher;
    const std::uint16_t* bins;  // null in colours mode
    bool intensity;
    int operator()(const glm::vec3& c) const {
      if (!bins) return matcher->match(c);
      const float q = intensity ? 3.0f * std::max(c.r, std::max(c.g, c.b)) : c.r + c.g + c.b;
      // Through int, not size_t: converting a float to an unsigned 64-bit integer is a slow,
      // branching sequence on x86 and cost more than the rest of the per-triangle work.
      const std::uint16_t e = bins[static_cast<int>(q * (float(kExactBins) / 3.0f))];
      return e != kAmbiguous ? e : matcher->matchQuery(q);
    }
  };
  UnitLookup unitLookup() const {
    return {this, mode_ == MatchMode::Colors ? nullptr : exactBins_.data(), mode_ == MatchMode::Intensity};
  }
  PaletteBlend matchSmooth(const glm::vec3& lit) const;
  // 1D modes: continuous position among the sorted distinct levels (what `smooth` blends by).
  float tonePosition(const glm::vec3& lit) const;
  float query(const glm::vec3& lit) const;          // the 1D query value q

  MatchMode mode() const { return mode_; }
  int size() const { return n_; }
  float rangeScale() const { return scale_; }
  const std::vector<float>& bands() const { return bands_; }
  const std::vector<float>& levels() const { return sortedLevels_; }       // 1D: distinct, ascending
  const std::vector<int>& entryRanks() const { return entryRank_; }        // 1D: each entry's level index
  const std::vector<glm::vec3>& scaledAverages() const { return scaled_; } // colours: after scaling

  // GPU tables (built once per palette, mode and scale), sampled at the nearest grid point:
  // 1D modes over q = 3 i / (kLut1DSize - 1); colours over c = (x, y, z) / (kLut3DSize - 1).
  std::vector<std::uint8_t> buildLutIndex1D() const;  // R8: match()
  std::vector<float> buildLutBlend1D() const;         // RGBA32F: matchSmooth() as (a, b, t, 0)
  std::vector<std::uint8_t> buildLut3D() const;       // RG8: nearest and second nearest

 private:
  int nearestColour(const glm::vec3& c, int* second) const;
  float toneOfQuery(float q) const;
  int matchQuery(float q) const;  // exact, by binary search
  int toneRank(float q) const;
  static constexpr int kExactBins = 8192;
  static constexpr std::uint16_t kAmbiguous = 0xFFFF;
  std::vector<std::uint16_t> exactBins_;  // 1D modes: the answer per query bin, or kAmbiguous
  MatchMode mode_ = MatchMode::Intensity;
  int n_ = 0;
  float scale_ = 1.0f;
  // 1D modes
  std::vector<float> sortedLevels_;
  std::vector<int> levelEntry_;
  std::vector<int> entryRank_;
  std::vector<float> bands_;
  // colour mode: exact nearest search over per-cell candidate lists
  std::vector<glm::vec3> scaled_;
  static constexpr int kCells = 8;
  std::vector<std::uint32_t> cellStart_;  // kCells^3 + 1 offsets into cellCandidates_
  std::vector<std::uint16_t> cellCandidates_;
};

}  // namespace npr
