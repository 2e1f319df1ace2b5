// The windowed viewer. Reads top to bottom as the frame loop in runWindowViewer(): poll
// input, start the overlay frame, render the scene (or the split view), draw the light
// marker and the overlay, swap.
//
// [SECTION] Viewer: state shared by the callbacks
// [SECTION] Actions: what keys, overlay buttons and drops do
// [SECTION] Input callbacks
// [SECTION] Overlay
// [SECTION] Frame loop
#include "app/window_viewer.h"

// The app makes no GL calls of its own (the renderer does): GLFW must not pull in GL headers.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/frame_timer.h"
#include "app/input_map.h"
#include "app/startup.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"

namespace npr {
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------
// [SECTION] Viewer
namespace {

struct Viewer {
  GLFWwindow* window = nullptr;
  std::unique_ptr<Renderer> renderer;
  ViewerState state;
  FrameTimer timer;
  bool overlay = true, help = false, vsync = true, quit = false;
  bool screenshotRequested = false;
  int screenshotCount = 0;
  fs::path screenshotDir = ".";
  glm::dvec2 lastCursor{0.0};
  bool dragging[3] = {false, false, false};
  bool lightDrag = false;

  glm::ivec2 framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    return {w, h};
  }
  glm::ivec2 windowSize() const {
    int w = 0, h = 0;
    glfwGetWindowSize(window, &w, &h);
    return {w, h};
  }
  float aspect() const {
    const glm::ivec2 s = framebufferSize();
    const float a = s.y > 0 ? float(s.x) / float(s.y) : 1.0f;
    return state.splitView ? a * 0.5f : a;
  }
};

Viewer* viewerOf(GLFWwindow* w) { return static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

bool isPaletteFile(const std::string& path) {
  std::error_code ec;
  return fs::path(path).extension() == ".palette" || fs::is_directory(path, ec);
}

// ---------------------------------------------------------------------------------------
// [SECTION] Actions

void apply(Viewer& v, const KeyAction& a) {
  ViewerState& s = v.state;
  Renderer& r = *v.renderer;
  const int paletteCount = static_cast<int>(s.palettes.size());
  switch (a.action) {
    case Action::Quit: v.quit = true; break;
    case Action::ToggleOverlay: v.overlay = !v.overlay; break;
    case Action::ToggleHelp: v.help = !v.help; v.overlay = v.overlay || v.help; break;
    case Action::Screenshot: v.screenshotRequested = true; break;
    case Action::SelectPalette: (void)s.selectPalette(a.param, r); break;
    case Action::NextPalette: if (paletteCount) (void)s.selectPalette((s.paletteIndex + 1) % paletteCount, r); break;
    case Action::PreviousPalette: if (paletteCount) (void)s.selectPalette((s.paletteIndex + paletteCount - 1) % paletteCount, r); break;
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
    case Action::ToggleSplit: s.splitView = !s.splitView; break;
    case Action::FrameModel: s.camera.frame(s.mesh ? s.mesh->radius : 1.0f); break;
    case Action::ResetView: s.camera.reset(); break;
    case Action::ToggleLightFollow: {
      // Keep the light where it is on screen when switching: convert its position.
      const CameraMatrices cam = s.camera.matrices(v.aspect());
      const glm::vec3 world = s.lightWorldPosition(cam);
      s.lightFollowsCamera = !s.lightFollowsCamera;
      s.light = s.lightFollowsCamera ? glm::vec3(cam.view * glm::vec4(world, 1.0f)) : world;
      break;
    }
    case Action::ToggleVsync: v.vsync = !v.vsync; glfwSwapInterval(v.vsync ? 1 : 0); break;
    case Action::MoveLight: {
      const float step = 0.1f * (s.mesh ? s.mesh->radius : 1.0f);
      s.light[a.param / 2] += (a.param % 2) ? step : -step;
      break;
    }
  }
}

void loadDropped(Viewer& v, const std::string& path) {
  const Status st = isPaletteFile(path) ? v.state.loadPalette(path, *v.renderer) : v.state.loadModel(path, *v.renderer);
  if (st) v.state.note("loaded " + path);
}

// ---------------------------------------------------------------------------------------
// [SECTION] Input callbacks

void onKey(GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (action == GLFW_RELEASE) return;
  const auto a = actionForKey(key, mods);
  if (!a) return;
  // Only light movement repeats while a key is held; toggles fire once per press.
  if (action == GLFW_REPEAT && a->action != Action::MoveLight) return;
  apply(*viewerOf(w), *a);
}

void onMouseButton(GLFWwindow* w, int button, int action, int mods) {
  Viewer& v = *viewerOf(w);
  if (action == GLFW_PRESS && ImGui::GetIO().WantCaptureMouse) return;
  if (button < 0 || button > 2) return;
  v.dragging[button] = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) v.lightDrag = action == GLFW_PRESS && (mods & GLFW_MOD_CONTROL);
  glfwGetCursorPos(w, &v.lastCursor.x, &v.lastCursor.y);
}

void onCursor(GLFWwindow* w, double x, double y) {
  Viewer& v = *viewerOf(w);
  const glm::dvec2 d = glm::dvec2(x, y) - v.lastCursor;
  v.lastCursor = {x, y};
  const glm::ivec2 ws = v.windowSize();
  if (ws.x <= 0 || ws.y <= 0) return;
  ViewerState& s = v.state;
  if (v.dragging[GLFW_MOUSE_BUTTON_LEFT] && v.lightDrag) {
    const CameraMatrices cam = s.camera.matrices(v.aspect());
    const glm::mat3 camToWorld = glm::transpose(glm::mat3(cam.view));
    const float scale = 2.0f * s.camera.distance() * std::tan(glm::radians(s.camera.fovY()) * 0.5f) / float(ws.y);
    const glm::vec3 delta(float(d.x) * scale, -float(d.y) * scale, 0.0f);
    s.light += s.lightFollowsCamera ? delta : camToWorld * delta;
  } else if (v.dragging[GLFW_MOUSE_BUTTON_LEFT]) {
    s.camera.orbit(-float(d.x) * 0.4f, float(d.y) * 0.4f);
  } else if (v.dragging[GLFW_MOUSE_BUTTON_RIGHT] || v.dragging[GLFW_MOUSE_BUTTON_MIDDLE]) {
    s.camera.pan(glm::vec2(float(d.x) * 2.0f / float(ws.y) , -float(d.y) * 2.0f / float(ws.y)) * glm::vec2(1.0f / v.aspect(), 1.0f), v.aspect());
  }
}

void onScroll(GLFWwindow* w, double /*dx*/, double dy) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  Viewer& v = *viewerOf(w);
  const glm::ivec2 ws = v.windowSize();
  if (ws.x <= 0 || ws.y <= 0) return;
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  glm::vec2 ndc(float(x / ws.x) * 2.0f - 1.0f, 1.0f - float(y / ws.y) * 2.0f);
  if (v.state.splitView) ndc.x = ndc.x < 0.0f ? ndc.x * 2.0f + 1.0f : ndc.x * 2.0f - 1.0f;
  v.state.camera.zoom(std::pow(0.88f, float(dy)), ndc, v.aspect());
}

void onDrop(GLFWwindow* w, int count, const char** paths) {
  for (int i = 0; i < count; ++i) loadDropped(*viewerOf(w), paths[i]);
}

// ---------------------------------------------------------------------------------------
// [SECTION] Overlay

void drawOverlay(Viewer& v) {
  ViewerState& s = v.state;
  const FrameStats& st = v.renderer->stats();
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("npr-viewer (F1)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%.2f ms mean, %.2f ms 1%% worst, %.0f fps", v.timer.meanMs(), v.timer.worst1PercentMs(), v.timer.fps());
  const auto& h = v.timer.history();
  if (!h.empty()) ImGui::PlotLines("##frametimes", h.data(), int(h.size()), 0, "frame ms", 0.0f, 50.0f, ImVec2(300, 50));
  ImGui::Text("CPU: shading %.2f ms, frame %.2f ms   GPU: %s", st.cpuShadingMs, st.cpuFrameMs,
              st.gpuMs >= 0 ? (std::to_string(st.gpuMs).substr(0, 5) + " ms").c_str() : "n/a");
  ImGui::Text("%zu triangles, %d non-empty buckets", s.mesh ? s.mesh->triangleCount() : 0, st.nonEmptyBuckets);
  ImGui::Text("recomputes %d, uploads %d, shader builds %d", st.lightingRecomputes, st.bufferUploads, st.shaderBuilds);
  if (st.lines) ImGui::Text("%d lines, silhouettes %.2f ms", st.lines, st.cpuLinesMs);
  ImGui::Separator();
  ImGui::Text("model: %s", s.mesh ? fs::path(s.mesh->report.file).filename().c_str() : "-");
  // Palette list: the number keys and [ ] choose among these.
  const std::string current = s.palette ? s.palette->name : "-";
  if (ImGui::BeginCombo("palette", current.c_str())) {
    for (int i = 0; i < static_cast<int>(s.palettes.size()); ++i) {
      const std::string label = std::to_string(i + 1) + ": " + fs::path(s.palettes[static_cast<size_t>(i)]).stem().string();
      if (ImGui::Selectable(label.c_str(), i == s.paletteIndex)) apply(v, {Action::SelectPalette, i});
    }
    ImGui::EndCombo();
  }
  int mode = static_cast<int>(s.settings.match);
  if (ImGui::Combo("match (M)", &mode, "colors\0intensity\0order\0")) {
    s.settings.match = static_cast<MatchMode>(mode);
    s.settings.bands.clear();  // thresholds live on the previous mode's query axis
  }
  ImGui::SliderFloat("range scale (+/-)", &s.settings.rangeScale, 0.05f, 20.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
  s.settings.rangeScale = std::clamp(std::isfinite(s.settings.rangeScale) ? s.settings.rangeScale : 1.0f, 0.01f, 100.0f);
  const auto& paths = userRenderPaths();
  int pathIndex = int(std::find(paths.begin(), paths.end(), s.settings.path) - paths.begin());
  if (ImGui::Combo("path (P)", &pathIndex, "stencil\0triangle\0vertex\0pixel\0smooth\0reference\0")) s.settings.path = paths[static_cast<size_t>(pathIndex)];
  if (s.settings.path == RenderPath::Stencil) {
    ImGui::Checkbox("scissor buckets", &s.settings.stencilScissor);
    ImGui::SameLine();
    ImGui::Checkbox("skip empty", &s.settings.stencilSkipEmpty);
  }
  ImGui::Checkbox("Gouraud reference", &s.settings.referenceGouraud);
  if (ImGui::CollapsingHeader("Lines and tone")) {
    LineSettings& ls = s.settings.lines;
    ImGui::Checkbox("silhouettes", &ls.silhouettes);
    ImGui::SameLine();
    ImGui::Checkbox("creases", &ls.creases);
    ImGui::SameLine();
    ImGui::Checkbox("boundaries", &ls.boundaries);
    ImGui::Checkbox("image-space edges", &ls.imageSpace);
    ImGui::SameLine();
    ImGui::Checkbox("sketchy", &ls.sketchy);
    ImGui::SameLine();
    ImGui::Checkbox("depth falloff", &ls.depthFalloff);
    ImGui::SliderFloat("crease angle", &ls.creaseAngle, 1.0f, 179.0f, "%.0f deg");
    ImGui::SliderFloat("line width", &ls.width, 0.5f, 12.0f, "%.1f px");
    ImGui::SliderFloat("edge threshold", &ls.imageThreshold, 0.05f, 2.0f, "%.2f");
    ImGui::ColorEdit3("silhouette", &ls.silhouetteColour.x, ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("crease", &ls.creaseColour.x, ImGuiColorEditFlags_NoInputs);
    ImGui::SameLine();
    ImGui::ColorEdit3("boundary", &ls.boundaryColour.x, ImGuiColorEditFlags_NoInputs);
    // Cel bands: movable thresholds between the palette's tones (2 to 8 of them).
    const PaletteMatcher* matcher = v.renderer->matcher();
    if (matcher && s.settings.match != MatchMode::Colors && matcher->levels().size() >= 2 && matcher->levels().size() <= 8) {
      bool bands = !s.settings.bands.empty();
      if (ImGui::Checkbox("cel bands (thresholds)", &bands)) {
        s.settings.bands.clear();
        const auto& L = matcher->levels();
        if (bands)
          for (size_t i = 0; i + 1 < L.size(); ++i) s.settings.bands.push_back(std::clamp(0.5f * (L[i] + L[i + 1]), 0.0f, 3.0f));
      }
      for (size_t i = 0; i < s.settings.bands.size(); ++i) {
        const float lo = i > 0 ? s.settings.bands[i - 1] + 0.01f : 0.0f;
        const float hi = i + 1 < s.settings.bands.size() ? s.settings.bands[i + 1] - 0.01f : 3.0f;
        ImGui::SliderFloat(("threshold " + std::to_string(i + 1)).c_str(), &s.settings.bands[i], lo, hi, "%.3f");
        s.settings.bands[i] = std::clamp(s.settings.bands[i], lo, hi);
      }
    }
    LightingState& lighting = v.renderer->lighting();
    int tone = static_cast<int>(lighting.toneModel());
    ToneParameters tp = lighting.toneParameters();
    bool changed = ImGui::Combo("tone", &tone, "OpenGL\0Gooch\0splashback\0");
    if (tone != 0) {
      changed |= ImGui::SliderFloat("blue", &tp.blue, 0.0f, 1.0f);
      changed |= ImGui::SliderFloat("yellow", &tp.yellow, 0.0f, 1.0f);
      changed |= ImGui::SliderFloat("alpha", &tp.alpha, 0.0f, 1.0f);
      changed |= ImGui::SliderFloat("beta", &tp.beta, 0.0f, 1.0f);
      if (tone == 2) {
        changed |= ImGui::SliderFloat("splash alpha", &tp.splashAlpha, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("splash power", &tp.splashPower, 0.0f, 16.0f);
      }
    }
    if (changed) {
      if (Status st = lighting.setToneModel(static_cast<ToneModel>(tone), tp); !st) s.note(st.error());
    }
  }
  ImGui::Checkbox("split view (B)", &s.splitView);
  ImGui::Separator();
  ImGui::DragFloat3("light", &s.light.x, 0.02f);
  if (ImGui::Checkbox("light follows camera (L)", &s.lightFollowsCamera)) {
    s.lightFollowsCamera = !s.lightFollowsCamera;  // undo, then convert through the action
    apply(v, {Action::ToggleLightFollow});
  }
  if (ImGui::Button("frame (F)")) apply(v, {Action::FrameModel});
  ImGui::SameLine();
  if (ImGui::Button("reset view (R)")) apply(v, {Action::ResetView});
  ImGui::SameLine();
  if (ImGui::Button("screenshot (F12)")) apply(v, {Action::Screenshot});
  ImGui::SameLine();
  if (ImGui::Checkbox("vsync (V)", &v.vsync)) glfwSwapInterval(v.vsync ? 1 : 0);
  ImGui::Checkbox("help (H)", &v.help);
  ImGui::SameLine();
  if (ImGui::Button("quit (Esc)")) apply(v, {Action::Quit});
  if (!s.messages.empty()) {
    ImGui::Separator();
    for (const auto& m : s.messages) ImGui::TextWrapped("%s", m.c_str());
    if (ImGui::Button("clear messages")) s.messages.clear();
  }
  if (v.help) {
    ImGui::Separator();
    for (const Binding& b : keyBindings()) ImGui::BulletText("%s: %s", b.keys, b.what);
  }
  ImGui::End();
}

void takeScreenshot(Viewer& v, const fs::path& file) {
  const glm::ivec2 fb = v.framebufferSize();
  const Status s = writeImage(file.string(), readFramebufferRGBA8(0, 0, fb.x, fb.y));
  v.state.note(s ? "screenshot written to " + file.string() : s.error());
}

}  // namespace

// ---------------------------------------------------------------------------------------
// [SECTION] Frame loop

int runWindowViewer(const Options& o) {
  glfwSetErrorCallback([](int code, const char* msg) { std::fprintf(stderr, "GLFW error %d: %s\n", code, msg); });
  if (!glfwInit()) {
    std::fprintf(stderr, "npr-viewer: cannot open a window (no display?); use --headless to render without one\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  Viewer v;
  v.window = glfwCreateWindow(o.size.x, o.size.y, "npr-viewer", nullptr, nullptr);
  if (!v.window) {
    std::fprintf(stderr, "npr-viewer: could not create an OpenGL 3.3 core window with an 8-bit stencil buffer\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(v.window);
  glfwSwapInterval(1);
  gl::installDebugOutput();
  int exitCode = 0;
  {
    auto renderer = Renderer::create();
    if (!renderer) {
      std::fprintf(stderr, "npr-viewer: %s\n", renderer.error().c_str());
      glfwDestroyWindow(v.window);
      glfwTerminate();
      return 1;
    }
    v.renderer = std::move(*renderer);
    if (Status s = startScene(o, v.state, *v.renderer); !s) {
      std::fprintf(stderr, "npr-viewer: %s\n", s.error().c_str());
      v.renderer.reset();
      glfwDestroyWindow(v.window);
      glfwTerminate();
      return 1;
    }
    if (!o.screenshot.empty()) v.screenshotDir = fs::path(o.screenshot).parent_path();
    if (v.screenshotDir.empty()) v.screenshotDir = ".";

    glfwSetWindowUserPointer(v.window, &v);
    glfwSetKeyCallback(v.window, onKey);
    glfwSetMouseButtonCallback(v.window, onMouseButton);
    glfwSetCursorPosCallback(v.window, onCursor);
    glfwSetScrollCallback(v.window, onScroll);
    glfwSetDropCallback(v.window, onDrop);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui_ImplGlfw_InitForOpenGL(v.window, true);  // chains to the callbacks above
    ImGui_ImplOpenGL3_Init("#version 330 core");

    auto last = std::chrono::steady_clock::now();
    const auto start = last;
    for (int frame = 0; !glfwWindowShouldClose(v.window) && !v.quit; ++frame) {
      glfwPollEvents();
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      if (v.overlay) drawOverlay(v);
      ImGui::Render();

      const glm::ivec2 fb = v.framebufferSize();
      bindWindowFramebuffer();
      const CameraMatrices cam = v.state.camera.matrices(v.aspect());
      v.state.applyLight(*v.renderer, cam);
      const glm::vec3 lightWorld = v.state.lightWorldPosition(cam);
      auto drawView = [&](const RenderSettings& settings, const glm::ivec4& viewport) {
        Status st = v.renderer->render(cam, settings, viewport);
        if (st) st = v.renderer->drawMarker(cam, lightWorld, {1.0f, 0.85f, 0.2f}, 14.0f, viewport);
        if (!st) v.state.note(st.error());
      };
      if (v.state.splitView) {
        // Left: the plain lit render the original showed beside its NPR images; right: the chosen path.
        const int half = fb.x / 2;
        RenderSettings ref = v.state.settings;
        ref.path = RenderPath::Reference;
        drawView(ref, {0, 0, half, fb.y});
        drawView(v.state.settings, {half, 0, fb.x - half, fb.y});
      } else {
        drawView(v.state.settings, {0, 0, fb.x, fb.y});
      }
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      const bool lastFrame = o.frames > 0 && frame + 1 >= o.frames;
      if (v.screenshotRequested) {
        v.screenshotRequested = false;
        takeScreenshot(v, v.screenshotDir / ("npr-screenshot-" + std::to_string(++v.screenshotCount) + ".png"));
      }
      if (lastFrame && !o.screenshot.empty()) takeScreenshot(v, o.screenshot);
      glfwSwapBuffers(v.window);
      const auto now = std::chrono::steady_clock::now();
      v.timer.add(std::chrono::duration<double>(now - start).count(), std::chrono::duration<double, std::milli>(now - last).count());
      last = now;
      if (lastFrame) break;
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    const int errors = gl::checkErrors("end of viewer run");
    if (errors) {
      std::fprintf(stderr, "npr-viewer: %d OpenGL error(s) during the run\n", errors);
      exitCode = 1;
    }
    v.renderer.reset();
  }
  glfwDestroyWindow(v.window);
  glfwTerminate();
  return exitCode;
}

}  // namespace npr
