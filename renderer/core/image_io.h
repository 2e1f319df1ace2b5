// Images through OpenImageIO: reading any format it knows as encoded RGBA8 (palette textures),
// resizing, and writing (screenshots, test diffs, the palette generator) in the format the
// file's extension names (PNG, TGA, EXR, ...).
#pragma once

#include <string>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

// Grey, grey+alpha, RGB or RGBA; 8-bit, 16-bit or float (float taken as linear light and
// encoded); at most 16384 pixels a side. Alpha stays straight (unassociated).
[[nodiscard]] Result<ImageRGBA8> loadImage(const std::string& path);
[[nodiscard]] Result<ImageRGBA8> resizeImage(const ImageRGBA8& image, int width, int height);
[[nodiscard]] Status writeImage(const std::string& path, const ImageRGBA8& image);

}  // namespace npr
