// The interface of the OpenImageIO module (oiio-images.so, built from image_codec_oiio.cpp):
// what image_io.cpp hands to OpenImageIO when a file is not a PNG or JPEG it decodes itself,
// or is too large to decode whole, and the writers for formats other than PNG. Loaded on first
// use (plugin_module.h).
#pragma once

#include <memory>
#include <string>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

// An open image, read a band of rows at a time as floats (the file's own scale: 0..1 for
// integer formats, linear light for float ones).
class ImageRowReader {
 public:
  virtual ~ImageRowReader() = default;
  int width = 0, height = 0, channels = 0;
  int alpha = -1;        // the alpha channel, or -1
  bool isFloat = false;  // float, half or double samples: linear light
  // Rows [y0, y1) into `out`, width * channels floats per row.
  [[nodiscard]] virtual Status readRows(int y0, int y1, float* out) = 0;
};

// A file written a part at a time: rows top to bottom (a strip writer), or whole frames (an
// animation). The file is finished after its last part.
class ImageSink {
 public:
  virtual ~ImageSink() = default;
  [[nodiscard]] virtual Status append(const ImageRGBA8& part) = 0;
};

struct ImageCodecModule {
  Result<std::unique_ptr<ImageRowReader>> (*open)(const std::string& path);
  Status (*write)(const std::string& path, const ImageRGBA8& image);
  Result<std::unique_ptr<ImageSink>> (*openStrips)(const std::string& path, int width, int height);
  Result<std::unique_ptr<ImageSink>> (*openAnimation)(const std::string& path, int width, int height, int frames, int fps);
};

// The module's table, loaded on first call; an error says how to get it back.
[[nodiscard]] Result<const ImageCodecModule*> imageCodecModule();

}  // namespace npr
