// Line drawing comparisons (see line_comparison.h).
#include "line_comparison.h"

#include <algorithm>
#include <cmath>

namespace npr::test {

int LineMask::count() const { return int(std::count(ink.begin(), ink.end(), 1)); }

LineMask lineMask(const ImageRGBA8& img) {
  LineMask m{img.width, img.height, std::vector<char>(std::size_t(img.width) * std::size_t(img.height))};
  for (std::size_t i = 0; i < m.ink.size(); ++i) {
    const std::uint8_t* p = &img.pixels[i * 4];
    // Composited over white (rsvg-convert leaves the ground transparent; renders are opaque).
    const float a = p[3] / 255.0f;
    m.ink[i] = (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f * a + (1.0f - a) < 0.5f;
  }
  return m;
}

double nearShare(const LineMask& a, const LineMask& b, int radius) {
  int n = 0, near = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!a.at(x, y)) continue;
      ++n;
      bool found = false;
      for (int dy = -radius; dy <= radius && !found; ++dy)
        for (int dx = -radius; dx <= radius && !found; ++dx) found = b.at(x + dx, y + dy);
      near += found;
    }
  return n ? double(near) / n : 0.0;
}

std::vector<float> widthsAcross(const LineMask& mask, const std::vector<FeatureLine>& edges, const CameraMatrices& camera) {
  const glm::mat4 mvp = camera.projection * camera.view;
  auto toPixels = [&](const glm::vec3& p, bool& ok) {
    const glm::vec4 c = mvp * glm::vec4(p, 1.0f);
    ok = ok && c.w > 1e-6f;
    return glm::vec2((c.x / c.w * 0.5f + 0.5f) * float(mask.width), (0.5f - c.y / c.w * 0.5f) * float(mask.height));
  };
  std::vector<float> widths;
  for (const FeatureLine& e : edges) {
    bool ok = true;
    const glm::vec2 a = toPixels(e.a, ok), b = toPixels(e.b, ok);
    const glm::vec2 d = b - a;
    if (!ok || glm::length(d) < 2.0f) continue;
    const glm::vec2 n = glm::vec2(-d.y, d.x) / glm::length(d);
    const glm::vec2 mid = 0.5f * (a + b);
    // Start from ink within a pixel of the midpoint (the edge may sit on either side of it).
    float start = NAN;
    for (float t : {0.0f, -1.0f, 1.0f})
      if (std::isnan(start) && mask.at(int(std::floor(mid.x + n.x * t)), int(std::floor(mid.y + n.y * t)))) start = t;
    if (std::isnan(start)) continue;
    // Walk both ways in half-pixel steps until the ink ends (at most 40 pixels each way).
    auto run = [&](float dir) {
      float t = start;
      while (std::abs(t - start) < 40.0f && mask.at(int(std::floor(mid.x + n.x * (t + dir * 0.5f))), int(std::floor(mid.y + n.y * (t + dir * 0.5f)))))
        t += dir * 0.5f;
      return t;
    };
    widths.push_back(run(1.0f) - run(-1.0f) + 0.5f);
  }
  return widths;
}

Spread spreadOf(std::vector<float> v) {
  Spread s;
  s.samples = int(v.size());
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  auto at = [&](double q) { return v[std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5))]; };
  s.median = at(0.5);
  s.p10 = at(0.1);
  s.p90 = at(0.9);
  return s;
}

}  // namespace npr::test
