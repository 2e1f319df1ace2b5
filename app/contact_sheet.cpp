// Contact sheet drawing (see contact_sheet.h).
#include "app/contact_sheet.h"

#include <stb_truetype.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <optional>

#include "renderer/core/colour.h"

namespace npr {
namespace {

// DejaVu Sans (fonts-dejavu-core) where distributions put it; read once.
const std::optional<std::string>& fontBytes() {
  static const std::optional<std::string> bytes = []() -> std::optional<std::string> {
    for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
                             "/usr/share/fonts/dejavu/DejaVuSans.ttf", "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf"}) {
      std::ifstream f(path, std::ios::binary);
      if (!f) continue;
      std::string b((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
      if (b.size() > 12) return b;
    }
    return std::nullopt;
  }();
  return bytes;
}

}  // namespace

ImageRGBA8 blankSheet(int width, int height) {
  return ImageRGBA8{width, height, std::vector<std::uint8_t>(size_t(std::max(0, width)) * size_t(std::max(0, height)) * 4, 255)};
}

void paste(ImageRGBA8& sheet, int x, int y, const ImageRGBA8& image) {
  for (int r = std::max(0, -y); r < image.height && y + r < sheet.height; ++r) {
    const int c0 = std::max(0, -x), c1 = std::min(image.width, sheet.width - x);
    if (c1 <= c0) return;
    std::copy_n(&image.pixels[(size_t(r) * image.width + c0) * 4], size_t(c1 - c0) * 4,
                &sheet.pixels[(size_t(y + r) * sheet.width + size_t(x + c0)) * 4]);
  }
}

void fillRect(ImageRGBA8& sheet, int x, int y, int width, int height, const float rgb[3]) {
  const std::uint8_t px[4] = {toByte(rgb[0]), toByte(rgb[1]), toByte(rgb[2]), 255};
  for (int r = std::max(0, y); r < std::min(sheet.height, y + height); ++r)
    for (int c = std::max(0, x); c < std::min(sheet.width, x + width); ++c) std::copy_n(px, 4, &sheet.pixels[(size_t(r) * sheet.width + c) * 4]);
}

bool drawText(ImageRGBA8& sheet, int x, int y, const std::string& text, int size, bool& fontMissing) {
  const std::optional<std::string>& font = fontBytes();
  stbtt_fontinfo info;
  if (fontMissing || !font || !stbtt_InitFont(&info, reinterpret_cast<const unsigned char*>(font->data()), 0)) {
    fontMissing = true;
    return false;
  }
  const float scale = stbtt_ScaleForMappingEmToPixels(&info, float(size));
  const float ink[3] = {0.1f, 0.1f, 0.12f};
  float pen = float(x);
  for (size_t i = 0; i < text.size(); ++i) {
    const int cp = static_cast<unsigned char>(text[i]) < 0x80 ? text[i] : '?';  // labels are ASCII; anything else shows as '?'
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&info, cp, &advance, &bearing);
    int w = 0, h = 0, ox = 0, oy = 0;
    unsigned char* glyph = stbtt_GetCodepointBitmapSubpixel(&info, scale, scale, pen - std::floor(pen), 0.0f, cp, &w, &h, &ox, &oy);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) {
        const int sx = int(std::floor(pen)) + ox + c, sy = y + oy + r;
        if (sx < 0 || sy < 0 || sx >= sheet.width || sy >= sheet.height) continue;
        const float a = glyph[r * w + c] / 255.0f;
        std::uint8_t* d = &sheet.pixels[(size_t(sy) * sheet.width + sx) * 4];
        for (int k = 0; k < 3; ++k) d[k] = toByte(d[k] / 255.0f * (1.0f - a) + ink[k] * a);
      }
    stbtt_FreeBitmap(glyph, nullptr);
    pen += float(advance) * scale;
    if (i + 1 < text.size()) pen += scale * float(stbtt_GetCodepointKernAdvance(&info, cp, static_cast<unsigned char>(text[i + 1])));
  }
  return true;
}

}  // namespace npr
