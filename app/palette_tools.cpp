// --make-palette and --palette-sheet (see palette_tools.h).
#include "app/palette_tools.h"


#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/contact_sheet.h"
#include "app/headless/headless_session.h"
#include "app/progress_line.h"
#include "app/startup.h"
#include "app/viewer_state.h"
#include "renderer/core/colour.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/palette/palette_analysis.h"
#include "app/cli.h"

namespace npr {
namespace fs = std::filesystem;

int runPaletteMaker(const Options& o) {
  MakePaletteRequest r;
  r.image = o.makePalette;
  r.ladder = o.ladder;
  r.tam = o.tam;
  r.levels = o.levels;
  r.outDir = o.outDir;
  ProgressLine progress("making palette " + fs::path(o.outDir).filename().string());
  Result<std::string> file = makePalette(r, [&](double f) { progress.update(f); });
  if (!file) return reportFailure(file.error());
  Result<Palette> p = loadPalette(*file);
  if (!p) return reportFailure("the palette just written does not load: " + p.error());
  tellUser("wrote " + *file + " (" + std::to_string(p->entries.size()) + " entries)");
  std::printf("%s\n", paletteReportJson(*p).c_str());
  return 0;
}

namespace {

constexpr int kSphere = 256, kTile = 96, kSwatch = 14, kLabel = 18, kGap = 6, kColumns = 8, kTitle = 24;

// A lit sphere drawn with the palette through the pixel path, as the viewer shows it.
Result<ImageRGBA8> litSphere(HeadlessSession& session, const std::string& palette) {
  Options o;
  o.models = {"generated:icosphere-4"};
  o.palettes = {palette};
  o.settings.push_back({findSetting("path"), "pixel", "the contact sheet"});
  ViewerState state;
  if (Status s = startScene(o, state, *session.renderer); !s) return Error{s.error()};
  auto target = OffscreenTarget::create(kSphere, kSphere);
  if (!target) return Error{target.error()};
  target->bind();
  const CameraMatrices cam = state.camera.matrices(1.0f);
  if (Status s = state.applyLight(*session.renderer, cam); !s) return Error{s.error()};
  if (Status s = session.renderer->render(cam, state.settings, {0, 0, kSphere, kSphere}); !s) return Error{s.error()};
  finishGpuWork();
  return target->readRGBA8();
}

// Sheets are named after the palette's folder (the shipped palettes' and the maker's layout),
// made unique within a run.
std::string sheetName(const std::string& paletteFile, std::vector<std::string>& used) {
  std::error_code ec;
  fs::path p = fs::path(paletteFile).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // a folder given with a trailing slash
  std::string name = fs::is_directory(p, ec) ? p.filename().string() : p.parent_path().filename().string();
  if (name.empty() || name == ".") name = p.stem().string();
  std::string unique = name;
  for (int k = 2; std::find(used.begin(), used.end(), unique) != used.end(); ++k) unique = name + "-" + std::to_string(k);
  used.push_back(unique);
  return unique;
}

Status writeSheet(HeadlessSession& session, const std::string& paletteFile, const fs::path& out, bool& fontMissing) {
  Result<Palette> p = loadPalette(paletteFile);
  if (!p) return Error{p.error()};
  Result<ImageRGBA8> sphere = litSphere(session, paletteFile);
  if (!sphere) return Error{paletteFile + ": " + sphere.error()};
  const int n = static_cast<int>(p->entries.size());
  const int columns = std::min(n, kColumns), rows = (n + kColumns - 1) / kColumns;
  const int width = kSphere + kGap + columns * (kTile + kGap) + kGap;
  const int height = kTitle + std::max(kSphere, rows * (kTile + kSwatch + kLabel + kGap)) + kGap;
  ImageRGBA8 sheet = blankSheet(width, height);
  const PaletteAnalysis a = analysePalette(*p);
  char title[256];
  std::snprintf(title, sizeof title, "%s: %d levels, tones %.2f to %.2f, steps within %.1f%% of even", p->name.c_str(), n,
                a.minIntensity / 3.0f, a.maxIntensity / 3.0f, 100.0f * a.spacingError);
  drawText(sheet, kGap, kTitle - 6, title, 16, fontMissing);
  paste(sheet, 0, kTitle, *sphere);
  const ImageRGBA8* bg = p->backgroundImage ? &*p->backgroundImage : nullptr;
  for (int i = 0; i < n; ++i) {
    const PaletteEntry& e = p->entries[size_t(i)];
    const int x = kSphere + kGap + (i % kColumns) * (kTile + kGap), y = kTitle + (i / kColumns) * (kTile + kSwatch + kLabel + kGap);
    // The level as the screen shows it, one texel per pixel, tiled if it is smaller than a tile.
    const ImageRGBA8 shown = compositeOver(e.image, p->backgroundColour, bg);
    ImageRGBA8 tile{kTile, kTile, std::vector<std::uint8_t>(size_t(kTile) * kTile * 4)};
    for (int ty = 0; ty < kTile; ++ty)
      for (int tx = 0; tx < kTile; ++tx)
        for (int k = 0; k < 4; ++k)
          tile.pixels[(size_t(ty) * kTile + size_t(tx)) * 4 + size_t(k)] =
              shown.pixels[(size_t(ty % shown.height) * size_t(shown.width) + size_t(tx % shown.width)) * 4 + size_t(k)];
    paste(sheet, x, y, tile);
    const float swatch[3] = {e.average.r, e.average.g, e.average.b};
    fillRect(sheet, x, y + kTile, kTile, kSwatch, swatch);
    char label[32];
    std::snprintf(label, sizeof label, "%d: %.3f", i, e.intensity / 3.0f);
    drawText(sheet, x, y + kTile + kSwatch + kLabel - 4, label, 13, fontMissing);
  }
  if (Status s = writeImage(out.string(), sheet); !s) return s;
  tellUser("wrote " + out.string());
  return okStatus();
}

}  // namespace

int runPaletteSheets(const Options& o) {
  std::error_code ec;
  fs::create_directories(o.paletteSheet, ec);
  if (!fs::is_directory(o.paletteSheet, ec)) return reportFailure("--palette-sheet: cannot create the folder " + o.paletteSheet);
  auto session = openHeadlessSession(true, o.gpu);
  if (!session) return reportFailure(session.error());
  const std::vector<std::string> palettes = o.palettes.empty() ? discoverPalettes() : o.palettes;
  bool fontMissing = false;
  int failed = 0;
  std::vector<std::string> used;
  for (const std::string& p : palettes)
    if (Status s = writeSheet(*session, p, fs::path(o.paletteSheet) / (sheetName(p, used) + ".png"), fontMissing); !s) {
      tellUser(s.error());
      ++failed;
    }
  if (fontMissing) std::fprintf(stderr, "npr-viewer: no DejaVu Sans font found: the sheets show the tones as swatches without numbers\n");
  if (const int errors = gl::checkErrors("palette sheets")) return reportFailure(std::to_string(errors) + " OpenGL error(s)");
  return failed ? 1 : 0;
}

}  // namespace npr
