// The style sheet (see style_sheet.h).
#include "app/headless/style_sheet.h"


#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/contact_sheet.h"
#include "app/headless/headless_session.h"
#include "app/progress_line.h"
#include "app/settings/style_file.h"
#include "app/startup.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/offscreen_target.h"

namespace npr {

namespace {

constexpr int kLabel = 22;  // the strip under each cell holding the style's name

// One cell: the scene as --style STYLE with the other options beside it, framed for the cell.
Result<ImageRGBA8> renderCell(const Options& o, const std::string& styleFile, const glm::ivec2& cell, Renderer& renderer) {
  Options withStyle = o;
  withStyle.style = styleFile;
  withStyle.size = cell;
  ViewerState state;
  if (Status s = startScene(withStyle, state, renderer); !s) return Error{s.error()};
  auto target = OffscreenTarget::create(cell.x, cell.y);
  if (!target) return Error{target.error()};
  target->bind();
  const CameraMatrices cam = state.view(float(cell.x) / float(cell.y));
  if (Status s = state.applyLight(renderer, cam); !s) return Error{s.error()};
  if (Status s = renderer.render(cam, state.settings, {0, 0, cell.x, cell.y}); !s) return Error{s.error()};
  finishGpuWork();
  ImageRGBA8 image = target->readRGBA8();
  // What a style sets on the renderer beyond the look's rows: the next style starts clean.
  renderer.palettes().clearControl(ControlParameter::Shadow);
  renderer.palettes().clearControl(ControlParameter::Occlusion);
  return image;
}

}  // namespace

int runStyleSheet(const Options& o) {
  const std::vector<std::string> styles = discoverStyles();
  if (styles.empty()) return reportFailure("--style-sheet: no style files in " + dataDirectory() + "/palettes/styles");
  // Columns and rows so the cells are about as wide as the sheet's shape asks.
  const int n = static_cast<int>(styles.size());
  const float sheetAspect = float(o.size.x) / float(o.size.y);
  const int columns = std::clamp(static_cast<int>(std::lround(std::sqrt(double(n) * sheetAspect * 0.75))), 1, n);
  const int rows = (n + columns - 1) / columns;
  const glm::ivec2 cell(o.size.x / columns, o.size.y / rows - kLabel);
  if (cell.x < 32 || cell.y < 32)
    return reportFailure("--style-sheet: --size " + std::to_string(o.size.x) + "x" + std::to_string(o.size.y) + " leaves cells of " +
                         std::to_string(cell.x) + "x" + std::to_string(cell.y) + " for " + std::to_string(n) + " styles; give at least " +
                         std::to_string(columns * 32) + "x" + std::to_string(rows * (32 + kLabel)));
  auto session = openHeadlessSession(true, o.gpu);
  if (!session) return reportFailure(session.error());
  ImageRGBA8 sheet = blankSheet(columns * cell.x, rows * (cell.y + kLabel));
  bool fontMissing = false;
  ProgressLine progress("style sheet of " + std::to_string(n) + " styles");
  for (int i = 0; i < n; ++i) {
    const std::string& file = styles[static_cast<std::size_t>(i)];
    Result<ImageRGBA8> image = renderCell(o, file, cell, *session->renderer);
    if (!image) return reportFailure("--style-sheet: " + file + ": " + image.error());
    const int x = (i % columns) * cell.x, y = (i / columns) * (cell.y + kLabel);
    paste(sheet, x, y, *image);
    Result<Style> style = loadStyle(file);
    const std::string name = std::filesystem::path(file).stem().string();
    drawText(sheet, x + 6, y + cell.y + kLabel - 6, style && !style->name.empty() ? style->name + " (" + name + ")" : name, 15, fontMissing);
    progress.update(double(i + 1) / n);
  }
  if (fontMissing) std::fprintf(stderr, "npr-viewer: no DejaVu Sans font found: the style sheet's cells are not labelled\n");
  if (Status s = writeImage(o.styleSheet, sheet); !s) return reportFailure(s.error());
  if (const int errors = gl::checkErrors("style sheet")) return reportFailure(std::to_string(errors) + " OpenGL error(s) during the style sheet");
  tellUser("style sheet of " + std::to_string(n) + " styles written to " + o.styleSheet);
  return 0;
}

}  // namespace npr
