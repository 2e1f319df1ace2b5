// Pattern slide between frames (see pattern_motion.h).
#include "support/pattern_motion.h"

#include <cmath>

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

}  // namespace npr::test
