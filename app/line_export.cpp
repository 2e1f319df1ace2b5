// --svg (see line_export.h).
#include "app/line_export.h"

#include <cstdio>
#include <fstream>

#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lines/line_pass.h"
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
  // One group per kind and part of each line style (the line settings' own, then the sets),
  // as the frame draws them.
  const std::vector<FeatureLine> all = renderer.featureLines(camera, settings);
  const char* names[kEdgeKinds] = {"silhouettes", "creases", "boundaries", "materials", "intersections"};
  std::vector<SvgGroup> groups;
  int paths = 0;
  double lengthPx = 0.0;
  const std::vector<LineStyle> styles = lineStyles(settings.lines);
  const bool base = settings.lines.baseKinds() != 0;  // lineStyles puts the base style first
  for (std::size_t i = 0; i < styles.size(); ++i) {
    const LineStyle& style = styles[i];
    // The base style's groups are named by kind ("silhouettes"); set N's "setN-silhouettes".
    const std::string prefix = base && i == 0 ? "" : "set" + std::to_string(base ? i : i + 1) + "-";
    std::vector<FeatureLine> mine;
    for (const FeatureLine& l : all)
      if ((style.kinds >> int(l.kind + 0.5f)) & 1u) mine.push_back(l);
    for (const bool hidden : {false, true}) {
      if (!(hidden ? style.hidden : style.visible)) continue;
      const SvgLines chains = visibleLineChains(mine, camera, size, eye, hidden);
      paths += chains.paths;
      lengthPx += chains.lengthPx;
      for (int k = 0; k < kEdgeKinds; ++k)
        groups.push_back({prefix + names[k] + (hidden ? "-hidden" : ""), style.colours[k], hidden ? style.hiddenWidthScale * style.width : style.width,
                          hidden ? style.hiddenInk : 1.0f, hidden ? style.hiddenDash : style.dash, chains.chains[k]});
    }
  }
  std::vector<std::uint8_t> png;
  if (raster) {
    Result<std::vector<std::uint8_t>> encoded = encodePng(*raster);
    if (!encoded) return Error{encoded.error()};
    png = std::move(*encoded);
  }
  std::ofstream out(path, std::ios::binary);
  out << svgDocument(groups, size, png);
  if (!out.flush()) return Error{path + ": cannot write the SVG"};
  tellUser("wrote " + path + ": " + std::to_string(paths) + " paths, " + std::to_string(static_cast<long>(lengthPx + 0.5)) + " px of lines");
  return okStatus();
}

}  // namespace npr
