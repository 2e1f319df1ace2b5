// CPU tier: the tests' measure of how far an image's content moved (support/phase_correlation.h).
// A band-limited random texture sampled again shifted by known fractions of a pixel is found
// shifted by that much, within 0.05 pixel; hard-edged strokes in two directions, as the
// palettes draw, within 0.1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "support/phase_correlation.h"

namespace npr {
namespace {

constexpr int kSize = 128, kWindow = 96, kMargin = 16;

// The texture f sampled at p - d for every pixel p: the image of f moved by d.
template <class F>
ImageRGBA8 sampled(F f, glm::vec2 d) {
  ImageRGBA8 img{kSize, kSize, std::vector<std::uint8_t>(std::size_t(kSize) * kSize * 4, 255)};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto v = std::uint8_t(std::lround(std::clamp(f(float(x) - d.x, float(y) - d.y), 0.0f, 255.0f)));
      std::uint8_t* p = &img.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
      p[0] = p[1] = p[2] = v;
    }
  return img;
}

TEST(PhaseCorrelation, FindsKnownSubpixelShifts) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  struct Wave { float fx, fy, phase; };
  std::vector<Wave> waves;
  for (int i = 0; i < 40; ++i) waves.push_back({(u(rng) - 0.5f) * 0.8f, (u(rng) - 0.5f) * 0.8f, u(rng) * 6.283f});
  auto smooth = [&](float x, float y) {
    float s = 0.0f;
    for (const Wave& w : waves) s += std::cos(w.fx * x + w.fy * y + w.phase);
    return 128.0f + 12.0f * s;
  };
  // Hard-edged marks, as the palettes draw: 300 random strokes 1.5 pixels wide, in two
  // directions (one direction alone would leave a shift along the strokes unmeasurable),
  // supersampled 4 x 4 so a fractional shift moves their edges' coverage, as a filtered lookup
  // does.
  struct Stroke { glm::vec2 centre, direction; };
  std::vector<Stroke> strokes;
  for (int i = 0; i < 300; ++i) {
    const float a = (i % 2 ? 0.7f : 2.3f) + 0.2f * u(rng);
    strokes.push_back({glm::vec2(u(rng), u(rng)) * float(kSize + 40) - 20.0f, glm::vec2(std::cos(a), std::sin(a))});
  }
  // Each 8-pixel cell lists the strokes that reach into it, so a sample tests a few strokes,
  // not all (the test stays quick under the sanitizers).
  constexpr float kCell = 8.0f, kOrigin = -32.0f;
  constexpr int kCells = (kSize + 64) / 8;
  std::vector<std::vector<int>> cells(std::size_t(kCells) * kCells);
  auto cellOf = [&](float v) { return std::clamp(int(std::floor((v - kOrigin) / kCell)), 0, kCells - 1); };
  for (int k = 0; k < int(strokes.size()); ++k) {
    const glm::vec2 c = strokes[std::size_t(k)].centre;
    for (int cy = cellOf(c.y - 9.0f); cy <= cellOf(c.y + 9.0f); ++cy)
      for (int cx = cellOf(c.x - 9.0f); cx <= cellOf(c.x + 9.0f); ++cx) cells[std::size_t(cy) * kCells + std::size_t(cx)].push_back(k);
  }
  auto hatch = [&](float x, float y) {
    float ink = 0.0f;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const glm::vec2 p(x + (float(i) + 0.5f) / 4.0f, y + (float(j) + 0.5f) / 4.0f);
        for (int k : cells[std::size_t(cellOf(p.y)) * kCells + std::size_t(cellOf(p.x))]) {
          const Stroke& s = strokes[std::size_t(k)];
          const glm::vec2 q = p - s.centre;
          const float along = glm::dot(q, s.direction), across = q.x * s.direction.y - q.y * s.direction.x;
          if (std::fabs(along) < 8.0f && std::fabs(across) < 0.75f) {
            ink += 1.0f;
            break;
          }
        }
      }
    return 240.0f - 200.0f * ink / 16.0f;
  };
  for (const glm::vec2 d : {glm::vec2(0.0f), glm::vec2(3.3f, -2.6f), glm::vec2(-7.75f, 5.5f), glm::vec2(0.4f, 0.1f)}) {
    const glm::vec2 s = test::phaseCorrelationShift(sampled(smooth, glm::vec2(0.0f)), sampled(smooth, d), kMargin, kMargin, kWindow);
    EXPECT_NEAR(s.x, d.x, 0.05f) << "smooth, shift " << d.x << ", " << d.y;
    EXPECT_NEAR(s.y, d.y, 0.05f) << "smooth, shift " << d.x << ", " << d.y;
    const glm::vec2 h = test::phaseCorrelationShift(sampled(hatch, glm::vec2(0.0f)), sampled(hatch, d), kMargin, kMargin, kWindow);
    std::printf("shift (%.2f, %.2f): smooth (%.3f, %.3f), strokes (%.3f, %.3f)\n", double(d.x), double(d.y), double(s.x), double(s.y), double(h.x),
                double(h.y));
    EXPECT_NEAR(h.x, d.x, 0.1f) << "hatching, shift " << d.x << ", " << d.y;
    EXPECT_NEAR(h.y, d.y, 0.1f) << "hatching, shift " << d.x << ", " << d.y;
  }
}

}  // namespace
}  // namespace npr
