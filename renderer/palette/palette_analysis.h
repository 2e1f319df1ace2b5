// Palette analysis, in the project's colour convention (core/colour.h): each texture
// composited over the background as the renderer shows it, its average in linear light,
// the spread and order of the entries' intensities, and the report `--palette-info` prints.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"
#include "renderer/palette/palette.h"

namespace npr {

// `img` composited over the background as the renderer shows it: blended on encoded values
// (as OpenGL blends into an 8-bit framebuffer), texel over background texel where the two
// have the same size, over the background's mean colour otherwise.
ImageRGBA8 compositeOver(const ImageRGBA8& img, const glm::vec3& bgColour, const ImageRGBA8* bgImage);
// The average of that composite, taken in linear light and returned encoded.
glm::vec3 compositeAverage(const ImageRGBA8& img, const glm::vec3& bgColour, const ImageRGBA8* bgImage);
// The mean of an image's colours in linear light (white for an empty image).
glm::vec3 linearMean(const ImageRGBA8& img);

struct PaletteAnalysis {
  float minIntensity = 0, maxIntensity = 0, largestGap = 0;
  bool monotonic = true;  // intensities strictly decrease or increase along the order
  // How far the steps between consecutive entries' intensities are from even, as a fraction
  // of the range (0: evenly spaced; drawn palettes keep it within kEvenSpacing).
  float spacingError = 0;
  static constexpr float kEvenSpacing = 0.01f;
  std::vector<std::string> suitabilityWarnings(MatchMode mode) const;
};
// Of one row's tone ladder (the first: what matching uses).
PaletteAnalysis analysePalette(const Palette& p, int row = 0);
// The palette report: one line of JSON (`npr-viewer --palette-info`).
std::string paletteReportJson(const Palette& p);

}  // namespace npr
