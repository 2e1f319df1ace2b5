// Palette matching (see palette_matcher.h).
#include "renderer/palette/palette_matcher.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace npr {
namespace {

// Scaled levels and colours are clamped to +-kFar: far enough to act as infinity for queries
// in [0, 3], near enough that differences and squares stay finite in float.
constexpr double kFar = 1e15;

float finiteOr0(float x) { return std::isfinite(x) ? x : 0.0f; }

glm::vec3 sanitize01(const glm::vec3& c) {
  return glm::clamp(glm::vec3(finiteOr0(c.r), finiteOr0(c.g), finiteOr0(c.b)), 0.0f, 1.0f);
}

}  // namespace

Status PaletteMatcher::validateRangeScale(float s) {
  if (!std::isfinite(s) || !(s > 0.0f))
    return Error{"IntensityRangeScale must be a finite number > 0 (got " + std::to_string(s) + ")"};
  return okStatus();
}

Result<PaletteMatcher> PaletteMatcher::create(const std::vector<glm::vec3>& averages, MatchMode mode, float scale,
                                              const std::vector<float>& bands, std::optional<glm::vec2> toneTarget) {
  if (averages.empty()) return Error{"cannot match against an empty palette"};
  if (averages.size() > static_cast<size_t>(kMaxPaletteEntries))
    return Error{"palette has " + std::to_string(averages.size()) + " entries; at most " + std::to_string(kMaxPaletteEntries)};
  if (Status s = validateRangeScale(scale); !s) return Error{s.error()};
  if (!bands.empty() && mode == MatchMode::Colors) return Error{"band thresholds apply to match intensity and order, not colors"};
  PaletteMatcher m;
  m.mode_ = mode;
  m.n_ = static_cast<int>(averages.size());
  m.scale_ = scale;
  if (toneTarget && !(std::isfinite(toneTarget->x) && std::isfinite(toneTarget->y) && toneTarget->y > toneTarget->x))
    return Error{"a tone target must be a finite range lo < hi"};
  // The 1D levels' range (sums of channels; order: entry positions), for the tone target's fit.
  double levelLo = std::numeric_limits<double>::max(), levelHi = -levelLo;
  for (std::size_t t = 0; t < averages.size(); ++t) {
    const double v = mode == MatchMode::Order ? (double(t) + 0.5) * 3.0 / double(averages.size())
                                              : double(averages[t].r) + averages[t].g + averages[t].b;
    levelLo = std::min(levelLo, v);
    levelHi = std::max(levelHi, v);
  }
  // A palette of one level has no range to fit: the target only moves it.
  const double fit = toneTarget && levelHi > levelLo ? (double(toneTarget->y) - toneTarget->x) / (levelHi - levelLo) : 1.0;
  const double shift = toneTarget ? 0.5 * (double(toneTarget->x) + toneTarget->y) - 0.5 * (levelLo + levelHi) : 0.0;
  const double s = double(scale) * fit;
  if (mode == MatchMode::Colors) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const auto& a : averages) {
      lo = glm::min(lo, glm::dvec3(a));
      hi = glm::max(hi, glm::dvec3(a));
    }
    const glm::dvec3 mid = (lo + hi) * 0.5;
    const glm::dvec3 centre = mid + glm::dvec3(shift / 3.0);
    // A huge scale pushes colours far out: clamp so squared distances stay finite in float.
    for (const auto& a : averages)
      m.scaled_.push_back(glm::vec3(glm::clamp(centre + s * (glm::dvec3(a) - mid), glm::dvec3(-kFar), glm::dvec3(kFar))));
    // Candidate lists: entry t can be nearest somewhere in a cell only if its distance to the
    // cell's box is within the smallest farthest-distance of any entry to that box.
    const int C = kCells;
    m.cellStart_.assign(static_cast<size_t>(C * C * C + 1), 0);
    for (int z = 0; z < C; ++z)
      for (int y = 0; y < C; ++y)
        for (int x = 0; x < C; ++x) {
          const glm::vec3 bl = glm::vec3(x, y, z) / float(C), bh = glm::vec3(x + 1, y + 1, z + 1) / float(C);
          double bound = std::numeric_limits<double>::max();
          std::vector<double> dmin(m.scaled_.size());
          for (size_t t = 0; t < m.scaled_.size(); ++t) {
            const glm::dvec3 c(m.scaled_[t]);
            const glm::dvec3 nearP = glm::clamp(c, glm::dvec3(bl), glm::dvec3(bh));
            const glm::dvec3 farP(c.x < (bl.x + bh.x) * 0.5 ? bh.x : bl.x, c.y < (bl.y + bh.y) * 0.5 ? bh.y : bl.y,
                                  c.z < (bl.z + bh.z) * 0.5 ? bh.z : bl.z);
            dmin[t] = glm::length(c - nearP);
            bound = std::min(bound, glm::length(c - farP));
          }
          const size_t cell = static_cast<size_t>((z * C + y) * C + x);
          for (size_t t = 0; t < dmin.size(); ++t)
            if (dmin[t] <= bound * (1.0 + 1e-9) + 1e-12) m.cellCandidates_.push_back(static_cast<std::uint16_t>(t));
          m.cellStart_[cell + 1] = static_cast<std::uint32_t>(m.cellCandidates_.size());
        }
  } else {
    std::vector<double> lv(averages.size());
    for (size_t t = 0; t < averages.size(); ++t)
      lv[t] = mode == MatchMode::Intensity ? double(averages[t].r) + averages[t].g + averages[t].b
                                           : (double(t) + 0.5) * 3.0 / double(averages.size());
    const auto [mn, mx] = std::minmax_element(lv.begin(), lv.end());
    const double mid = mode == MatchMode::Order ? 1.5 : (*mn + *mx) * 0.5;
    const double centre = (toneTarget ? 0.5 * (levelLo + levelHi) : mid) + shift;
    std::vector<int> order(averages.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<float> scaled(averages.size());
    for (size_t t = 0; t < lv.size(); ++t) {
      const double v = centre + s * (lv[t] - (toneTarget ? 0.5 * (levelLo + levelHi) : mid));
      // A huge scale can push levels past float range: keep them finite and ordered.
      scaled[t] = static_cast<float>(std::clamp(v, -kFar, kFar));
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return scaled[static_cast<size_t>(a)] < scaled[static_cast<size_t>(b)]; });
    for (int t : order) {
      const float v = scaled[static_cast<size_t>(t)];
      if (!m.sortedLevels_.empty() && m.sortedLevels_.back() == v) continue;  // equal level: lowest index kept
      m.sortedLevels_.push_back(v);
      m.levelEntry_.push_back(t);
    }
    if (!bands.empty()) {
      if (bands.size() + 1 != m.sortedLevels_.size())
        return Error{"band thresholds: " + std::to_string(bands.size()) + " given, the palette's " +
                     std::to_string(m.sortedLevels_.size()) + " distinct levels need " + std::to_string(m.sortedLevels_.size() - 1)};
      for (size_t i = 0; i < bands.size(); ++i)
        if (!std::isfinite(bands[i]) || (i > 0 && !(bands[i] > bands[i - 1])))
          return Error{"band thresholds must be finite and strictly ascending"};
      m.bands_ = bands;
    }
    for (float v : scaled)
      m.entryRank_.push_back(int(std::lower_bound(m.sortedLevels_.begin(), m.sortedLevels_.end(), v) - m.sortedLevels_.begin()));
    // Bins of the query axis that one entry covers whole answer match() directly; bins
    // holding a decision boundary (at most one per level) fall back to the exact search.
    // The nearest level's rank never decreases with q, so equal answers at both ends of a
    // bin mean one answer throughout.
    m.exactBins_.assign(kExactBins + 1, kAmbiguous);
    for (int b = 0; b < kExactBins; ++b) {
      const float q0 = 3.0f * float(b) / float(kExactBins), q1 = 3.0f * float(b + 1) / float(kExactBins);
      const int a = m.matchQuery(q0);
      if (a == m.matchQuery(q1) && m.toneRank(q0) == m.toneRank(q1)) m.exactBins_[static_cast<size_t>(b)] = static_cast<std::uint16_t>(a);
    }
  }
  return m;
}

float PaletteMatcher::query(const glm::vec3& lit) const {
  const glm::vec3 c = sanitize01(lit);
  return mode_ == MatchMode::Intensity ? 3.0f * std::max(c.r, std::max(c.g, c.b)) : c.r + c.g + c.b;
}

float PaletteMatcher::tonePosition(const glm::vec3& lit) const { return toneOfQuery(query(lit)); }

float PaletteMatcher::toneOfQuery(float q) const {
  if (!bands_.empty()) {
    // Flat within a band; a linear ramp of half-width kBandEdge across each threshold.
    const size_t k = static_cast<size_t>(std::upper_bound(bands_.begin(), bands_.end(), q) - bands_.begin());
    for (size_t j : {k, k - 1}) {  // the threshold above and the one below
      if (j >= bands_.size()) continue;
      const float d = q - bands_[j];
      if (std::fabs(d) < kBandEdge) return float(j) + 0.5f + 0.5f * d / kBandEdge;
    }
    return float(k);
  }
  const auto& L = sortedLevels_;
  if (L.size() < 2 || q <= L.front()) return 0.0f;
  if (q >= L.back()) return float(L.size() - 1);
  const size_t k = static_cast<size_t>(std::upper_bound(L.begin(), L.end(), q) - L.begin()) - 1;
  const double f = (double(q) - L[k]) / (double(L[k + 1]) - L[k]);
  return float(double(k) + std::clamp(f, 0.0, 1.0));
}

int PaletteMatcher::nearestColour(const glm::vec3& lit, int* second) const {
  const glm::vec3 c = sanitize01(lit);
  const int C = kCells;
  const glm::ivec3 cell = glm::clamp(glm::ivec3(c * float(C)), 0, C - 1);
  const size_t ci = static_cast<size_t>((cell.z * C + cell.y) * C + cell.x);
  int best = -1, next = -1;
  float bd = std::numeric_limits<float>::infinity(), nd = bd;
  auto consider = [&](int t) {
    const glm::vec3 d = scaled_[static_cast<size_t>(t)] - c;
    const float dd = glm::dot(d, d);
    if (dd < bd || (dd == bd && t < best)) {
      next = best; nd = bd; best = t; bd = dd;
    } else if (dd < nd || (dd == nd && t < next)) {
      next = t; nd = dd;
    }
  };
  if (!second) {
    for (uint32_t i = cellStart_[ci]; i < cellStart_[ci + 1]; ++i) consider(cellCandidates_[i]);
    return std::max(best, 0);  // distances are finite (clamped colours), so best is set
  }
  // The second nearest may lie outside the cell's candidate list: scan all (smooth path only).
  for (int t = 0; t < n_; ++t) consider(t);
  best = std::max(best, 0);
  *second = next < 0 ? best : next;
  return best;
}

int PaletteMatcher::match(const glm::vec3& lit) const {
  if (mode_ == MatchMode::Colors) return nearestColour(lit, nullptr);
  const float q = query(lit);  // in [0, 3]
  const std::uint16_t e = exactBins_[static_cast<size_t>(static_cast<int>(q * (float(kExactBins) / 3.0f)))];
  return e != kAmbiguous ? e : matchQuery(q);
}

int PaletteMatcher::matchQuery(float q) const {
  const float u = toneOfQuery(q);
  const int k = static_cast<int>(u);
  const float f = u - float(k);
  if (k + 1 >= static_cast<int>(levelEntry_.size())) return levelEntry_[static_cast<size_t>(k)];
  const int a = levelEntry_[static_cast<size_t>(k)], b = levelEntry_[static_cast<size_t>(k + 1)];
  if (f < 0.5f) return a;
  if (f > 0.5f) return b;
  return std::min(a, b);
}

int PaletteMatcher::toneRank(float q) const {
  const float u = toneOfQuery(q);
  const int k = static_cast<int>(u);
  return (u - float(k)) <= 0.5f ? k : k + 1;
}

PaletteBlend PaletteMatcher::matchSmooth(const glm::vec3& lit) const {
  if (mode_ == MatchMode::Colors) {
    int second = 0;
    const int first = nearestColour(lit, &second);
    const glm::vec3 c = sanitize01(lit);
    const float da = glm::length(scaled_[static_cast<size_t>(first)] - c);
    const float db = glm::length(scaled_[static_cast<size_t>(second)] - c);
    // Inverse-distance weights: w_a = 1/da, w_b = 1/db, so b's share is da / (da + db).
    const float t = (da + db) > 0.0f ? da / (da + db) : 0.0f;
    return {first, second, t};
  }
  const float u = tonePosition(lit);
  const int k = static_cast<int>(u);
  const int last = static_cast<int>(levelEntry_.size()) - 1;
  if (k >= last) return {levelEntry_[static_cast<size_t>(last)], levelEntry_[static_cast<size_t>(last)], 0.0f};
  return {levelEntry_[static_cast<size_t>(k)], levelEntry_[static_cast<size_t>(k + 1)], u - float(k)};
}

// In the 1D modes a grey of channel q/3 has query q, so sampling greys samples the query axis.
std::vector<std::uint8_t> PaletteMatcher::buildLutIndex1D() const {
  std::vector<std::uint8_t> lut(kLut1DSize, 0);
  for (int i = 0; i < kLut1DSize; ++i)
    lut[static_cast<size_t>(i)] = static_cast<std::uint8_t>(match(glm::vec3(float(i) / float(kLut1DSize - 1))));
  return lut;
}

std::vector<float> PaletteMatcher::buildLutBlend1D() const {
  std::vector<float> lut(static_cast<size_t>(kLut1DSize) * 4, 0.0f);
  for (int i = 0; i < kLut1DSize; ++i) {
    const PaletteBlend b = matchSmooth(glm::vec3(float(i) / float(kLut1DSize - 1)));
    float* o = &lut[static_cast<size_t>(i) * 4];
    o[0] = float(b.a);
    o[1] = float(b.b);
    o[2] = b.t;
  }
  return lut;
}

std::vector<std::uint8_t> PaletteMatcher::buildLut3D() const {
  const int G = kLut3DSize;
  std::vector<std::uint8_t> lut(static_cast<size_t>(G) * G * G * 2, 0);
  if (mode_ != MatchMode::Colors) return lut;
  for (int z = 0; z < G; ++z)
    for (int y = 0; y < G; ++y)
      for (int x = 0; x < G; ++x) {
        const glm::vec3 c = glm::vec3(x, y, z) / float(G - 1);
        int second = 0;
        const int first = nearestColour(c, &second);
        const size_t i = (static_cast<size_t>(z) * G * G + static_cast<size_t>(y) * G + static_cast<size_t>(x)) * 2;
        lut[i] = static_cast<std::uint8_t>(first);
        lut[i + 1] = static_cast<std::uint8_t>(second);
      }
  return lut;
}

}  // namespace npr
