// Palette mip levels (see palette_mipmaps.h).
#include "renderer/palette/palette_mipmaps.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/colour.h"
#include "renderer/palette/palette_analysis.h"

namespace npr {

int mipLevelCount(int width, int height) {
  int levels = 1;
  while (std::min(mipSide(width, levels), mipSide(height, levels)) >= kMinMipSide) ++levels;
  return levels;
}

namespace {

// Source texels covered by destination texel i of n (out of m source texels), with weights:
// the interval [i m / n, (i + 1) m / n) of the wrapped source row.
struct Span {
  int first = 0;
  std::vector<float> weights;
};
std::vector<Span> spans(int m, int n) {
  std::vector<Span> out(static_cast<size_t>(n));
  const double step = double(m) / n;
  for (int i = 0; i < n; ++i) {
    const double a = i * step, b = (i + 1) * step;
    Span& s = out[static_cast<size_t>(i)];
    s.first = int(std::floor(a));
    for (int j = s.first; j < int(std::ceil(b)); ++j)
      s.weights.push_back(float((std::min(b, double(j + 1)) - std::max(a, double(j))) / step));
  }
  return out;
}

}  // namespace

ImageRGBA8 downsampleHalf(const ImageRGBA8& img) {
  const int w = img.width, h = img.height;
  const int nw = mipSide(w, 1), nh = mipSide(h, 1);
  const auto& lin = srgbTable();
  // Premultiplied linear colour and alpha per source texel.
  std::vector<glm::vec4> src(static_cast<size_t>(w) * static_cast<size_t>(h));
  for (size_t i = 0; i < src.size(); ++i) {
    const std::uint8_t* p = &img.pixels[i * 4];
    const float a = p[3] / 255.0f;
    src[i] = glm::vec4(lin[p[0]] * a, lin[p[1]] * a, lin[p[2]] * a, a);
  }
  const std::vector<Span> sx = spans(w, nw), sy = spans(h, nh);
  ImageRGBA8 out{nw, nh, std::vector<std::uint8_t>(static_cast<size_t>(nw) * static_cast<size_t>(nh) * 4)};
  for (int y = 0; y < nh; ++y)
    for (int x = 0; x < nw; ++x) {
      glm::vec4 sum(0.0f);
      const Span& ry = sy[static_cast<size_t>(y)];
      const Span& rx = sx[static_cast<size_t>(x)];
      for (size_t j = 0; j < ry.weights.size(); ++j)
        for (size_t i = 0; i < rx.weights.size(); ++i) {
          const int xx = (rx.first + int(i)) % w, yy = (ry.first + int(j)) % h;
          sum += ry.weights[j] * rx.weights[i] * src[static_cast<size_t>(yy) * static_cast<size_t>(w) + static_cast<size_t>(xx)];
        }
      std::uint8_t* o = &out.pixels[(static_cast<size_t>(y) * static_cast<size_t>(nw) + static_cast<size_t>(x)) * 4];
      const float a = sum.a;
      for (int k = 0; k < 3; ++k) o[k] = a > 0.0f ? toByte(linearToSrgb(sum[k] / a)) : 0;
      o[3] = toByte(a);
    }
  return out;
}

std::vector<ImageRGBA8> mipChain(const ImageRGBA8& img, int levels) {
  std::vector<ImageRGBA8> chain{img};
  while (static_cast<int>(chain.size()) < levels) chain.push_back(downsampleHalf(chain.back()));
  return chain;
}

std::vector<ImageRGBA8> entryMipChain(const PaletteEntry& e, int levels, bool precomposited, const glm::vec3& bgColour,
                                      const std::vector<ImageRGBA8>& background) {
  auto shown = [&](const ImageRGBA8& img, int level) {
    if (!precomposited) return img;
    const ImageRGBA8* bg = background.empty() ? nullptr : &background[static_cast<size_t>(level)];
    return compositeOver(img, bgColour, bg);
  };
  std::vector<ImageRGBA8> chain{shown(e.image, 0)};
  for (int k = 1; k < levels; ++k) {
    const size_t given = static_cast<size_t>(k - 1);
    if (given < e.mips.size()) chain.push_back(shown(e.mips[given], k));
    else chain.push_back(downsampleHalf(chain.back()));
  }
  return chain;
}

bool layersPrecomposited(const Palette& p) {
  if (!p.backgroundImage) return true;
  for (const PaletteEntry& e : p.entries)
    if (e.image.width != p.backgroundImage->width || e.image.height != p.backgroundImage->height) return false;
  return true;
}

int paletteMipLevels(const Palette& p) {
  int w = 1, h = 1;
  for (const PaletteEntry& e : p.entries) {
    w = std::max(w, e.image.width);
    h = std::max(h, e.image.height);
  }
  return mipLevelCount(w, h);
}

std::vector<float> entryMipTones(const Palette& p, size_t entry) {
  const bool pre = layersPrecomposited(p);
  const int levels = paletteMipLevels(p);
  const std::vector<ImageRGBA8> bg = pre && p.backgroundImage ? mipChain(*p.backgroundImage, levels) : std::vector<ImageRGBA8>{};
  std::vector<float> tones;
  for (const ImageRGBA8& img : entryMipChain(p.entries[entry], levels, pre, p.backgroundColour, bg)) {
    const glm::vec3 a = pre ? linearToSrgb(linearMean(img)) : compositeAverage(img, p.backgroundColour, nullptr);
    tones.push_back(a.r + a.g + a.b);
  }
  return tones;
}

}  // namespace npr
