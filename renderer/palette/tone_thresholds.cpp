// Per-texel tone thresholds for crisp tone (see tone_thresholds.h).
#include "renderer/palette/tone_thresholds.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "renderer/core/colour.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_mipmaps.h"

namespace npr {
namespace {

// A texel's light: the mean of its channels in linear light (alpha is ignored: the layers are
// stored composited over the paper).
std::vector<float> lightOf(const ImageRGBA8& img) {
  const auto& lin = srgbTable();
  std::vector<float> out(std::size_t(img.width) * std::size_t(img.height));
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = (lin[img.pixels[4 * i]] + lin[img.pixels[4 * i + 1]] + lin[img.pixels[4 * i + 2]]) / 3.0f;
  return out;
}

constexpr float kChange = 0.05f;       // less added darkness than this is not a mark
constexpr int kPiecesPerLevel = 16;    // no mark carries more than this share of a level's darkness
constexpr double kMarkCover = 0.6;      // the share of texels a step may darken, on average
constexpr double kConcentrated = 0.3;   // how much of a texel's darkening one step must do (0 even .. 1 one step)

}  // namespace

Result<std::vector<std::uint8_t>> toneThresholds(const std::vector<const ImageRGBA8*>& levels, bool requireMarks) {
  if (levels.size() < 2) return Error{"a threshold map needs at least two levels"};
  const int w = levels[0]->width, h = levels[0]->height;
  for (const ImageRGBA8* img : levels)
    if (img->width != w || img->height != h) return Error{"the levels differ in size"};
  const std::size_t n = std::size_t(w) * std::size_t(h);
  if (n == 0) return Error{"the levels are empty"};
  std::vector<std::vector<float>> light;
  for (const ImageRGBA8* img : levels) light.push_back(lightOf(*img));
  // Nested: each level keeps the marks of the lighter one.
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    std::size_t lighter = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (light[k + 1][i] > light[k][i] + 0.1f) ++lighter;
    if (lighter * 50 > n)
      return Error{"levels " + std::to_string(k + 1) + " and " + std::to_string(k + 2) + " (lightest first) are not nested: " +
                   std::to_string(lighter * 100 / n) + "% of the texels get lighter"};
  }
  // Marks, not a ramp: each step of a tonal art map adds strokes or dots over part of the tile
  // and leaves the rest; a flat or tinted ladder (cel, Gooch, wood) changes every texel at
  // every step, and the mix suits it. The share of texels a step darkens by more than kChange,
  // averaged over the steps, must stay below kMarkCover.
  if (requireMarks) {
    double cover = 0;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
      std::size_t changed = 0;
      for (std::size_t i = 0; i < n; ++i) changed += light[k][i] - light[k + 1][i] > kChange;
      cover += double(changed) / double(n) / double(levels.size() - 1);
    }
    // And a texel's darkening comes mostly at one step (where a stroke lands), not spread
    // evenly over the steps as a ramp's: the share at its largest step, weighted by the
    // darkening, scaled so that an even spread is 0 and a single step 1.
    double largest = 0, all = 0;
    for (std::size_t i = 0; i < n; ++i) {
      float step = 0;
      for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        const float d = std::max(0.0f, light[k][i] - light[k + 1][i]);
        step = std::max(step, d);
        all += d;
      }
      largest += step;
    }
    const double even = 1.0 / double(levels.size() - 1);
    const double concentration = all > 0 && even < 1.0 ? (largest / all - even) / (1.0 - even) : 1.0;
    if (!(cover < kMarkCover) || !(concentration >= kConcentrated))
      return Error{"levels are a ramp rather than marks added step by step (each step darkens " + std::to_string(int(100 * cover)) +
                   "% of the texels; " + std::to_string(int(100 * concentration)) +
                   "% concentration of a texel's darkening in one step): the mix suits them"};
  }
  // Each texel belongs to the pair of levels where it darkens most.
  std::vector<int> pairOf(n, -1);
  std::vector<float> added(n, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
      const float d = light[k][i] - light[k + 1][i];
      if (d > kChange && d > added[i]) {
        added[i] = d;
        pairOf[i] = int(k);
      }
    }
  std::vector<std::uint8_t> out(n, 128);
  std::vector<char> seen(n, 0);
  std::mt19937 rng(0x70e5);
  std::vector<std::uint32_t> queue;
  for (int pair = 0; pair + 1 < int(levels.size()); ++pair) {
    // The pair's marks: 8-connected texels it adds, wrapping like the tile, each as its flood
    // fill's order, cut into pieces of at most 1/kPiecesPerLevel of the pair's darkness.
    double total = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (pairOf[i] == pair) total += added[i];
    if (!(total > 0)) continue;
    const double piece = total / kPiecesPerLevel;
    std::vector<std::vector<std::uint32_t>> marks;
    for (std::size_t start = 0; start < n; ++start) {
      if (pairOf[start] != pair || seen[start]) continue;
      queue.assign(1, std::uint32_t(start));
      seen[start] = 1;
      marks.emplace_back();
      double weight = 0;
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::uint32_t t = queue[q];
        if (weight + added[t] > piece && !marks.back().empty()) {
          marks.emplace_back();
          weight = 0;
        }
        marks.back().push_back(t);
        weight += added[t];
        const int x = int(t % std::uint32_t(w)), y = int(t / std::uint32_t(w));
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = (x + dx + w) % w, ny = (y + dy + h) % h;
            const std::uint32_t u = std::uint32_t(ny) * std::uint32_t(w) + std::uint32_t(nx);
            if (pairOf[u] == pair && !seen[u]) {
              seen[u] = 1;
              queue.push_back(u);
            }
          }
      }
    }
    std::shuffle(marks.begin(), marks.end(), rng);
    double before = 0;
    for (const auto& mark : marks) {
      double weight = 0;
      for (std::uint32_t t : mark) weight += added[t];
      // The middle of the mark's share: it shows once the weight passes it.
      const float f = float((before + 0.5 * weight) / total);
      for (std::uint32_t t : mark) out[t] = toByte(f);
      before += weight;
    }
  }
  return out;
}

Result<std::vector<std::uint8_t>> paletteToneThresholds(const Palette& p, const std::vector<std::vector<ImageRGBA8>>& chains,
                                                        std::size_t level, int row) {
  const std::size_t columns = std::size_t(p.columns());
  if (chains.size() != p.entries.size() || columns < 2 || row < 0 || row >= std::max(p.axis.rows, 1)) return Error{"it has fewer than two entries"};
  if (!layersPrecomposited(p)) return Error{"its background image differs in size from its entries"};
  std::vector<std::size_t> order(columns);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::size_t(row) * columns + i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.entries[a].intensity > p.entries[b].intensity; });
  std::vector<const ImageRGBA8*> lightToDark;
  for (std::size_t i : order) {
    if (level >= chains[i].size()) return Error{"an entry lacks mip level " + std::to_string(level)};
    lightToDark.push_back(&chains[i][level]);
  }
  Result<std::vector<std::uint8_t>> t = toneThresholds(lightToDark, level == 0);
  if (!t) return Error{"its " + t.error()};
  return t;
}

Result<std::vector<std::uint8_t>> paletteToneThresholds(const Palette& p) {
  const bool pre = layersPrecomposited(p);
  const std::vector<ImageRGBA8> bg = pre && p.backgroundImage ? mipChain(*p.backgroundImage, 1) : std::vector<ImageRGBA8>{};
  std::vector<std::vector<ImageRGBA8>> chains;
  for (const PaletteEntry& e : p.entries) chains.push_back(entryMipChain(e, 1, pre, p.backgroundColour, bg));
  for (int r = 0; r < std::max(p.axis.rows, 1); ++r) {
    Result<std::vector<std::uint8_t>> t = paletteToneThresholds(p, chains, 0, r);
    if (!t || r + 1 == std::max(p.axis.rows, 1)) return p.axis.rows > 1 && !t ? Error{"row " + std::to_string(r + 1) + ": " + t.error()} : t;
  }
  return Error{"it has no entries"};
}

ToneBlendMeasure measureToneBlend(const std::vector<const ImageRGBA8*>& levels, const std::vector<std::uint8_t>& thresholds,
                                  std::size_t pair, double w) {
  ToneBlendMeasure m;
  if (pair + 1 >= levels.size()) return m;
  const std::vector<float> a = lightOf(*levels[pair]), b = lightOf(*levels[pair + 1]);
  if (a.size() != thresholds.size() || b.size() != a.size() || a.empty()) return m;
  const auto meanAndSpread = [](const std::vector<double>& v) {
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
    double var = 0;
    for (double x : v) var += (x - mean) * (x - mean);
    return std::pair{mean, std::sqrt(var / double(v.size()))};
  };
  std::vector<double> crisp(a.size()), mixed(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    // As the shader compares: the weight against the stored byte's fraction.
    crisp[i] = w > thresholds[i] / 255.0 ? b[i] : a[i];
    mixed[i] = (1.0 - w) * a[i] + w * b[i];
  }
  const auto [ma, sa] = meanAndSpread(std::vector<double>(a.begin(), a.end()));
  const auto [mb, sb] = meanAndSpread(std::vector<double>(b.begin(), b.end()));
  const auto [mc, sc] = meanAndSpread(crisp);
  const auto [mm, sm] = meanAndSpread(mixed);
  // The tone as a position in levels (plain variables for clang 14's lambdas, as below).
  const double meanA = ma, meanB = mb;
  const auto position = [&](double mean) { return double(pair) + (meanA != meanB ? (meanA - mean) / (meanA - meanB) : w); };
  // Grey: between a quarter and three quarters of the way from the darkest texel to the lightest.
  // Plain variables, not a structured binding: the lambda below captures them (clang 14 cannot).
  const double lo = std::min(*std::min_element(a.begin(), a.end()), *std::min_element(b.begin(), b.end()));
  const double hi = std::max(*std::max_element(a.begin(), a.end()), *std::max_element(b.begin(), b.end()));
  const auto grey = [&](const auto& v) {
    std::size_t count = 0;
    for (const auto x : v) {
      const double u = hi > lo ? (double(x) - lo) / (hi - lo) : 0.0;
      count += u > 0.25 && u < 0.75;
    }
    return double(count) / double(v.size());
  };
  m.thresholdGrey = grey(crisp);
  m.mixGrey = grey(mixed);
  m.singleGrey = (1.0 - w) * grey(a) + w * grey(b);
  m.thresholdTone = position(mc);
  m.mixTone = position(mm);
  m.thresholdSpread = sc;
  m.mixSpread = sm;
  m.single = (1.0 - w) * sa + w * sb;
  return m;
}

}  // namespace npr
