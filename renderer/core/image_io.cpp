// Image writing through OpenImageIO (see image_io.h).
#include "renderer/core/image_io.h"

#include <OpenImageIO/imageio.h>

namespace npr {

Status writeImage(const std::string& path, int width, int height, int channels, const unsigned char* pixels) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels carry straight alpha
  if (!out->open(path, spec)) return Error{path + ": cannot open for writing: " + out->geterror()};
  if (!out->write_image(OIIO::TypeDesc::UINT8, pixels)) return Error{path + ": write failed: " + out->geterror()};
  if (!out->close()) return Error{path + ": close failed: " + out->geterror()};
  return okStatus();
}

Status writeImage(const std::string& path, const ImageRGBA8& image) {
  return writeImage(path, image.width, image.height, 4, image.pixels.data());
}

Status writeImage(const std::string& path, const RgbaImage& image) {
  return writeImage(path, image.width, image.height, 4, image.pixels.data());
}

}  // namespace npr
