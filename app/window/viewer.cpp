// Viewer actions (see viewer.h).
#include "app/window/viewer.h"

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

#include "app/settings/style_file.h"
#include "renderer/core/heap_policy.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/palette/palette_analysis.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

bool isPaletteFile(const std::string& path) {
  std::error_code ec;
  return fs::path(path).extension() == ".palette" || fs::is_directory(path, ec);
}

void reportIfFailed(ViewerState& s, const Status& st) {
  if (!st) s.problem(st.error());
}

}  // namespace

glm::ivec4 Viewer::sceneViewport() const {
  const glm::ivec2 fb = window->framebufferSize();
  const glm::ivec2 ws = window->windowSize();
  const int panel = overlay && ws.x > 0 ? int(std::lround(double(panelWidth) * fb.x / ws.x)) : 0;
  return {0, 0, std::max(fb.x - panel, 1), fb.y};
}

float Viewer::aspect() const {
  const glm::ivec4 s = sceneViewport();
  const float a = s.w > 0 ? float(s.z) / float(s.w) : 1.0f;
  return state.splitView ? a * 0.5f : a;
}

void applyAction(Viewer& v, const KeyAction& a) {
  ViewerState& s = v.state;
  Renderer& r = *v.renderer;
  const int paletteCount = static_cast<int>(s.palettes.size());
  switch (a.action) {
    case Action::Quit: v.quit = true; break;
    case Action::ToggleOverlay: v.overlay = !v.overlay; break;
    case Action::ToggleHelp: v.help = !v.help; break;
    case Action::Screenshot: v.screenshotRequested = a.param; break;
    case Action::Open:
      v.dialog = Viewer::Dialog::Open;
      v.dialogAdds = a.param == 1;
      v.dialogJustOpened = true;
      break;
    case Action::SaveStyle:
      v.dialog = Viewer::Dialog::SaveStyle;
      v.dialogJustOpened = true;
      break;
    case Action::Export:
      v.dialog = Viewer::Dialog::Export;
      v.dialogJustOpened = true;
      break;
    // A palette that fails to load leaves the current one; the bar says why. Its images are
    // decoded whole, on worker threads: their transient memory goes back as a file's does.
    case Action::SelectPalette:
    case Action::NextPalette:
    case Action::PreviousPalette: {
      const int step = a.action == Action::NextPalette ? 1 : a.action == Action::PreviousPalette ? paletteCount - 1 : 0;
      if (a.action != Action::SelectPalette && !paletteCount) break;
      reportIfFailed(s, s.selectPalette(step ? (s.paletteIndex + step) % paletteCount : a.param, r));
      releaseFreedHeapMemory();
      break;
    }
    case Action::CycleMatch:
      s.settings.bands.clear();
      s.settings.match = s.settings.match == MatchMode::Colors ? MatchMode::Intensity
                         : s.settings.match == MatchMode::Intensity ? MatchMode::Order : MatchMode::Colors;
      if (s.palette)
        for (const auto& w : analysePalette(*s.palette).suitabilityWarnings(s.settings.match)) s.note(s.palette->name + ": " + w);
      break;
    case Action::RangeScaleUp: s.settings.rangeScale = std::min(s.settings.rangeScale * 1.1f, 100.0f); break;
    case Action::RangeScaleDown: s.settings.rangeScale = std::max(s.settings.rangeScale / 1.1f, 0.01f); break;
    case Action::CyclePath: {
      const auto& paths = userRenderPaths();
      auto it = std::find(paths.begin(), paths.end(), s.settings.path);
      s.settings.path = (it == paths.end() || it + 1 == paths.end()) ? paths.front() : *(it + 1);
      break;
    }
    case Action::ToggleSplit:
      s.splitView = !s.splitView;
      // Each half is half as wide: framed again so both show the whole scene (leaving the
      // split view keeps the view; the model only gains room).
      if (s.splitView && !s.fileCamera) {
        s.viewAspect = v.aspect();
        s.frameScene();
        r.resetPattern();
      }
      break;
    case Action::FrameModel:
      s.fileCamera.reset();
      s.viewAspect = v.aspect();
      s.frameScene();
      r.resetPattern();
      break;
    case Action::CyclePattern:
      s.settings.pattern = s.settings.pattern == PatternSpace::Screen     ? PatternSpace::Anchored
                           : s.settings.pattern == PatternSpace::Anchored ? PatternSpace::Object
                                                                          : PatternSpace::Screen;
      r.resetPattern();
      break;
    case Action::ResetView:
      s.fileCamera.reset();
      s.camera.reset();
      r.resetPattern();
      break;
    case Action::ToggleLightFollow: {
      // Keep the light where it is on screen when switching: convert its position.
      const CameraMatrices cam = s.camera.matrices(v.aspect());
      const glm::vec3 world = s.lightWorldPosition(cam);
      s.lightFollowsCamera = !s.lightFollowsCamera;
      s.light = s.lightFollowsCamera ? glm::vec3(cam.view * glm::vec4(world, 1.0f)) : world;
      break;
    }
    case Action::ToggleVsync: v.vsync = !v.vsync; glfwSwapInterval(v.vsync ? 1 : 0); break;
    case Action::TogglePlay:
      if (v.state.animationLength() > 0.0) v.state.playback.playing = !v.state.playback.playing;
      else v.state.note("nothing to play: " + v.state.scene.label() + " has no animation that moves it");
      break;
    case Action::MoveLight: {
      const float step = 0.1f;  // a tenth of the scene's radius
      s.light[a.param / 2] += (a.param % 2) ? step : -step;
      break;
    }
  }
}

bool openFile(Viewer& v, const std::string& path, bool add) {
  if (fs::path(path).extension() == ".style") {
    Result<Style> style = loadStyle(path);
    Status st = style ? applyStyle(*style, v.state, *v.renderer) : Status(Error{style.error()});
    if (!st) v.state.problem("style not applied: " + st.error());
    return false;
  }
  const bool palette = isPaletteFile(path);
  v.state.viewAspect = v.aspect();  // a new scene is framed for the window's shape
  const Status st = palette ? v.state.loadPalette(path, *v.renderer) : v.state.loadModels({path}, add, *v.renderer);
  releaseFreedHeapMemory();  // the load's transient memory, and the scene it replaced
  if (st) v.state.note((add && !palette ? "added " : "loaded ") + path);
  else v.state.problem(st.error());
  return st && !palette;
}

void takeScreenshot(Viewer& v, const fs::path& file) {
  const glm::ivec2 fb = v.window->framebufferSize();
  const Status s = writeImage(file.string(), readFramebufferRGBA8(0, 0, fb.x, fb.y));
  if (s) v.state.note("screenshot written to " + file.string());
  else v.state.problem("screenshot not written: " + s.error());
}

}  // namespace npr
