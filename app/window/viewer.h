// The windowed viewer's state, shared by the frame loop, the input callbacks and the overlay,
// and the actions that keys, overlay buttons and dropped files trigger.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "app/viewer_state.h"
#include "app/window/frame_timer.h"
#include "app/window/glfw_window.h"
#include "app/window/input_map.h"
#include "renderer/renderer.h"

namespace npr {

struct Viewer {
  std::unique_ptr<GlfwWindow> window;
  std::unique_ptr<Renderer> renderer;
  ViewerState state;
  FrameTimer timer;
  bool overlay = true, help = false, vsync = true, quit = false;
  bool screenshotRequested = false;
  bool svgRequested = false;  // the overlay's "export lines (SVG)"
  int svgCount = 0;
  int styleCount = 0;  // "save style" files written
  int screenshotCount = 0;
  std::filesystem::path screenshotDir = ".";
  glm::dvec2 lastCursor{0.0};
  glm::dvec2 lastClick{0.0};   // the last left press (double-click framing)
  double lastClickTime = -1.0;
  bool dragging[3] = {false, false, false};
  bool lightDrag = false;

  // The docked panel's width in window units (0: hidden or collapsed), as the overlay last
  // drew it; the scene takes the rest of the window.
  float panelWidth = 0.0f;
  // Where the scene is drawn in the framebuffer: the window left of the panel.
  glm::ivec4 sceneViewport() const;
  // Of one view: half the scene in split view.
  float aspect() const;
};

void applyAction(Viewer& viewer, const KeyAction& action);
// A dropped .palette (or palette folder) or model (in place of the scene, or beside it with
// `add`); a failure keeps the current one and is noted. True when a model was loaded.
bool loadDropped(Viewer& viewer, const std::string& path, bool add);
void takeScreenshot(Viewer& viewer, const std::filesystem::path& file);

}  // namespace npr
