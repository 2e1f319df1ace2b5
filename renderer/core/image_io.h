// Writing images through OpenImageIO (screenshots, test diffs, the palette generator): the
// format follows the file's extension (PNG, TGA, EXR, ...). Reading is the palette's
// loadImage, which also converts formats and colour encodings.
#pragma once

#include <string>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

[[nodiscard]] Status writeImage(const std::string& path, const ImageRGBA8& image);

}  // namespace npr
