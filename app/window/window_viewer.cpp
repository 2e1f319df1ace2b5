// The windowed viewer's frame loop, top to bottom: poll input, build the overlay, light and
// render the scene (or the split view) with the light marker, draw the overlay, swap. The
// window, input, overlay and actions live in the other files of this folder.
#include "app/window/window_viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cstdio>
#include <optional>

#include "app/camera_animation.h"
#include "app/line_export.h"
#include "app/startup.h"
#include "renderer/core/image_io.h"
#include "app/window/input_callbacks.h"
#include "app/next_free_name.h"
#include "app/window/export_dialog.h"
#include "app/window/file_dialogs.h"
#include "app/window/recent_files.h"
#include "app/window/help_overlay.h"
#include "app/window/message_bar.h"
#include "app/window/overlay.h"
#include "app/window/viewer.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/offscreen_target.h"

namespace npr {

namespace {

// The scene over `width` x `height` from the corner: the chosen path, or in the split view the
// plain lit render the original showed beside its NPR images (left) and the chosen path
// (right). `each` draws over each view once it is drawn (the window's light marker).
Status drawViews(Viewer& v, const CameraMatrices& cam, int width, int height, const std::function<Status(const glm::ivec4&)>& each) {
  auto one = [&](const RenderSettings& settings, const glm::ivec4& viewport) {
    Status st = v.renderer->render(cam, settings, viewport);
    return st && each ? each(viewport) : st;
  };
  if (!v.state.splitView) return one(v.state.settings, {0, 0, width, height});
  const int half = width / 2;
  RenderSettings reference = v.state.settings;
  reference.path = RenderPath::Reference;
  const Status left = one(reference, {0, 0, half, height});
  const Status right = one(v.state.settings, {half, 0, width - half, height});
  return left ? right : left;
}

// The scene as the window shows it (both halves of the split view), at the window's whole
// size without the panel, into a target of its own.
void writeSceneScreenshot(Viewer& v, const glm::ivec2& size, const std::filesystem::path& file) {
  Result<OffscreenTarget> target = OffscreenTarget::create(size.x, size.y);
  Status st = target ? okStatus() : Status(Error{target.error()});
  if (st) {
    target->bind();
    const int half = size.x / 2;
    const float aspect = float(v.state.splitView ? half : size.x) / float(std::max(size.y, 1));
    const CameraMatrices cam = v.state.view(aspect);
    st = v.state.applyLight(*v.renderer, cam);
    if (st) st = drawViews(v, cam, size.x, size.y, nullptr);
    if (st) st = writeImage(file.string(), target->readRGBA8());
  }
  bindWindowFramebuffer();
  if (st) v.state.note("screenshot written to " + file.string());
  else v.state.problem("screenshot not written: " + st.error());
}

}  // namespace

int runWindowViewer(const Options& o) {
  Viewer v;
  Result<std::unique_ptr<GlfwWindow>> window = GlfwWindow::open(o.size, "npr-viewer");
  if (!window) return reportFailure(window.error());
  v.window = std::move(*window);
  gl::installDebugOutput();
  Result<std::unique_ptr<Renderer>> renderer = Renderer::create();
  if (!renderer) return reportFailure(renderer.error());
  v.renderer = std::move(*renderer);
  // The occlusion bake runs a few directions per frame in the window, so it stays responsive
  // and the overlay shows progress (headless runs bake to the end at once).
  v.renderer->setOcclusionBudget(30.0);
  // Hatching keeps its physical size on a high-DPI screen unless a style or the command line
  // sets a scale (startScene applies those over this default).
  v.state.settings.patternScale = std::clamp(v.window->contentScale(), RenderSettings::kMinPatternScale, RenderSettings::kMaxPatternScale);
  if (Status s = startScene(o, v.state, *v.renderer); !s) {
    // Opened from a file manager there is no terminal: a file that fails opens the default
    // model instead, with the reason in the window's message bar (and on stderr). A failure
    // that is not the file's (an option, a style) fails again and ends the run as before.
    if (o.models.empty()) return reportFailure(s.error());
    // (Loads are all or nothing: the failed model left the state as it was.)
    Options plain = o;
    plain.models.clear();
    if (Status again = startScene(plain, v.state, *v.renderer); !again) return reportFailure(s.error());
    if (v.state.problems.empty()) v.state.problem(s.error());  // a failed load has said it already
  }
  v.recent = loadRecentFiles();
  for (auto it = o.models.rbegin(); it != o.models.rend(); ++it) {
    std::error_code ec;
    addRecentFile(v.recent, std::filesystem::absolute(*it, ec).string());
  }
  if (!o.models.empty()) saveRecentFiles(v.recent);
  if (!o.screenshot.empty()) v.screenshotDir = std::filesystem::path(o.screenshot).parent_path();
  if (v.screenshotDir.empty()) v.screenshotDir = ".";
  installInputCallbacks(v);
  ImGuiSession imgui(v.window->handle());
  v.overlay = !o.noPanel;
  // Framed again for the view beside the panel once the panel has its width (startScene
  // framed it for the window's whole size).
  bool framePending = !o.camera && o.cameraFromFile <= 0;

  GLFWwindow* w = v.window->handle();
  std::optional<OffscreenTarget> scene;  // what the views draw into, the window's size
  glm::ivec2 sceneSize(0);
  auto last = std::chrono::steady_clock::now();
  const auto start = last;
  for (int frame = 0; !glfwWindowShouldClose(w) && !v.quit; ++frame) {
    glfwPollEvents();
    imgui.newFrame();
    if (v.overlay) drawOverlay(v);
    drawMessageBar(v);
    drawHelpOverlay(v);
    drawExportDialog(v);  // before the file dialogs, which end every dialog's first frame
    drawFileDialogs(v);
    imgui.endFrame();
    if (v.exportJob) {
      // The export's frames in place of the scene's: the window shows its progress.
      stepExport(v);
      const glm::ivec2 size = v.window->framebufferSize();
      bindWindowFramebuffer();
      clearRightOf(0, size.x, size.y);
      imgui.draw();
      glfwSwapBuffers(w);
      last = std::chrono::steady_clock::now();
      continue;
    }
    // The style menu's next picture, by a renderer of its own, before the scene's frame.
    if (Status st = v.styleThumbnails.drawStep(v.state); !st) v.state.note(st.error());
    if (framePending) {
      framePending = false;
      v.state.viewAspect = v.aspect();
      v.state.frameScene(o.animation.orbitDegrees != 0.0f);
    }

    const glm::ivec2 fb = v.window->framebufferSize();
    const glm::ivec4 sceneView = v.sceneViewport();
    v.state.poseScene(*v.renderer);
    const CameraMatrices cam = v.state.view(v.aspect());
    // Where this frame's passes share the framebuffer's depth and stencil (the stencil path's
    // masks writing its per-pixel buffers as they mark, the turn resolve), which the window's
    // own cannot (they would draw the mesh once more for each buffer), the scene is drawn in a
    // framebuffer of ours and copied into the window; elsewhere straight into the window, as
    // the copy costs a frame a few milliseconds. The renderer says so before the frame.
    const glm::ivec4 chosenView = v.state.splitView ? glm::ivec4(sceneView.z / 2, 0, sceneView.z - sceneView.z / 2, fb.y) : sceneView;
    const bool offscreen = v.renderer->sharesFramebufferDepth(cam, v.state.settings, chosenView);
    if (!offscreen) {
      scene.reset();
      sceneSize = glm::ivec2(0);
    } else if (fb.x > 0 && fb.y > 0 && fb != sceneSize) {
      sceneSize = fb;
      Result<OffscreenTarget> target = OffscreenTarget::create(fb.x, fb.y);
      scene.reset();
      if (target) scene = std::move(*target);
      else v.state.note("drawing straight into the window: " + target.error());
    }
    if (scene) scene->bind();
    else bindWindowFramebuffer();
    if (Status st = v.state.applyLight(*v.renderer, cam); !st) v.state.note("light not moved: " + st.error());
    const glm::vec3 lightWorld = v.state.lightWorldPosition(cam);
    // The scene left of the docked panel, which is drawn over a cleared strip.
    clearRightOf(sceneView.z, fb.x, fb.y);
    const Status drawn = drawViews(v, cam, sceneView.z, sceneView.w, [&](const glm::ivec4& viewport) {
      return v.renderer->drawMarker(cam, lightWorld, {1.0f, 0.85f, 0.2f}, 14.0f, viewport);
    });
    if (!drawn) v.state.note(drawn.error());
    if (scene) scene->copyToWindow();
    // F12: the scene alone at the window's size, drawn again without the panel's strip.
    if (v.screenshotRequested == 0) {
      v.screenshotRequested = -1;
      writeSceneScreenshot(v, fb, nextFreeName(v.screenshotDir, "npr-screenshot", ".png"));
    }
    // Vector export of what this frame shows (the lines of the full view, even when split).
    const bool lastFrame = o.frames > 0 && frame + 1 >= o.frames;
    if (v.svgRequested || (lastFrame && !o.svg.empty())) {
      const std::filesystem::path file =
          v.svgRequested ? nextFreeName(v.screenshotDir, "npr-lines", ".svg") : std::filesystem::path(o.svg);
      v.svgRequested = false;
      const Status st = exportSvg(*v.renderer, cam, v.state.settings, {sceneView.z, sceneView.w}, SvgContents{nullptr, o.svgFill, v.state.palette.get()},
                                  file.string());
      if (st) v.state.note("lines written to " + file.string());
      else v.state.problem("lines not written: " + st.error());
      bindWindowFramebuffer();
    }
    // The frames written are the scene alone, without the overlay.
    if (!o.saveFrames.empty()) {
      const Status st = writeImage(frameFileName(o.saveFrames, frame), readFramebufferRGBA8(0, 0, sceneView.z, sceneView.w));
      if (!st) v.state.note(st.error());
    }
    imgui.draw();

    if (v.screenshotRequested == 1) {  // Shift+F12: the whole window, panel included
      v.screenshotRequested = -1;
      takeScreenshot(v, nextFreeName(v.screenshotDir, "npr-screenshot", ".png"));
    }
    if (lastFrame && !o.screenshot.empty()) takeScreenshot(v, o.screenshot);
    stepCameraAnimation(v.state.camera, o.animation, fb);
    glfwSwapBuffers(w);
    const auto now = std::chrono::steady_clock::now();
    v.state.playback.advance(std::chrono::duration<double>(now - last).count(), v.state.animationLength());
    v.timer.add(std::chrono::duration<double>(now - start).count(), std::chrono::duration<double, std::milli>(now - last).count());
    last = now;
    if (lastFrame) break;
  }
  if (const int errors = gl::checkErrors("end of viewer run")) return reportFailure(std::to_string(errors) + " OpenGL error(s) during the run");
  return 0;
}

}  // namespace npr
