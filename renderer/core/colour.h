// The project's one colour convention (README, "Colour"): palette images are sRGB-encoded and
// are shown as stored. Lit colours are display values, as fixed-function OpenGL wrote them
// straight to an 8-bit framebuffer, so matching compares encoded values. A texture's average
// is taken in linear light and then encoded: the flat colour that emits the same light as the
// texture seen from afar, which is what its hatching or stippling looks like at a distance.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

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
// [0, 1] to a byte, rounded; NaN and negatives to 0.
inline std::uint8_t toByte(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}
// Linear light of each encoded byte value.
inline const std::array<float, 256>& srgbTable() {
  static const std::array<float, 256> t = [] {
    std::array<float, 256> a{};
    for (int i = 0; i < 256; ++i) a[static_cast<size_t>(i)] = srgbToLinear(i / 255.0f);
    return a;
  }();
  return t;
}
inline glm::vec3 srgbToLinear(const glm::vec3& c) { return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)}; }
inline glm::vec3 linearToSrgb(const glm::vec3& c) { return {linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)}; }

}  // namespace npr
