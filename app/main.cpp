// npr-viewer: parses the command line and hands over to the window, --headless, --info,
// --palette-info, --make-palette, --palette-sheet, --list-paths, --settings-reference,
// --gl-info, --version or --benchmark. Exit status: 0 success, 1 a file failed to load or
// render, 2 bad arguments.
#include <cstdio>

#include "app/benchmark/benchmark_run.h"
#include "app/cli.h"
#include "app/data_directory.h"
#include "app/headless/headless_session.h"
#include "app/headless/headless_run.h"
#include "app/headless/style_sheet.h"
#include "app/palette_tools.h"
#include "app/settings/settings_reference.h"
#include "app/window/window_viewer.h"
#include "renderer/core/heap_policy.h"
#include "renderer/mesh/scene_loader.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_analysis.h"
#include "renderer/paths/path_table.h"
#include "app/version.h"

#if defined(__SANITIZE_ADDRESS__)
// See tests/gl/gl_test_env.cpp: Mesa's unloaded driver would be reported as leaking.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif

int main(int argc, char** argv) {
  npr::keepFreedHeapMemory();  // frame times without the heap trimmed every frame (heap_policy.h)
  const npr::ParseOutcome parsed = npr::parseCommandLine(argc, argv);
  if (!parsed.options) return parsed.exitCode;
  const npr::Options& o = *parsed.options;

  if (o.version) {
    const std::string git = NPR_GIT_DESCRIPTION;
    std::printf("npr-viewer %s%s\ndata: %s\n", NPR_VERSION, git.empty() ? "" : (" (" + git + ")").c_str(),
                npr::dataDirectory().c_str());
    return 0;
  }
  if (o.glInfo) {
    auto session = npr::openHeadlessSession(false, o.gpu);
    if (!session) return npr::reportFailure(session.error());
    const npr::GlInfo& info = session->context->info();
    std::printf("%s\nEGL devices:\n%s", info.line().c_str(),
                info.devices.empty() ? "  (none listed)\n" : npr::describeDevices(info.devices).c_str());
    return 0;
  }
  if (o.settingsReference) {
    std::printf("%s", npr::settingsReferenceMarkdown().c_str());
    return 0;
  }
  if (o.listPaths) {
    for (const npr::PathInfo& p : npr::renderPaths())
      std::printf("%s\t%s\t%s\n", p.name, p.userSelectable ? "user" : "internal", p.label);
    return 0;
  }
  if (o.info) {
    if (o.models.empty()) {
      std::fprintf(stderr, "npr-viewer: --info needs a MODEL file\n");
      return 2;
    }
    // One line per file: its load report and its scene.
    for (const std::string& model : o.models) {
      npr::Result<npr::LoadedScene> s = npr::loadScene(model, npr::SceneLoadOptions{o.splitObjects, o.verbose});
      if (!s) return npr::reportFailure(s.error());
      std::printf("%s\n", npr::sceneReportJson(*s).c_str());
    }
    return 0;
  }
  if (!o.paletteInfo.empty()) {
    npr::Result<npr::Palette> p = npr::loadPalette(o.paletteInfo);
    if (!p) return npr::reportFailure(p.error());
    std::printf("%s\n", npr::paletteReportJson(*p).c_str());
    return 0;
  }
  if (!o.makePalette.empty()) return npr::runPaletteMaker(o);
  if (!o.paletteSheet.empty()) return npr::runPaletteSheets(o);
  if (!o.styleSheet.empty()) return npr::runStyleSheet(o);
  if (o.benchmark) return npr::runBenchmark(o);
  if (o.headless) return npr::runHeadless(o);
  return npr::runWindowViewer(o);
}
