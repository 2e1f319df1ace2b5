// Image reading, resizing and writing through OpenImageIO (see image_io.h).
#include "renderer/core/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>

#include "renderer/core/colour.h"

namespace npr {
namespace fs = std::filesystem;
namespace {
constexpr int kMaxImageSide = 16384;
}  // namespace

Result<ImageRGBA8> loadImage(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path + ": no such image file"};
  if (fs::is_directory(path, ec)) return Error{path + ": is a directory, not an image"};
  // Keep straight (unassociated) alpha: OpenImageIO would otherwise premultiply PNG and TGA
  // colours on read, and the compositing below expects straight alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    std::string why = OIIO::geterror();
    if (why.empty()) why = "unsupported or corrupt image";
    return Error{path + ": cannot read image: " + why};
  }
  const OIIO::ImageSpec spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    return Error{path + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                 " is outside 1.." + std::to_string(kMaxImageSide)};
  const int nc = spec.nchannels;
  if (nc < 1) return Error{path + ": image has no channels"};
  const int alpha = spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 2 ? 1 : (nc >= 4 ? 3 : -1));
  const bool isFloat = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
                       spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  ImageRGBA8 img{spec.width, spec.height, std::vector<std::uint8_t>(static_cast<size_t>(spec.width) * spec.height * 4)};
  const int rowsPerChunk = 64;
  std::vector<float> buf(static_cast<size_t>(spec.width) * rowsPerChunk * nc);
  for (int y0 = 0; y0 < spec.height; y0 += rowsPerChunk) {
    const int y1 = std::min(spec.height, y0 + rowsPerChunk);
    if (!in->read_scanlines(0, 0, y0 + spec.y, y1 + spec.y, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data())) {
      std::string why = in->geterror();
      return Error{path + ": image data could not be read (truncated or corrupt): " + (why.empty() ? "read failed" : why)};
    }
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const float* s = &buf[(static_cast<size_t>(y - y0) * spec.width + x) * nc];
        float rgb[3];
        if (nc <= 2) rgb[0] = rgb[1] = rgb[2] = s[0];
        else for (int k = 0; k < 3; ++k) rgb[k] = s[k];
        if (isFloat) for (float& v : rgb) v = linearToSrgb(v);  // float images hold linear light
        std::uint8_t* d = &img.pixels[(static_cast<size_t>(y) * spec.width + x) * 4];
        for (int k = 0; k < 3; ++k) d[k] = toByte(rgb[k]);
        d[3] = alpha >= 0 ? toByte(s[alpha]) : 255;
      }
    }
  }
  return img;
}

Result<ImageRGBA8> resizeImage(const ImageRGBA8& img, int w, int h) {
  OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf src(spec, const_cast<std::uint8_t*>(img.pixels.data()));
  OIIO::ImageBuf dst = OIIO::ImageBufAlgo::resize(src, "", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, 4));
  if (dst.has_error()) return Error{"resize failed: " + dst.geterror()};
  ImageRGBA8 out{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  dst.get_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, 4), OIIO::TypeDesc::UINT8, out.pixels.data());
  return out;
}


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
