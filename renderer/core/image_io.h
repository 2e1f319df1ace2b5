// Writing images through OpenImageIO (screenshots, test diffs): the format follows the
// file's extension (PNG, TGA, EXR, ...).
#pragma once

#include <string>

#include "renderer/gl/offscreen_target.h"
#include "renderer/palette/palette.h"
#include "renderer/core/result.h"

namespace npr {

Status writeImage(const std::string& path, int width, int height, int channels, const unsigned char* pixels);
Status writeImage(const std::string& path, const ImageRGBA8& image);
Status writeImage(const std::string& path, const RgbaImage& image);

}  // namespace npr
