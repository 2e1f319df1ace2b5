// Gradient-orientation histogram of a palette texture (see palette_orientation.h).
#include "renderer/palette/palette_orientation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace npr {

TextureOrientation textureOrientation(const ImageRGBA8& img, const glm::vec3& bg) {
  TextureOrientation out;
  if (img.width < 3 || img.height < 3 || img.pixels.size() < size_t(img.width) * size_t(img.height) * 4) return out;
  // A corner of at most 512 x 512 texels decides (strokes are a texture-wide property; large
  // entries would cost a palette load seconds): tiled only when the image is that small.
  const int w = std::min(img.width, 512), h = std::min(img.height, 512);
  std::vector<float> lum(size_t(w) * size_t(h));
  const float bgLum = 0.2126f * bg.r + 0.7152f * bg.g + 0.0722f * bg.b;
  for (size_t i = 0; i < lum.size(); ++i) {
    const std::uint8_t* p = &img.pixels[((i / size_t(w)) * size_t(img.width) + i % size_t(w)) * 4];
    const float a = p[3] / 255.0f;
    const float l = (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f;
    lum[i] = a * l + (1.0f - a) * bgLum;
  }
  // Smoothed by a binomial [1 2 1]^2 (tiling) before differencing: central differences of
  // single-texel dots point only along the axes, which would read as crosshatch.
  {
    std::vector<float> tmp(lum.size());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        tmp[size_t(y) * w + x] = 0.25f * lum[size_t(y) * w + (x + w - 1) % w] + 0.5f * lum[size_t(y) * w + x] + 0.25f * lum[size_t(y) * w + (x + 1) % w];
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        lum[size_t(y) * w + x] = 0.25f * tmp[size_t((y + h - 1) % h) * w + x] + 0.5f * tmp[size_t(y) * w + x] + 0.25f * tmp[size_t((y + 1) % h) * w + x];
  }
  // One-degree bins of gradient orientation in [0, 180).
  constexpr int kBins = 180;
  std::vector<double> hist(kBins, 0.0);
  double total = 0.0;
  for (int y = 0; y < h; ++y) {
    const int yu = (y + h - 1) % h, yd = (y + 1) % h;  // rows are stored top first
    for (int x = 0; x < w; ++x) {
      const int xl = (x + w - 1) % w, xr = (x + 1) % w;
      const float gx = lum[size_t(y) * w + xr] - lum[size_t(y) * w + xl];
      const float gy = lum[size_t(yu) * w + x] - lum[size_t(yd) * w + x];  // screen y points up
      const double e = double(gx) * gx + double(gy) * gy;
      if (!(e > 1e-8)) continue;
      double a = std::atan2(double(gy), double(gx)) * 180.0 / M_PI;
      a = std::fmod(a + 360.0, 180.0);
      hist[size_t(std::min(kBins - 1, int(a)))] += e;
      total += e;
    }
  }
  if (!(total > 0.0)) return out;
  // The peak of the histogram smoothed over +-7 degrees (circularly).
  int peak = 0;
  double best = -1.0;
  for (int b = 0; b < kBins; ++b) {
    double s = 0.0;
    for (int k = -7; k <= 7; ++k) s += hist[size_t((b + k + kBins) % kBins)];
    if (s > best) {
      best = s;
      peak = b;
    }
  }
  // Refined as the mean doubled angle within +-15 degrees of the peak; that window's share is
  // the strength.
  double c = 0.0, s = 0.0, near = 0.0;
  for (int k = -15; k <= 15; ++k) {
    const int b = (peak + k + kBins) % kBins;
    const double angle = 2.0 * (b + 0.5) * M_PI / 180.0;
    c += hist[size_t(b)] * std::cos(angle);
    s += hist[size_t(b)] * std::sin(angle);
    near += hist[size_t(b)];
  }
  const double gradient = 0.5 * std::atan2(s, c) * 180.0 / M_PI;
  out.degrees = float(std::fmod(gradient + 90.0 + 360.0, 180.0));  // strokes run across the gradient
  out.strength = float(near / total);
  return out;
}

std::optional<float> sharedStrokeDegrees(const std::vector<TextureOrientation>& entries) {
  constexpr double kRadians = M_PI / 180.0;
  double c = 0.0, s = 0.0;
  for (const TextureOrientation& e : entries)
    if (e.oriented()) {
      c += std::cos(2.0 * kRadians * e.degrees);
      s += std::sin(2.0 * kRadians * e.degrees);
    }
  if (c * c + s * s < 1e-12) return std::nullopt;  // none oriented, or opposed so they cancel
  double mean = 0.5 * std::atan2(s, c) / kRadians;
  if (mean < 0.0) mean += 180.0;
  for (const TextureOrientation& e : entries) {
    if (!e.oriented()) continue;
    const double d = std::fmod(std::fabs(double(e.degrees) - mean), 180.0);
    if (std::min(d, 180.0 - d) > kSharedStrokeTolerance) return std::nullopt;
  }
  return float(mean >= 180.0 ? mean - 180.0 : mean);
}

}  // namespace npr
