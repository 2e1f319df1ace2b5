// The project's one colour convention (README, "Colour"): palette images are sRGB-encoded and
// are shown as stored. Lit colours are display values, as fixed-function OpenGL wrote them
// straight to an 8-bit framebuffer, so matching compares encoded values. A texture's average
// is taken in linear light and then encoded: the flat colour that emits the same light as the
// texture seen from afar, which is what its hatching or stippling looks like at a distance.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace npr {

inline float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
inline float linearToSrgb(float c) {
  if (!(c > 0.0f)) return 0.0f;
  if (c >= 1.0f) return 1.0f;
  return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}
inline glm::vec3 srgbToLinear(const glm::vec3& c) { return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)}; }
inline glm::vec3 linearToSrgb(const glm::vec3& c) { return {linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)}; }

}  // namespace npr
