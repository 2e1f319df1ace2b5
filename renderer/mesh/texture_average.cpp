// Texture averages over triangles (see texture_average.h).
#include "renderer/mesh/texture_average.h"

#include <algorithm>
#include <cmath>

namespace npr {

TextureAverager::TextureAverager(const ImageRGBA8& image, bool alphaWeighted) {
  Level base;
  base.width = std::max(image.width, 1);
  base.height = std::max(image.height, 1);
  base.texels.assign(static_cast<std::size_t>(base.width) * static_cast<std::size_t>(base.height), glm::vec4(1.0f));
  if (image.width > 0 && image.height > 0 && image.pixels.size() >= static_cast<std::size_t>(image.width) * image.height * 4) {
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const std::uint8_t* px = &image.pixels[(static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * 4];
        const float w = alphaWeighted ? float(px[3]) / 255.0f : 1.0f;
        base.texels[static_cast<std::size_t>(y) * base.width + x] = glm::vec4(glm::vec3(px[0], px[1], px[2]) / 255.0f * w, w);
      }
  }
  levels_.push_back(std::move(base));
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& f = levels_.back();
    Level c;
    c.width = std::max(1, f.width / 2);
    c.height = std::max(1, f.height / 2);
    c.texels.resize(static_cast<std::size_t>(c.width) * c.height);
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        // Odd sizes: the last coarse texel also takes the leftover row or column.
        const int x0 = x * 2, y0 = y * 2;
        const int x1 = (x == c.width - 1) ? f.width : x0 + 2, y1 = (y == c.height - 1) ? f.height : y0 + 2;
        glm::vec4 sum(0.0f);
        for (int yy = y0; yy < y1; ++yy)
          for (int xx = x0; xx < x1; ++xx) sum += f.texels[static_cast<std::size_t>(yy) * f.width + xx];
        c.texels[static_cast<std::size_t>(y) * c.width + x] = sum / float((x1 - x0) * (y1 - y0));
      }
    levels_.push_back(std::move(c));
  }
}

namespace {
// A weighted sum's colour; where nothing was weighted (all cut away), white: nothing shows.
glm::vec3 colourOf(const glm::vec4& weighted) { return weighted.w > 1e-6f ? glm::vec3(weighted) / weighted.w : glm::vec3(1.0f); }
}  // namespace

glm::vec3 TextureAverager::whole() const { return colourOf(levels_.back().texels[0]); }

glm::vec4 TextureAverager::sample(const Level& l, glm::vec2 uv) const {
  // Bilinear, repeating. The coordinate is wrapped into [0, 1) first: a far one (a texture
  // transform's offset of 1e24, found by fuzz_gltf) must not overflow the texel index.
  uv -= glm::floor(uv);
  const float fx = uv.x * float(l.width) - 0.5f, fy = uv.y * float(l.height) - 0.5f;
  const float x0f = std::floor(fx), y0f = std::floor(fy);
  const float tx = fx - x0f, ty = fy - y0f;
  auto wrap = [](long v, int n) { return static_cast<std::size_t>(((v % n) + n) % n); };
  const long x0 = static_cast<long>(x0f), y0 = static_cast<long>(y0f);
  auto at = [&](long x, long y) { return l.texels[wrap(y, l.height) * static_cast<std::size_t>(l.width) + wrap(x, l.width)]; };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), tx), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx), ty);
}

glm::vec3 TextureAverager::average(const glm::vec2& a, const glm::vec2& b, const glm::vec2& c) const {
  if (!(std::isfinite(a.x + a.y + b.x + b.y + c.x + c.y))) return whole();
  // Footprint in texels on the base level: pick the level where the triangle spans about 4
  // texels across: seven bilinear samples then see all of it without blurring in much of
  // what lies outside.
  const Level& base = levels_.front();
  const glm::vec2 size(base.width, base.height);
  const glm::vec2 lo = glm::min(a, glm::min(b, c)) * size, hi = glm::max(a, glm::max(b, c)) * size;
  const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(extent < 1e7f)) return whole();
  const int level = std::clamp(static_cast<int>(std::ceil(std::log2(std::max(extent, 1.0f) / 4.0f))), 0,
                               static_cast<int>(levels_.size()) - 1);
  const Level& l = levels_[static_cast<std::size_t>(level)];
  const glm::vec2 centre = (a + b + c) / 3.0f;
  glm::vec4 sum = sample(l, centre) * 4.0f;
  for (const glm::vec2& corner : {a, b, c}) sum += sample(l, glm::mix(centre, corner, 0.6f));
  return colourOf(sum);
}

}  // namespace npr
