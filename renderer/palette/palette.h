// Palettes: an ordered list of textures that replaces lighting (the user's whole style),
// read from a plain-text palette file (palette_file.cpp), its images loaded through
// OpenImageIO and averaged over the background, alpha taken into account
// (palette_analysis.h).
//
// Palette file: one image path per line, in order, relative to the palette file; lines
// starting with '#' and blank lines are ignored; optional lines:
//   background PATH | background #RRGGBB     (default: white paper, #FFFFFF)
//   match colors|intensity|order             (default applied when the palette is chosen)
//   range-scale S
//   name TEXT
//   mip PATH                                 (the next mip level of the entry above: half its size)
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"
#include "renderer/core/result.h"
#include "renderer/palette/palette_orientation.h"

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
  TextureOrientation orientation;  // its strokes' dominant direction (over the background colour)
  std::vector<ImageRGBA8> mips;    // levels 1, 2, ... the palette file gave (`mip PATH` lines); the rest are reduced
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
[[nodiscard]] Result<Palette> loadPalette(const std::string& path);

}  // namespace npr
