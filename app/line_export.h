// --svg FILE: the frame as SVG (renderer/lines/svg_export.h): its feature lines as styled
// groups, and with --svg-fill its shaded picture as regions filled with the palette's
// textures; written after a headless frame or from the overlay's button; with the rendered
// frame embedded underneath when asked.
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/palette/palette.h"
#include "renderer/renderer.h"

namespace npr {

struct SvgContents {
  const ImageRGBA8* raster = nullptr;  // embedded underneath (--svg-raster); null: none
  bool fill = false;                   // the palette's regions (--svg-fill)
  const Palette* palette = nullptr;    // the main palette, for the fills
};

// Renders the frame's eye-space depth at `size`, cuts the lines it hides, traces the fills when
// asked, writes `path`. Logs the path count, total length and regions.
[[nodiscard]] Status exportSvg(Renderer& renderer, const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec2& size,
                               const SvgContents& what, const std::string& path);

}  // namespace npr
