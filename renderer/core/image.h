// The project's two image types: 8-bit RGBA (palette textures, screenshots, read-backs) and
// float RGBA (read-backs of float targets). Rows are stored top row first, as image files
// are; what is uploaded to GL is flipped where it is uploaded.
#pragma once

#include <cstdint>
#include <vector>

namespace npr {

// sRGB-encoded (as displayed) RGBA8, straight alpha, 4 bytes per pixel.
struct ImageRGBA8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};

// 4 floats per pixel.
struct ImageRGBA32F {
  int width = 0, height = 0;
  std::vector<float> pixels;
};

}  // namespace npr
