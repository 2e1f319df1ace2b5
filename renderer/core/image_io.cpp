// Image writing through OpenImageIO (see image_io.h).
#include "renderer/core/image_io.h"

#include <OpenImageIO/imageio.h>

namespace npr {

Status writeImage(const std::string& path, const ImageRGBA8& image) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels carry straight alpha
  if (!out->open(path, spec)) return Error{path + ": cannot open for writing: " + out->geterror()};
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) return Error{path + ": write failed: " + out->geterror()};
  if (!out->close()) return Error{path + ": close failed: " + out->geterror()};
  return okStatus();
}

}  // namespace npr
