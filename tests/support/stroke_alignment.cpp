// Stroke orientation measures (see stroke_alignment.h).
#include "support/stroke_alignment.h"

#include <algorithm>
#include <cmath>

namespace npr::test {
namespace {

// Separable Gaussian blur of one channel, clamped at the edges.
std::vector<float> blur(const std::vector<float>& in, int w, int h, float sigma) {
  const int r = std::max(1, int(std::ceil(3.0f * sigma)));
  std::vector<float> k(size_t(2 * r + 1));
  float sum = 0.0f;
  for (int i = -r; i <= r; ++i) sum += k[size_t(i + r)] = std::exp(-0.5f * float(i * i) / (sigma * sigma));
  for (float& v : k) v /= sum;
  std::vector<float> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float s = 0.0f;
      for (int i = -r; i <= r; ++i) s += k[size_t(i + r)] * in[size_t(y) * w + std::clamp(x + i, 0, w - 1)];
      tmp[size_t(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float s = 0.0f;
      for (int i = -r; i <= r; ++i) s += k[size_t(i + r)] * tmp[size_t(std::clamp(y + i, 0, h - 1)) * w + x];
      out[size_t(y) * w + x] = s;
    }
  return out;
}

double lineDifference(double a, double b) {  // radians, lines (mod pi)
  double d = std::fmod(std::fabs(a - b), M_PI);
  return std::min(d, M_PI - d);
}

}  // namespace

StrokeOrientation strokeOrientation(const ImageRGBA8& img, float sigma) {
  StrokeOrientation o;
  const int w = img.width, h = img.height;
  o.width = w;
  o.height = h;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  std::vector<float> lum(n);
  for (std::size_t i = 0; i < n; ++i)
    lum[i] = (0.2126f * img.pixels[i * 4] + 0.7152f * img.pixels[i * 4 + 1] + 0.0722f * img.pixels[i * 4 + 2]) / 255.0f;
  std::vector<float> jxx(n, 0.0f), jxy(n, 0.0f), jyy(n, 0.0f);
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const float gx = 0.5f * (lum[i + 1] - lum[i - 1]);
      const float gy = 0.5f * (lum[i - size_t(w)] - lum[i + size_t(w)]);  // y up
      jxx[i] = gx * gx;
      jxy[i] = gx * gy;
      jyy[i] = gy * gy;
    }
  jxx = blur(jxx, w, h, sigma);
  jxy = blur(jxy, w, h, sigma);
  jyy = blur(jyy, w, h, sigma);
  o.angle.resize(n);
  o.coherence.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = jxx[i], b = jxy[i], c = jyy[i];
    const double tr = a + c, d = std::sqrt((a - c) * (a - c) + 4.0 * b * b);
    const double gradient = 0.5 * std::atan2(2.0 * b, a - c);  // dominant gradient direction
    o.angle[i] = float(std::fmod(gradient + 0.5 * M_PI + 2.0 * M_PI, M_PI));
    o.coherence[i] = tr > 1e-9 ? float(d / tr) : 0.0f;
  }
  return o;
}

Alignment strokeAlignment(const ImageRGBA8& img, const ImageRGBA32F& wanted, double offset, double minCoherence) {
  Alignment out;
  const StrokeOrientation o = strokeOrientation(img);
  std::vector<double> errors;
  for (std::size_t i = 0; i < o.angle.size() && i * 4 + 1 < wanted.pixels.size(); ++i) {
    if (wanted.pixels[i * 4 + 1] < 0.5f || o.coherence[i] < minCoherence) continue;
    errors.push_back(lineDifference(o.angle[i], double(wanted.pixels[i * 4]) + offset) * 180.0 / M_PI);
  }
  out.pixels = errors.size();
  if (!errors.empty()) {
    std::nth_element(errors.begin(), errors.begin() + long(errors.size() / 2), errors.end());
    out.medianDegrees = errors[errors.size() / 2];
  }
  return out;
}

double stepJumpFraction(const ImageRGBA32F& anglesNow, const ImageRGBA32F& eyeNow, const CameraMatrices& cameraNow,
                        const ImageRGBA32F& anglesNext, const ImageRGBA32F& eyeNext, const CameraMatrices& cameraNext, int bins,
                        float entryAngle, std::size_t* compared) {
  const int w = eyeNow.width, h = eyeNow.height;
  const glm::mat4 toObject = glm::inverse(cameraNow.view);
  const glm::mat4 viewNext = cameraNext.view, projNext = cameraNext.projection;
  auto step = [&](float angle) {
    double t = (double(angle) - entryAngle) * bins / M_PI;
    t -= bins * std::floor(t / bins);
    return std::min(bins - 1, int(t));
  };
  std::size_t n = 0, jumps = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (eyeNow.pixels[i * 4 + 3] == 0.0f || anglesNow.pixels[i * 4 + 1] < 0.5f) continue;
      const glm::vec4 object = toObject * glm::vec4(eyeNow.pixels[i * 4], eyeNow.pixels[i * 4 + 1], eyeNow.pixels[i * 4 + 2], 1.0f);
      const glm::vec4 eye = viewNext * object;
      const glm::vec4 c = projNext * eye;
      if (!(c.w > 0.0f)) continue;
      const glm::vec2 win = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(w, h);
      const int qx = int(std::floor(win.x)), qy = h - 1 - int(std::floor(win.y));
      if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
      const std::size_t j = std::size_t(qy) * w + qx;
      if (eyeNext.pixels[j * 4 + 3] == 0.0f || anglesNext.pixels[j * 4 + 1] < 0.5f) continue;
      const glm::vec3 seen(eyeNext.pixels[j * 4], eyeNext.pixels[j * 4 + 1], eyeNext.pixels[j * 4 + 2]);
      if (glm::length(seen - glm::vec3(eye)) > 0.01f * std::max(1.0f, -eye.z)) continue;  // hidden in the next frame
      int d = std::abs(step(anglesNow.pixels[i * 4]) - step(anglesNext.pixels[j * 4]));
      d = std::min(d, bins - d);
      ++n;
      if (d > 1) ++jumps;
    }
  if (compared) *compared = n;
  return n ? double(jumps) / double(n) : 0.0;
}

}  // namespace npr::test
