// Line sets' stroke textures (see stroke_textures.h).
#include "renderer/lines/stroke_textures.h"

#include <algorithm>

#include "renderer/core/image_io.h"
#include "renderer/gl/texture_units.h"
#include "renderer/strokes/brush_shapes.h"

namespace npr {

Result<StrokeCoverage> strokeCoverage(const std::string& name) {
  StrokeCoverage out;
  if (name == "brush") {
    const std::vector<std::uint8_t> all = brushCoverage();
    out.width = kBrushLength;
    out.height = kBrushWidth;
    out.texels.resize(std::size_t(kBrushLength) * kBrushWidth);
    for (int y = 0; y < kBrushWidth; ++y)
      std::copy_n(all.begin() + std::ptrdiff_t(y) * kBrushLength * kBrushes, kBrushLength, out.texels.begin() + std::ptrdiff_t(y) * kBrushLength);
    return out;
  }
  Result<ImageRGBA8> image = loadImage(name, {kMaxStrokeTextureSide, kMaxStrokeTextureSide});
  if (!image) return Error{"the line texture: " + image.error()};
  out.width = image->width;
  out.height = image->height;
  out.texels.resize(std::size_t(out.width) * std::size_t(out.height));
  const std::vector<std::uint8_t>& px = image->pixels;
  bool alpha = false;
  for (std::size_t i = 3; i < px.size() && !alpha; i += 4) alpha = px[i] < 255;
  for (std::size_t i = 0; i < out.texels.size(); ++i) {
    const std::uint8_t* p = &px[4 * i];
    // Rec. 709 luma of the encoded values: what "dark" looks like on paper.
    const int luma = (2126 * p[0] + 7152 * p[1] + 722 * p[2] + 5000) / 10000;
    out.texels[i] = alpha ? p[3] : std::uint8_t(255 - std::min(luma, 255));
  }
  return out;
}

Result<StrokeTexture> StrokeTextures::find(const std::string& name) {
  auto it = loaded_.find(name);
  if (it != loaded_.end()) return StrokeTexture{it->second.id()};
  gl::Texture& texture = loaded_[name];  // kept, failed or not: a failure is reported once
  Result<StrokeCoverage> c = strokeCoverage(name);
  if (!c) return Error{c.error()};
  texture = gl::createTexture();
  gl::bindTexture(kLineTextureUnit, GL_TEXTURE_2D, texture.id());
  glActiveTexture(GL_TEXTURE0 + GLenum(kLineTextureUnit.index));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Rows from the bottom, as GL counts them: the image's top row is the stroke's left side.
  std::vector<std::uint8_t> flipped(c->texels.size());
  for (int y = 0; y < c->height; ++y)
    std::copy_n(c->texels.begin() + std::ptrdiff_t(y) * c->width, c->width, flipped.begin() + std::ptrdiff_t(c->height - 1 - y) * c->width);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, c->width, c->height, 0, GL_RED, GL_UNSIGNED_BYTE, flipped.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  // Mipmapped: a texture tens of texels across drawn on a line a few pixels wide.
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glActiveTexture(GL_TEXTURE0);
  return StrokeTexture{texture.id()};
}

}  // namespace npr
