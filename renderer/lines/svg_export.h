// Vector export of the feature lines (`--svg FILE`): the object-space lines the line pass draws
// for a camera, projected, cut where the model hides them (each edge sampled at a pixel step
// against the frame's eye-space depth; the hidden parts instead for hidden lines), chained into
// polylines at shared ends in drawing order, one SVG group per kind and part of each line style
// (the line settings' own, then the line sets) with its colour, width and dashes, optionally over the rendered frame as
// an embedded raster layer, and the file's own points and lines (glTF's) as dots and polylines. Plain SVG 1.1 that vector editors read. No GL here: the caller
// hands over the lines and the depth it read back.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/image.h"
#include "renderer/lines/feature_edges.h"
#include "renderer/settings/render_settings.h"

namespace npr {

struct SvgLines {
  // 2D polylines in window pixels (y down), one list per EdgeKind.
  std::vector<std::vector<glm::vec2>> chains[kEdgeKinds];  // per EdgeKind
  int paths = 0;
  double lengthPx = 0;  // total drawn length
};

// Projects `lines` (object space) with `camera` into a `size` window and keeps what the model
// does not hide (or, `hiddenParts`, only what it hides): `eyePosition` is the frame's eye-space
// position per pixel (rows top first, alpha 0 where no surface), as
// Renderer::renderGeometry(EyePosition) reads it back.
SvgLines visibleLineChains(const std::vector<FeatureLine>& lines, const CameraMatrices& camera, const glm::ivec2& size,
                           const ImageRGBA32F& eyePosition, bool hiddenParts = false);

// Of `dots` (scene space), where they land in the window (pixels, y down) and the model does not
// hide them, tested as the lines' samples are.
std::vector<glm::vec2> visibleDots(const std::vector<glm::vec3>& dots, const CameraMatrices& camera, const glm::ivec2& size,
                                   const ImageRGBA32F& eyePosition);

// "#rrggbb", each channel clamped to 0..1 and rounded.
std::string hexColour(const glm::vec3& c);

// One group of the document: polylines in one stroke style.
struct SvgGroup {
  std::string id;
  glm::vec3 colour{0.0f};
  float width = 1.0f, opacity = 1.0f;
  glm::vec2 dash{0.0f};  // pixels on, off; 0: solid
  std::vector<std::vector<glm::vec2>> chains;
  // Pixels over which each chain narrows to a point at both ends (0: blunt). Tapered chains
  // are written as filled outlines (SVG strokes have one width), dashes cut out of them.
  float taper = 0.0f;
};

// Round dots in one colour (a file's points), `diameter` pixels across.
struct SvgDots {
  std::string id;
  glm::vec3 colour{0.0f};
  float diameter = 3.0f;
  std::vector<glm::vec2> centres;
};

// The outline of `chain` drawn `width` wide and narrowing to points over `taper` pixels at both
// ends (a closed chain, first point = last, keeps its width), split into dashes (`dash` pixels
// on, off along the chain; 0: solid): closed polygons, one per dash.
std::vector<std::vector<glm::vec2>> taperedOutlines(const std::vector<glm::vec2>& chain, float width, float taper, glm::vec2 dash);
// The groups of the line settings' kinds, each in its kind's colour and `style.width`.
std::vector<SvgGroup> kindGroups(const SvgLines& lines, const LineSettings& style);

// The shaded picture as vector regions (`--svg-fill`): each palette entry's region (traced from
// the selection output, lines/region_trace.h) filled with that entry's texture as an SVG
// pattern tiled over the frame as the screen-space pattern tiles it, over the background.
struct SvgPattern {
  std::vector<std::uint8_t> png;  // one tile, as the palette file's image
  glm::ivec2 size{1};             // its texels
};
struct SvgFills {
  glm::vec3 backgroundColour{1.0f};
  std::optional<SvgPattern> background;  // tiled like the entries
  std::vector<SvgPattern> entries;
  std::vector<std::vector<std::vector<glm::ivec2>>> regions;  // per entry: closed loops, pixel corners
  float scale = 1.0f;  // window pixels per texel
};

// The SVG document: the canvas is the frame; `rasterPng` (may be empty) is embedded underneath,
// then the fills (may be null), then the groups in order, then the dots, empty ones left out.
std::string svgDocument(const std::vector<SvgGroup>& groups, const glm::ivec2& size, const std::vector<std::uint8_t>& rasterPng,
                        const SvgFills* fills = nullptr, const std::vector<SvgDots>& dots = {});

}  // namespace npr
