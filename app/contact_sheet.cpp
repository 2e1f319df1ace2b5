// Contact sheet drawing (see contact_sheet.h).
#include "app/contact_sheet.h"

#include <OpenImageIO/imagebufalgo.h>

namespace npr {

OIIO::ImageBuf toBuf(const ImageRGBA8& img) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 4, OIIO::TypeDesc::UINT8));
  buf.set_pixels(buf.roi(), OIIO::TypeDesc::UINT8, img.pixels.data());
  return buf;
}

ImageRGBA8 fromBuf(const OIIO::ImageBuf& buf) {
  const OIIO::ImageSpec& s = buf.spec();
  ImageRGBA8 img{s.width, s.height, std::vector<std::uint8_t>(size_t(s.width) * size_t(s.height) * 4)};
  buf.get_pixels(OIIO::ROI(0, s.width, 0, s.height, 0, 1, 0, 4), OIIO::TypeDesc::UINT8, img.pixels.data());
  return img;
}

bool drawText(OIIO::ImageBuf& sheet, int x, int y, const std::string& text, int size, bool& fontMissing) {
  if (fontMissing) return false;
  const float ink[4] = {0.1f, 0.1f, 0.12f, 1.0f};
  if (OIIO::ImageBufAlgo::render_text(sheet, x, y, text, size, "DejaVuSans", ink)) return true;
  fontMissing = true;
  return false;
}

}  // namespace npr
