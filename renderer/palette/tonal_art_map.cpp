// Tonal art maps, stroke by stroke (see tonal_art_map.h).
#include "renderer/palette/tonal_art_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/core/colour.h"
#include "renderer/palette/palette_mipmaps.h"

namespace npr {
namespace {

// Deterministic and the same on every platform (std's distributions are not).
struct Rng {
  std::uint64_t state;
  std::uint64_t next() {
    state += 0x9e3779b97f4a7c15ull;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  float uniform() { return float(next() >> 40) / float(1u << 24); }
  float range(float a, float b) { return a + (b - a) * uniform(); }
  float jitter(float v, float j) { return v * (1.0f + range(-j, j)); }
};

// A mark in level 0's normalised coordinates (the tile is [0, 1)^2, y down); its width in
// texels of whatever level it is drawn in.
struct Mark {
  glm::vec2 centre{0.0f};
  glm::vec2 dir{1.0f, 0.0f};
  float length = 0;  // of the tile
  float width = 1;   // texels (a dot's radius for dots)
  float bend = 0;    // midpoint offset, fraction of the length
  float pressure = 1;
  float grain = 0;
  bool dot = false;
};

// The ink stamp: darkness x alpha, bilinear, rows top first.
struct Stamp {
  int w = 0, h = 0;
  std::vector<float> ink;
  float at(float x, float y) const {
    if (x < 0 || y < 0 || x > float(w - 1) || y > float(h - 1)) return 0.0f;
    const int x0 = std::min(int(x), w - 2 < 0 ? 0 : w - 2), y0 = std::min(int(y), h - 2 < 0 ? 0 : h - 2);
    const int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
    const float fx = x - float(x0), fy = y - float(y0);
    auto v = [&](int xx, int yy) { return ink[size_t(yy) * size_t(w) + size_t(xx)]; };
    return (v(x0, y0) * (1 - fx) + v(x1, y0) * fx) * (1 - fy) + (v(x0, y1) * (1 - fx) + v(x1, y1) * fx) * fy;
  }
};

Stamp makeStamp(const ImageRGBA8& img) {
  Stamp s{img.width, img.height, std::vector<float>(size_t(img.width) * size_t(img.height))};
  const auto& lin = srgbTable();
  for (size_t i = 0; i < s.ink.size(); ++i) {
    const std::uint8_t* p = &img.pixels[i * 4];
    const float luminance = 0.2126f * lin[p[0]] + 0.7152f * lin[p[1]] + 0.0722f * lin[p[2]];
    s.ink[i] = (1.0f - luminance) * (p[3] / 255.0f);
  }
  return s;
}

// One mip level of the tone level being drawn: ink coverage per texel and the running sum of
// what the screen shows (the texel composited over the paper on encoded values, as
// compositeOver does, in linear light), so the tone is known after every mark.
class Canvas {
 public:
  Canvas(const ImageRGBA8& paper, glm::vec3 ink) : paper_(&paper), size_(paper.width), cov_(size_t(paper.width) * size_t(paper.width), 0.0f) {
    for (int k = 0; k < 3; ++k) ink_[k] = toByte(ink[k]);
    for (size_t i = 0; i < cov_.size(); ++i) sum_ += shown(i, 0.0f);
  }
  int size() const { return size_; }
  // Tooth height 0..1 at texel i (1 without a tooth image).
  void setTooth(const ImageRGBA8& tooth) {
    tooth_.resize(cov_.size());
    for (size_t i = 0; i < cov_.size(); ++i) tooth_[i] = tooth.pixels[i * 4] / 255.0f;
  }
  float tooth(size_t i) const { return tooth_.empty() ? 1.0f : tooth_[i]; }
  float coverage(int x, int y) const { return cov_[index(x, y)]; }
  size_t index(int x, int y) const {
    const int n = size_;
    return size_t(((y % n) + n) % n) * size_t(n) + size_t(((x % n) + n) % n);
  }
  // Sum of the channels of the mean shown colour (encoded): the palette analysis's intensity.
  float intensity() const {
    const glm::dvec3 m = sum_ / double(cov_.size());
    return linearToSrgb(float(m.r)) + linearToSrgb(float(m.g)) + linearToSrgb(float(m.b));
  }
  void set(size_t i, float c) {
    sum_ += shown(i, c) - shown(i, cov_[i]);
    cov_[i] = c;
  }
  float at(size_t i) const { return cov_[i]; }
  ImageRGBA8 image() const {
    ImageRGBA8 img{size_, size_, std::vector<std::uint8_t>(cov_.size() * 4)};
    for (size_t i = 0; i < cov_.size(); ++i) {
      for (int k = 0; k < 3; ++k) img.pixels[i * 4 + size_t(k)] = ink_[k];
      img.pixels[i * 4 + 3] = toByte(cov_[i]);
    }
    return img;
  }

 private:
  glm::dvec3 shown(size_t i, float c) const {
    const auto& lin = srgbTable();
    const float a = toByte(c) / 255.0f;
    glm::dvec3 v;
    for (int k = 0; k < 3; ++k)
      v[k] = lin[toByte((a * float(ink_[k]) + (1.0f - a) * float(paper_->pixels[i * 4 + size_t(k)])) / 255.0f)];
    return v;
  }
  const ImageRGBA8* paper_;
  int size_;
  std::vector<float> cov_;
  std::vector<float> tooth_;
  std::uint8_t ink_[3]{};
  glm::dvec3 sum_{0.0};
};

struct Change {
  int canvas;
  size_t texel;
  float old;
};

// A mark's coverage at texel centre p (texels of a level of side n), 0 outside it.
float markCoverage(const Mark& m, glm::vec2 p, int n, const Stamp* stamp) {
  const glm::vec2 d = p - m.centre * float(n);
  if (m.dot) {
    const float r = m.width;
    return std::clamp(r - std::sqrt(glm::dot(d, d)) + 0.5f, 0.0f, 1.0f) * m.pressure;
  }
  const float half = 0.5f * m.length * float(n);
  const float s = glm::dot(d, m.dir);
  if (std::fabs(s) > half + 1.0f) return 0.0f;
  const float q = std::clamp(s / half, -1.0f, 1.0f);
  const float t = 0.5f * (q + 1.0f);
  const glm::vec2 perp(-m.dir.y, m.dir.x);
  const float v = glm::dot(d, perp) - m.bend * m.length * float(n) * (1.0f - q * q);
  const float ends = std::clamp(half - std::fabs(s) + 0.5f, 0.0f, 1.0f);
  if (stamp) {
    const float across = 3.0f * m.width;  // the stamp's height spans three stroke widths
    return stamp->at(t * float(stamp->w - 1), (v / across + 0.5f) * float(stamp->h - 1)) * m.pressure * ends;
  }
  // Pressure rises and falls along the stroke; the width tapers towards both ends.
  const float swell = std::sqrt(std::max(0.0f, std::sin(3.14159265f * t)));
  const float halfWidth = 0.5f * m.width * (0.3f + 0.7f * swell);
  const float pressure = m.pressure * (0.7f + 0.3f * swell);
  return std::clamp(halfWidth - std::fabs(v) + 0.5f, 0.0f, 1.0f) * pressure * ends;
}

// Draws a mark into a canvas (wrapping around the tile), recording what it changed.
void drawMark(const Mark& m, Canvas& c, int canvasIndex, const Stamp* stamp, std::vector<Change>& changes) {
  const int n = c.size();
  const glm::vec2 centre = m.centre * float(n);
  float rx, ry;
  if (m.dot) {
    rx = ry = m.width + 1.5f;
  } else {
    const float half = 0.5f * m.length * float(n) + 1.0f;
    const float across = (stamp ? 1.5f * m.width * 3.0f : m.width) + std::fabs(m.bend) * m.length * float(n) + 1.5f;
    rx = std::fabs(m.dir.x) * half + std::fabs(m.dir.y) * across;
    ry = std::fabs(m.dir.y) * half + std::fabs(m.dir.x) * across;
  }
  const int x0 = int(std::floor(centre.x - rx)), x1 = int(std::ceil(centre.x + rx));
  const int y0 = int(std::floor(centre.y - ry)), y1 = int(std::ceil(centre.y + ry));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const size_t i = c.index(x, y);
      const float a = markCoverage(m, glm::vec2(float(x) + 0.5f, float(y) + 0.5f), n, stamp) * (1.0f - m.grain * (1.0f - c.tooth(i)));
      if (a <= 0.0f) continue;
      const float old = c.at(i);
      changes.push_back({canvasIndex, i, old});
      c.set(i, 1.0f - (1.0f - old) * (1.0f - a));
    }
}

// Mitchell's best candidate on the unit torus: each new point is the candidate farthest from
// all earlier ones, so every prefix of the sequence is evenly spread (blue noise).
class BlueNoise {
 public:
  explicit BlueNoise(std::uint32_t seed) : rng_{seed * 0x2545f4914f6cdd1dull + 7}, cells_(size_t(kGrid) * kGrid) {}
  glm::vec2 next() {
    const int candidates = 12;
    glm::vec2 best(0.0f);
    float bestD = -1.0f;
    for (int k = 0; k < candidates; ++k) {
      const glm::vec2 c(rng_.uniform(), rng_.uniform());
      const float d = nearest(c);
      if (d > bestD) {
        bestD = d;
        best = c;
      }
    }
    const int cx = std::min(kGrid - 1, int(best.x * kGrid)), cy = std::min(kGrid - 1, int(best.y * kGrid));
    cells_[size_t(cy) * kGrid + size_t(cx)].push_back(best);
    ++count_;
    return best;
  }

 private:
  static constexpr int kGrid = 64;
  float nearest(glm::vec2 p) const {
    if (count_ == 0) return 1.0f;
    const int cx = std::min(kGrid - 1, int(p.x * kGrid)), cy = std::min(kGrid - 1, int(p.y * kGrid));
    float best = 1.0f;
    for (int r = 0; r <= kGrid / 2; ++r) {
      // Every point in ring r is at least (r - 1) cells away.
      if (best < float(r - 1) / kGrid) break;
      for (int j = -r; j <= r; ++j)
        for (int i = -r; i <= r; ++i) {
          if (std::max(std::abs(i), std::abs(j)) != r) continue;
          const auto& cell = cells_[size_t(((cy + j) % kGrid + kGrid) % kGrid) * kGrid + size_t(((cx + i) % kGrid + kGrid) % kGrid)];
          for (const glm::vec2& q : cell) {
            glm::vec2 d = glm::abs(p - q);
            d = glm::min(d, 1.0f - d);
            best = std::min(best, std::sqrt(glm::dot(d, d)));
          }
        }
    }
    return best;
  }
  Rng rng_;
  std::vector<std::vector<glm::vec2>> cells_;
  int count_ = 0;
};

}  // namespace

Result<TonalArtMap> buildTonalArtMap(const TamSpec& spec, const ImageRGBA8& paper, const std::function<void(double)>& progress) {
  if (spec.size < 16 || spec.size > 2048 || (spec.size & (spec.size - 1)) != 0)
    return Error{"tonal art map size must be a power of two from 16 to 2048, got " + std::to_string(spec.size)};
  if (spec.tones < 2 || spec.tones > 256) return Error{"tonal art map needs 2..256 levels, got " + std::to_string(spec.tones)};
  if (spec.strokeLevels < 1 || mipSide(spec.size, spec.strokeLevels - 1) < kMinMipSide)
    return Error{"tonal art map: " + std::to_string(spec.strokeLevels) + " stroke levels from " + std::to_string(spec.size) +
                 " go below " + std::to_string(kMinMipSide) + " texels"};
  if (!spec.dots && spec.families.empty()) return Error{"tonal art map: no stroke families"};
  if (!(spec.darkest > 0.0f && spec.darkest <= 1.0f)) return Error{"tonal art map: darkest must be in (0, 1]"};
  if (paper.width != spec.size || paper.height != spec.size || paper.pixels.size() != size_t(spec.size) * size_t(spec.size) * 4)
    return Error{"tonal art map: the paper must be " + std::to_string(spec.size) + "x" + std::to_string(spec.size)};

  const std::vector<ImageRGBA8> paperChain = mipChain(paper, spec.strokeLevels);
  std::vector<Canvas> canvas;
  if (spec.tooth && (spec.tooth->width != spec.size || spec.tooth->height != spec.size))
    return Error{"tonal art map: the tooth image must be " + std::to_string(spec.size) + "x" + std::to_string(spec.size)};
  const std::vector<ImageRGBA8> toothChain = spec.tooth ? mipChain(*spec.tooth, spec.strokeLevels) : std::vector<ImageRGBA8>{};
  for (const ImageRGBA8& p : paperChain) {
    canvas.emplace_back(p, spec.ink);
    if (spec.tooth) canvas.back().setTooth(toothChain[canvas.size() - 1]);
  }
  const std::optional<Stamp> stamp = spec.stamp ? std::optional<Stamp>(makeStamp(*spec.stamp)) : std::nullopt;
  const Stamp* stampPtr = stamp ? &*stamp : nullptr;

  const float paperTone = canvas[0].intensity();
  const float inkTone = [&] {
    float t = 0;
    for (int k = 0; k < 3; ++k) t += toByte(spec.ink[k]) / 255.0f;
    return t;
  }();
  const float darkestTone = paperTone + spec.darkest * (inkTone - paperTone);
  // Each mark is accepted only if it leaves the level within this of its target (intensity is
  // 0..3): a mark that would overshoot is drawn shorter until it fits.
  const float tolerance = 0.004f;

  TonalArtMap out;
  Rng rng{spec.seed};
  BlueNoise noise(spec.seed);
  int family = 0, totalMarks = 0;
  for (int t = 0; t < spec.tones; ++t) {
    const float target = paperTone + (darkestTone - paperTone) * float(t) / float(spec.tones - 1);
    out.targets.push_back(target);
    const float darkness = float(t) / float(spec.tones - 1) * spec.darkest;
    std::vector<int> active;
    for (size_t f = 0; f < spec.families.size(); ++f)
      if (darkness > spec.families[f].joinsAt || f == 0) active.push_back(int(f));
    for (int m = spec.strokeLevels - 1; m >= 0 && t > 0; --m) {
      int attempts = 0;
      while (canvas[size_t(m)].intensity() > target + tolerance) {
        if (++attempts > spec.maxMarksPerLevel) {
          out.notes.push_back("level " + std::to_string(t) + " mip " + std::to_string(m) + " stopped at tone " +
                              std::to_string(canvas[size_t(m)].intensity()) + " short of " + std::to_string(target));
          break;
        }
        Mark mark;
        if (spec.dots) {
          mark.dot = true;
          mark.centre = noise.next();
          mark.width = spec.dotRadius * rng.range(0.9f, 1.1f);
          mark.pressure = rng.range(0.9f, 1.0f);
        } else {
          const StrokeFamily& fam = spec.families[size_t(active[size_t(family++ % int(active.size()))])];
          // The best of a few candidates: the one over the least ink, so strokes spread evenly.
          float bestInk = 2.0f;
          for (int k = 0; k < 6; ++k) {
            Mark c;
            const float a = (fam.degrees + rng.range(-fam.degreesJitter, fam.degreesJitter)) * 3.14159265f / 180.0f;
            c.dir = glm::vec2(std::cos(a), -std::sin(a));
            c.centre = glm::vec2(rng.uniform(), rng.uniform());
            c.length = std::min(0.8f, rng.jitter(fam.length, fam.lengthJitter));
            c.width = std::max(0.5f, rng.jitter(fam.width, fam.widthJitter));
            c.bend = rng.range(-fam.bend, fam.bend);
            c.pressure = std::min(1.0f, rng.jitter(fam.pressure, fam.pressureJitter));
            c.grain = fam.grain;
            const int n = canvas[size_t(m)].size();
            float ink = 0.0f;
            for (int j = 0; j < 8; ++j) {
              const glm::vec2 p = (c.centre + c.dir * c.length * ((float(j) + 0.5f) / 8.0f - 0.5f)) * float(n);
              ink += canvas[size_t(m)].coverage(int(std::floor(p.x)), int(std::floor(p.y)));
            }
            if (ink < bestInk * 8.0f) {
              bestInk = ink / 8.0f;
              mark = c;
            }
          }
        }
        // Drawn in this level and every finer one; shortened while it overshoots.
        for (int tries = 0;; ++tries) {
          std::vector<Change> changes;
          for (int fine = m; fine >= 0; --fine) drawMark(mark, canvas[size_t(fine)], fine, stampPtr, changes);
          const float now = canvas[size_t(m)].intensity();
          if (now >= target - tolerance || tries == 6) break;
          for (auto it = changes.rbegin(); it != changes.rend(); ++it) canvas[size_t(it->canvas)].set(it->texel, it->old);
          if (mark.dot) mark.pressure *= 0.6f;
          else mark.length *= 0.6f;
        }
        ++totalMarks;
      }
    }
    TamLevel level;
    for (const Canvas& c : canvas) {
      level.mips.push_back(c.image());
      level.tone.push_back(c.intensity());
    }
    level.marks = totalMarks;
    out.levels.push_back(std::move(level));
    if (progress) progress(double(t + 1) / spec.tones);
  }
  return out;
}

}  // namespace npr
