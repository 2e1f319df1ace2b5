// --svg FILE: the frame's visible feature lines as SVG (renderer/lines/svg_export.h), written
// after a headless frame or from the overlay's button; with the rendered frame embedded
// underneath when asked.
#pragma once

#include <string>

#include "renderer/core/result.h"
#include "renderer/renderer.h"

namespace npr {

// Renders the frame's eye-space depth at `size`, cuts the lines it hides, writes `path`;
// `raster` (may be null) is embedded as a layer. Logs the path count and total length.
[[nodiscard]] Status exportLinesSvg(Renderer& renderer, const CameraMatrices& camera, const RenderSettings& settings,
                                    const glm::ivec2& size, const ImageRGBA8* raster, const std::string& path);

}  // namespace npr
