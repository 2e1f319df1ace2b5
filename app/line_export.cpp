// --svg (see line_export.h).
#include "app/line_export.h"

#include <cstdio>
#include <fstream>

#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lines/svg_export.h"
#include "app/cli.h"

namespace npr {

Status exportLinesSvg(Renderer& renderer, const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec2& size,
                      const ImageRGBA8* raster, const std::string& path) {
  if (!settings.lines.objectSpace())
    return Error{"--svg: no object-space lines to export; turn some on (--lines silhouette,crease,boundary,material,intersection)"};
  auto depth = OffscreenTarget::create(size.x, size.y, OffscreenTarget::Format::RGBA32F);
  if (!depth) return Error{depth.error()};
  depth->clear(glm::vec4(0.0f));
  if (Status s = renderer.renderGeometry(camera, GeometryOutput::EyePosition, {0, 0, size.x, size.y}); !s) return s;
  const ImageRGBA32F eye = depth->readRGBA32F();
  const SvgLines lines = visibleLineChains(renderer.featureLines(camera, settings), camera, size, eye);
  std::vector<std::uint8_t> png;
  if (raster) {
    Result<std::vector<std::uint8_t>> encoded = encodePng(*raster);
    if (!encoded) return Error{encoded.error()};
    png = std::move(*encoded);
  }
  std::ofstream out(path, std::ios::binary);
  out << svgDocument(lines, size, settings.lines, png);
  if (!out.flush()) return Error{path + ": cannot write the SVG"};
  tellUser("wrote " + path + ": " + std::to_string(lines.paths) + " paths, " + std::to_string(static_cast<long>(lines.lengthPx + 0.5)) + " px of lines");
  return okStatus();
}

}  // namespace npr
