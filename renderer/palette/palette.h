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
//   axis depth NEAR FAR | axis facing [FROM TO] | axis detail [FROM TO]  (a second axis: rows)
//   row                                      (starts the next row; every row is a whole tone ladder)
//
// Two-dimensional palettes (X-Toon, Barla, Thollot and Markosian 2006): the lit tone picks the
// column, matched against the first row's levels, and a second value at the surface picks the
// row, so the same tone can be drawn differently far away or at the rim. `depth`: the distance
// from the eye in units of the scene's bounding radius, NEAR at the first row, FAR at the last;
// `facing`: 1 - |N.V|, 0 where the surface faces the eye and 1 edge-on (default 0 1); `detail`:
// each object's own value in [0, 1] (Renderer::setModelDetail, --object-detail; default 0 1).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/image.h"
#include "renderer/core/palette_axis_kind.h"
#include "renderer/core/result.h"
#include "renderer/palette/palette_orientation.h"
#include "renderer/settings/choices.h"

namespace npr {

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

const char* paletteAxisName(PaletteAxisKind k);

// The row position for an axis value through the frame's map (GpuPalette::axisMap), in [0, rows - 1].
inline float paletteRowAt(float value, const glm::vec2& map, int rows) {
  const float r = value * map.x + map.y;
  return r > 0.0f ? std::min(r, float(rows - 1)) : 0.0f;  // NaN: the first row
}

struct PaletteAxis {
  PaletteAxisKind kind = PaletteAxisKind::None;
  float from = 0.0f, to = 1.0f;  // the axis value at the first row and at the last
  int rows = 1;
  // The map paletteRowAt reads, for axis values counted in `unit`s (depth: the scene's radius):
  // FROM at the first row, TO at the last.
  glm::vec2 map(float unit = 1.0f) const {
    const float k = float(std::max(rows, 1) - 1) / ((to - from) * unit);
    return {k, -from * unit * k};
  }
  // Where `value` falls among the rows, in [0, rows - 1] (rows blend between neighbours).
  float rowPosition(float value) const { return paletteRowAt(value, map(), rows); }
};

// The axis value at a surface point, from its eye-space position and normal (palette.glsl's
// setPaletteRow is the same per pixel): depth, the distance from the eye; facing, 1 - |N.V|;
// detail, the object's own value.
inline float paletteAxisValue(PaletteAxisKind kind, const glm::vec3& eyePosition, const glm::vec3& eyeNormal, float detail = 0.0f) {
  if (kind == PaletteAxisKind::Detail) return detail;
  if (kind == PaletteAxisKind::Depth) return glm::length(eyePosition);
  const float ln = glm::length(eyeNormal), lp = glm::length(eyePosition);
  return ln > 0.0f && lp > 0.0f ? 1.0f - std::abs(glm::dot(eyeNormal, eyePosition)) / (ln * lp) : 0.0f;
}

struct Palette {
  std::string file;
  std::string name;
  std::vector<PaletteEntry> entries;
  glm::vec3 backgroundColour{1.0f};  // encoded; the mean of the background image if there is one
  std::optional<ImageRGBA8> backgroundImage;
  std::optional<MatchMode> defaultMatch;
  std::optional<float> defaultRangeScale;
  std::vector<std::string> warnings;
  // Entries are stored row after row; a palette without an axis has one row.
  PaletteAxis axis;

  std::vector<glm::vec3> averages() const;
  int columns() const { return static_cast<int>(entries.size()) / std::max(axis.rows, 1); }
};

// Loads the whole palette or nothing: a failure names the file, the line and the reason.
[[nodiscard]] Result<Palette> loadPalette(const std::string& path);

}  // namespace npr
