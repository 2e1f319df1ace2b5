// Textures stretched along line sets' strokes (a set's texture=brush|FILE): each is a coverage
// image, its columns along the stroke and its rows across it, that multiplies the line's ink.
// `brush` is the first of the painterly strokes' brushes (strokes/brush_shapes.h); a file's
// coverage is its alpha where it has any, else its darkness (ink on white paper). Loaded once
// per name and kept; a file that fails is reported once and its sets draw plain lines.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/texture_units.h"

namespace npr {

// The texture unit the line sets' stroke textures are bound on (gl/texture_units.h).
inline const gl::TextureUnit kLineTextureUnit = gl::claimTextureUnit();

// A stroke texture before upload: coverage 0..255, row 0 at the top.
struct StrokeCoverage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> texels;
};
// Longest side a file's texture keeps (larger images are reduced as they are read).
inline constexpr int kMaxStrokeTextureSide = 2048;
[[nodiscard]] Result<StrokeCoverage> strokeCoverage(const std::string& name);

struct StrokeTexture {
  GLuint id = 0;
};

class StrokeTextures {
 public:
  // The texture `name` names, uploaded on first use. An error the first time a name fails,
  // then none with an empty texture (id 0).
  [[nodiscard]] Result<StrokeTexture> find(const std::string& name);

 private:
  std::map<std::string, gl::Texture> loaded_;
};

}  // namespace npr
