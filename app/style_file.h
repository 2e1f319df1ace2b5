// Style presets: a whole look (palette, match mode, range scale, path, tone model, lines,
// bands, pattern space and scale, stroke orientation) in one plain-text file of `key value`
// lines, like the palette file. Shipped styles live in palettes/styles/; `--style NAME|FILE`,
// the overlay's style list and its "save style" use them. A style that fails to load or apply
// changes nothing: the message names the file, the line and the reason.
//
//   name TEXT
//   palette NAME|PATH        (a shipped palette's folder name, or a path relative to the file)
//   match colors|intensity|order      range-scale S       path stencil|triangle|...
//   tone opengl|gooch|splashback|charcoal      bands T1,T2,...
//   lines none|silhouette,crease,boundary,image,hardware,rim   line-width PX   crease-angle DEG
//   outline fatten|offset|edges   outline-offset K
//   sketchy on|off           pattern screen|anchored|object   pattern-scale S   pattern-filter nearest|linear
//   orient none|curvature|light|DEGREES
//   strokes on|off   stroke-density D   stroke-size LxW
//   ground on|off   shadows on|off   occlusion on|off   light X,Y,Z (model radii, as --light)
//   shadow-palette NAME|PATH|none   occlusion-palette NAME|PATH|none   (control images)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/viewer_state.h"
#include "renderer/core/result.h"
#include "renderer/lighting/lighting_state.h"

namespace npr {

struct Style {
  std::string file, name;
  std::optional<std::string> palette;  // resolved to a path
  std::optional<MatchMode> match;
  std::optional<float> rangeScale;
  std::optional<RenderPath> path;
  std::optional<ToneModel> tone;
  std::optional<std::vector<float>> bands;
  std::optional<LineSettings> lines;  // kinds and their settings, over the defaults
  std::optional<PatternSpace> pattern;
  std::optional<float> patternScale;
  std::optional<bool> patternLinear;
  std::optional<OrientSettings> orient;
  std::optional<StrokeSettings> strokes;  // strokes, stroke-density, stroke-size
  std::optional<bool> ground, shadows, occlusion;
  std::optional<glm::vec3> light;  // scene space, model radii
  std::optional<std::string> shadowPalette, occlusionPalette;  // resolved paths; empty: none
};

// The shipped styles (palettes/styles/*.style), sorted.
std::vector<std::string> discoverStyles();
// NAME (a shipped style) or a path to a style file.
std::string resolveStyle(const std::string& nameOrFile);
[[nodiscard]] Result<Style> loadStyle(const std::string& path);
// Applies a style: its palette first (a palette that fails leaves everything as it was), then
// the settings it names; what it does not name stays.
[[nodiscard]] Status applyStyle(const Style& style, ViewerState& state, Renderer& renderer);
// The current look as a style file's text (what "save style" writes).
std::string styleText(const ViewerState& state, Renderer& renderer, const std::string& name);

}  // namespace npr
