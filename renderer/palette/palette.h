// Palettes: an ordered list of textures that replaces lighting (the user's whole style),
// read from a plain-text palette file, loaded through OpenImageIO and analysed for their
// average colour over the background, alpha taken into account.
//
// Palette file: one image path per line, in order, relative to the palette file; lines
// starting with '#' and blank lines are ignored; optional lines:
//   background PATH | background #RRGGBB     (default: white paper, #FFFFFF)
//   match colors|intensity|order             (default applied when the palette is chosen)
//   range-scale S
//   name TEXT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

enum class MatchMode { Colors, Intensity, Order };
const char* matchModeName(MatchMode m);
std::optional<MatchMode> parseMatchMode(const std::string& s);

constexpr int kMaxPaletteEntries = 256;

struct PaletteEntry {
  std::string path;
  ImageRGBA8 image;
  glm::vec3 average{0.0f};  // encoded colour of the texture composited over the background
  float intensity = 0.0f;   // sum of the average's channels, in [0, 3]
};

struct Palette {
  std::string file;
  std::string name;
  std::vector<PaletteEntry> entries;
  glm::vec3 backgroundColour{1.0f};  // encoded; the mean of the background image if there is one
  std::optional<ImageRGBA8> backgroundImage;
  std::optional<MatchMode> defaultMatch;
  std::optional<float> defaultRangeScale;
  std::vector<std::string> warnings;

  std::vector<glm::vec3> averages() const;
};

// Loads the whole palette or nothing: a failure names the file, the line and the reason.
Result<Palette> loadPalette(const std::string& path);

// Loads one image through OpenImageIO as sRGB-encoded RGBA8 (grey, grey+alpha, RGB, RGBA;
// 8-bit, 16-bit or float, float images being taken as linear and encoded).
Result<ImageRGBA8> loadImage(const std::string& path);

// `img` composited over the background as the renderer shows it: blended on encoded values
// (as OpenGL blends into an 8-bit framebuffer), texel over background texel where the two
// have the same size, over the background's mean colour otherwise.
ImageRGBA8 compositeOver(const ImageRGBA8& img, const glm::vec3& bgColour, const ImageRGBA8* bgImage);
// The average of that composite, taken in linear light and returned encoded.
glm::vec3 compositeAverage(const ImageRGBA8& img, const glm::vec3& bgColour, const ImageRGBA8* bgImage);

// The palette report: one line of JSON (`npr-viewer --palette-info`).
struct PaletteAnalysis {
  float minIntensity = 0, maxIntensity = 0, largestGap = 0;
  bool monotonic = true;  // intensities strictly decrease or increase along the order
  std::vector<std::string> suitabilityWarnings(MatchMode mode) const;
};
PaletteAnalysis analysePalette(const Palette& p);
std::string paletteReportJson(const Palette& p);

}  // namespace npr
