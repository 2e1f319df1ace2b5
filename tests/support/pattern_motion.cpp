// Pattern slide between frames (see pattern_motion.h).
#include "support/pattern_motion.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace npr::test {
namespace {

glm::vec2 applyFrame(const PatternFrame& f, const glm::vec2& u) {
  const float c = std::cos(f.rotation), s = std::sin(f.rotation);
  return f.scale * glm::vec2(c * u.x - s * u.y, s * u.x + c * u.y) + f.translation;
}

glm::vec2 inverseFrame(const PatternFrame& f, const glm::vec2& x) {
  const glm::vec2 d = (x - f.translation) / f.scale;
  const float c = std::cos(-f.rotation), s = std::sin(-f.rotation);
  return glm::vec2(c * d.x - s * d.y, s * d.x + c * d.y);
}

}  // namespace

double patternSlide(const ImageRGBA32F& geo, const CameraMatrices& cameraNow, const CameraMatrices& cameraNext,
                    const PatternFrame* now, const PatternFrame* next, int step) {
  const int w = geo.width, h = geo.height;
  const glm::mat4 toObject = glm::inverse(cameraNow.view);
  const glm::mat4 mvpNext = cameraNext.projection * cameraNext.view;
  double slide = 0.0;
  int n = 0;
  for (int y = 0; y < h; y += step)
    for (int x = 0; x < w; x += step) {
      const std::size_t i = std::size_t(y) * w + x;
      if (geo.pixels[i * 4 + 3] == 0.0f) continue;
      const glm::vec3 eyePos(geo.pixels[i * 4], geo.pixels[i * 4 + 1], geo.pixels[i * 4 + 2]);
      const glm::vec4 c = mvpNext * (toObject * glm::vec4(eyePos, 1.0f));
      if (!(c.w > 0.0f)) continue;
      const glm::vec2 px(float(x) + 0.5f, float(h - y) - 0.5f);  // window coordinates, y up
      const glm::vec2 surface = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(w, h);
      const glm::vec2 pattern = now && next ? applyFrame(*next, inverseFrame(*now, px)) : px;
      slide += glm::length(surface - pattern);
      ++n;
    }
  return n ? slide / n : 0.0;
}

double leastSimilaritySlide(const ImageRGBA32F& geo, const CameraMatrices& cameraNow, const CameraMatrices& cameraNext, int step) {
  const int w = geo.width, h = geo.height;
  const glm::mat4 toObject = glm::inverse(cameraNow.view);
  const glm::mat4 mvpNext = cameraNext.projection * cameraNext.view;
  std::vector<glm::dvec2> from, to;
  for (int y = 0; y < h; y += step)
    for (int x = 0; x < w; x += step) {
      const std::size_t i = std::size_t(y) * w + x;
      if (geo.pixels[i * 4 + 3] == 0.0f) continue;
      const glm::vec4 c = mvpNext * (toObject * glm::vec4(geo.pixels[i * 4], geo.pixels[i * 4 + 1], geo.pixels[i * 4 + 2], 1.0f));
      if (!(c.w > 0.0f)) continue;
      from.emplace_back(double(x) + 0.5, double(h - y) - 0.5);
      to.push_back((glm::dvec2(c) / double(c.w) * 0.5 + 0.5) * glm::dvec2(w, h));
    }
  if (from.empty()) return 0.0;
  // x' = [a -b; b a] x + t. Weighted least squares in closed form about the weighted centroids;
  // the weights 1 / |residual| of the last fit make it minimise the sum of the lengths.
  std::vector<double> weight(from.size(), 1.0);
  double best = INFINITY;
  for (int iteration = 0; iteration < 60; ++iteration) {
    double sw = 0.0;
    glm::dvec2 mf(0.0), mt(0.0);
    for (std::size_t k = 0; k < from.size(); ++k) {
      sw += weight[k];
      mf += weight[k] * from[k];
      mt += weight[k] * to[k];
    }
    mf /= sw;
    mt /= sw;
    double num_a = 0.0, num_b = 0.0, den = 0.0;
    for (std::size_t k = 0; k < from.size(); ++k) {
      const glm::dvec2 p = from[k] - mf, q = to[k] - mt;
      num_a += weight[k] * (p.x * q.x + p.y * q.y);
      num_b += weight[k] * (p.x * q.y - p.y * q.x);
      den += weight[k] * (p.x * p.x + p.y * p.y);
    }
    const double a = den > 0.0 ? num_a / den : 1.0, b = den > 0.0 ? num_b / den : 0.0;
    const glm::dvec2 t = mt - glm::dvec2(a * mf.x - b * mf.y, b * mf.x + a * mf.y);
    double sum = 0.0;
    for (std::size_t k = 0; k < from.size(); ++k) {
      const glm::dvec2 p = from[k];
      const double r = glm::length(glm::dvec2(a * p.x - b * p.y, b * p.x + a * p.y) + t - to[k]);
      sum += r;
      weight[k] = 1.0 / std::max(r, 1e-4);
    }
    best = std::min(best, sum / double(from.size()));
  }
  return best;
}

}  // namespace npr::test
