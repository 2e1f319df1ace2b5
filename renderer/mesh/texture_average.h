// The average colour of a texture map over a triangle of texture coordinates: what the
// per-triangle and per-vertex paths light a textured face with (the per-pixel paths sample
// the map itself). A box-filtered mip chain on the CPU; each triangle is sampled at seven
// points on the level where its texture-space footprint is a few texels, so the cost per
// triangle is constant however large the map or the triangle. For a see-through material
// (glTF's MASK and BLEND) the average is weighted by the map's alpha: the texels drawn, not the
// colour under the cut-away ones.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"

namespace npr {

class TextureAverager {
 public:
  explicit TextureAverager(const ImageRGBA8& image, bool alphaWeighted = false);
  // Texture coordinates as in the OBJ file (v up, repeating); the colour in [0,1].
  glm::vec3 average(const glm::vec2& a, const glm::vec2& b, const glm::vec2& c) const;
  glm::vec3 whole() const;  // the map's mean colour

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;  // bottom row first, as texture coordinates count; colour times weight, weight
  };
  glm::vec4 sample(const Level& level, glm::vec2 uv) const;
  std::vector<Level> levels_;
};

}  // namespace npr
