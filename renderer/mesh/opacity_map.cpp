// Folding map_d into a diffuse map's alpha (see opacity_map.h).
#include "renderer/mesh/opacity_map.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace npr {

ImageRGBA8 withOpacityMap(const ImageRGBA8* colour, const ImageRGBA8& opacity) {
  ImageRGBA8 out;
  if (colour && colour->width > 0 && colour->height > 0) {
    out = *colour;
  } else {
    out.width = opacity.width;
    out.height = opacity.height;
    out.pixels.assign(std::size_t(out.width) * std::size_t(out.height) * 4, 255);
  }
  if (opacity.width < 1 || opacity.height < 1) return out;
  bool hasAlpha = false;
  for (std::size_t i = 3; i < opacity.pixels.size(); i += 4) hasAlpha = hasAlpha || opacity.pixels[i] < 255;
  for (int y = 0; y < out.height; ++y) {
    const int oy = std::min(opacity.height - 1, int((std::int64_t(y) * 2 + 1) * opacity.height / (std::int64_t(out.height) * 2)));
    for (int x = 0; x < out.width; ++x) {
      const int ox = std::min(opacity.width - 1, int((std::int64_t(x) * 2 + 1) * opacity.width / (std::int64_t(out.width) * 2)));
      const std::uint8_t* o = &opacity.pixels[(std::size_t(oy) * std::size_t(opacity.width) + std::size_t(ox)) * 4];
      // Rec. 709 luma, in integers: 0.2126, 0.7152, 0.0722 of 256.
      const int a = hasAlpha ? o[3] : (54 * o[0] + 183 * o[1] + 19 * o[2] + 128) >> 8;
      std::uint8_t& alpha = out.pixels[(std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 4 + 3];
      alpha = std::uint8_t((alpha * std::min(a, 255) + 127) / 255);
    }
  }
  return out;
}

}  // namespace npr
