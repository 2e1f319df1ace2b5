// --svg (see line_export.h).
#include "app/line_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>

#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/lines/line_pass.h"
#include "renderer/lines/region_trace.h"
#include "renderer/lines/svg_export.h"
#include "app/cli.h"

namespace npr {

namespace {

// The shaded picture's regions, one per palette entry the selection shows, each filled with the
// entry's texture (renderer/lines/svg_export.h: SvgFills).
Result<SvgFills> traceFills(Renderer& renderer, const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec2& size,
                            const Palette& palette) {
  // The smooth path blends two entries: its region is the one weighing more.
  const bool blend = settings.path == RenderPath::Smooth;
  auto target = OffscreenTarget::create(size.x, size.y, blend ? OffscreenTarget::Format::RGBA32F : OffscreenTarget::Format::RGBA8);
  if (!target) return Error{target.error()};
  target->clear(glm::vec4(0.0f));
  if (Status s = renderer.render(camera, settings, {0, 0, size.x, size.y}, blend ? FrameOutput::Blend : FrameOutput::Entry); !s)
    return Error{s.error()};
  std::vector<int> labels(std::size_t(size.x) * std::size_t(size.y));
  if (blend) {
    const ImageRGBA32F selection = target->readRGBA32F();
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const float* p = &selection.pixels[4 * i];
      labels[i] = p[3] > 0.0f ? int(std::lround(p[2] < 0.5f ? p[0] : p[1])) : -1;
    }
  } else {
    const ImageRGBA8 selection = target->readRGBA8();
    for (std::size_t i = 0; i < labels.size(); ++i) labels[i] = selection.pixels[4 * i + 3] ? int(selection.pixels[4 * i]) : -1;
  }
  SvgFills fills;
  fills.regions = traceRegions(labels, size.x, size.y, int(palette.entries.size()));
  // The screen's pattern tiles texel by texel at the pattern scale; anchored and object patterns
  // are written as the screen's (a flat picture has no surface to follow).
  // An integer scale is written into the tiles texel by texel (viewers smooth a scaled
  // pattern image, which the raster's nearest texels are not); any other is left to the viewer.
  const float scale = settings.patternScale;
  const int whole = scale >= 2.0f && scale <= 8.0f && scale == std::floor(scale) ? int(scale) : 1;
  fills.scale = scale / float(whole);
  fills.backgroundColour = palette.backgroundColour;
  auto tile = [whole](const ImageRGBA8& img) -> Result<SvgPattern> {
    ImageRGBA8 big{img.width * whole, img.height * whole, std::vector<std::uint8_t>(img.pixels.size() * std::size_t(whole * whole))};
    for (int y = 0; y < big.height; ++y)
      for (int x = 0; x < big.width; ++x)
        for (int c = 0; c < 4; ++c)
          big.pixels[(std::size_t(y) * std::size_t(big.width) + std::size_t(x)) * 4 + std::size_t(c)] =
              img.pixels[(std::size_t(y / whole) * std::size_t(img.width) + std::size_t(x / whole)) * 4 + std::size_t(c)];
    Result<std::vector<std::uint8_t>> png = encodePng(big);
    if (!png) return Error{png.error()};
    return SvgPattern{std::move(*png), glm::ivec2(big.width, big.height)};
  };
  if (palette.backgroundImage) {
    Result<SvgPattern> bg = tile(*palette.backgroundImage);
    if (!bg) return Error{bg.error()};
    fills.background = std::move(*bg);
  }
  for (std::size_t e = 0; e < palette.entries.size(); ++e) {
    if (fills.regions[e].empty()) {
      fills.entries.emplace_back();
      continue;
    }
    Result<SvgPattern> p = tile(palette.entries[e].image);
    if (!p) return Error{p.error()};
    fills.entries.push_back(std::move(*p));
  }
  return fills;
}

}  // namespace

Status exportSvg(Renderer& renderer, const CameraMatrices& camera, const RenderSettings& settings, const glm::ivec2& size,
                 const SvgContents& what, const std::string& path) {
  const SceneMarks marks = renderer.marks();
  const bool anyMarks = !marks.segments.empty() || !marks.dots.empty();
  if (!settings.lines.objectSpace() && !what.fill && !anyMarks)
    return Error{"--svg: nothing to export; turn on some object-space lines (--lines silhouette,crease,boundary,material,intersection) or --svg-fill"};
  if (what.fill && !what.palette) return Error{"--svg-fill: no palette is loaded"};
  auto depth = OffscreenTarget::create(size.x, size.y, OffscreenTarget::Format::RGBA32F);
  if (!depth) return Error{depth.error()};
  depth->clear(glm::vec4(0.0f));
  if (Status s = renderer.render(camera, RenderSettings{}, {0, 0, size.x, size.y}, FrameOutput::EyePosition); !s) return s;
  const ImageRGBA32F eye = depth->readRGBA32F();
  // One group per kind and part of each line style (the line settings' own, then the sets),
  // as the frame draws them: each style keeps, on each object, the kinds it draws there.
  std::vector<SvgGroup> groups;
  int paths = 0;
  double lengthPx = 0.0;
  const LineSettings& ls = settings.lines;
  for (std::size_t i = 0; i <= ls.sets.size(); ++i) {
    // Style 0 is the base one, its groups named by kind ("silhouettes"); set N's "setN-silhouettes".
    const LineSet* set = i ? &ls.sets[i - 1] : nullptr;
    const LineStyle style = set ? LineStyle::of(*set, ls) : LineStyle::base(ls, nullptr);
    const std::string prefix = set ? "set" + std::to_string(i) + "-" : "";
    const std::vector<FeatureLine> mine = renderer.featureLines(camera, settings, [&](const std::string* object) -> std::uint8_t {
      return set ? (set->appliesTo(object) ? set->kinds : 0) : ls.baseKinds(object);
    }, set);
    if (mine.empty()) continue;
    // colour=tone: the lines split by the palette entry their lit tone matches, a group each in
    // the entry's average colour, lit and matched on the CPU as the line shader does on the GPU.
    std::vector<std::pair<std::vector<FeatureLine>, std::optional<glm::vec3>>> parts;
    const GpuPalette* palette = renderer.palettes().main();
    if (style.toneColour && palette && palette->matcher()) {
      const PreparedLighting<float> lit = prepareLighting<float>(renderer.lighting());
      const glm::mat3 normalToEye = glm::transpose(glm::inverse(glm::mat3(camera.view)));
      std::map<int, std::vector<FeatureLine>> byEntry;
      for (const FeatureLine& l : mine) {
        const glm::vec3 at = glm::vec3(camera.view * glm::vec4(0.5f * (l.a + l.b), 1.0f));
        glm::vec3 n = normalToEye * l.attributes.normal;
        n = glm::dot(n, n) > 1e-12f ? glm::normalize(n) : glm::normalize(-at);
        byEntry[palette->matcher()->match(shade(lit, at, n, false))].push_back(l);
      }
      for (auto& [entry, lines] : byEntry) parts.push_back({std::move(lines), palette->averages().at(std::size_t(entry))});
    } else {
      parts.push_back({mine, std::nullopt});
    }
    for (const auto& [lines, colour] : parts)
      for (const bool hidden : {false, true}) {
        if (!(hidden ? style.hidden : style.visible)) continue;
        const SvgLines chains = visibleLineChains(lines, camera, size, eye, hidden);
        paths += chains.paths;
        lengthPx += chains.lengthPx;
        const std::string suffix = colour ? "-tone-" + hexColour(*colour).substr(1) : "";
        for (int k = 0; k < kEdgeKinds; ++k)
          groups.push_back({prefix + kLineKinds[k].plural + (hidden ? "-hidden" : "") + suffix, colour.value_or(style.colours[k]),
                            hidden ? style.hiddenWidthScale * style.width : style.width, hidden ? style.hiddenInk : 1.0f,
                            hidden ? style.hiddenDash : style.dash, chains.chains[k], hidden ? 0.0f : style.taper});
      }
  }
  std::vector<SvgDots> dots;
  if (anyMarks) {
    // The file's own points and lines, as the frame draws them: in the base style's outline
    // ink and width, visible parts only.
    const LineStyle style = LineStyle::base(ls, nullptr);
    const glm::vec3 ink = style.colours[int(EdgeKind::Silhouette)];
    const SvgLines chains = visibleLineChains(marks.segments, camera, size, eye);
    paths += chains.paths;
    lengthPx += chains.lengthPx;
    groups.push_back({"marks", ink, style.width, 1.0f, glm::vec2(0.0f), chains.chains[int(EdgeKind::Silhouette)], 0.0f});
    dots.push_back({"marks-dots", ink, markDotDiameter(style.width), visibleDots(marks.dots, camera, size, eye)});
    paths += int(dots.back().centres.size());
  }
  std::optional<SvgFills> fills;
  if (what.fill) {
    Result<SvgFills> traced = traceFills(renderer, camera, settings, size, *what.palette);
    if (!traced) return Error{traced.error()};
    fills = std::move(*traced);
  }
  std::vector<std::uint8_t> png;
  if (what.raster) {
    Result<std::vector<std::uint8_t>> encoded = encodePng(*what.raster);
    if (!encoded) return Error{encoded.error()};
    png = std::move(*encoded);
  }
  std::ofstream out(path, std::ios::binary);
  out << svgDocument(groups, size, png, fills ? &*fills : nullptr, dots);
  if (!out.flush()) return Error{path + ": cannot write the SVG"};
  std::string regions;
  if (fills) {
    std::size_t loops = 0, filled = 0;
    for (const auto& r : fills->regions) loops += r.size(), filled += !r.empty();
    regions = ", " + std::to_string(filled) + " palette regions in " + std::to_string(loops) + " outlines";
  }
  tellUser("wrote " + path + ": " + std::to_string(paths) + " paths, " + std::to_string(static_cast<long>(lengthPx + 0.5)) + " px of lines" + regions);
  return okStatus();
}

}  // namespace npr
