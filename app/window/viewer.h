// The windowed viewer's state, shared by the frame loop, the input callbacks and the overlay,
// and the actions that keys, overlay buttons and dropped files trigger.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/viewer_state.h"
#include "app/window/frame_timer.h"
#include "app/window/glfw_window.h"
#include "app/window/export_job.h"
#include "app/window/input_map.h"
#include "app/window/style_thumbnails.h"
#include "renderer/renderer.h"

namespace npr {

struct Viewer {
  std::unique_ptr<GlfwWindow> window;
  std::unique_ptr<Renderer> renderer;
  ViewerState state;
  FrameTimer timer;
  bool overlay = true, help = false, vsync = true, quit = false;
  int screenshotRequested = -1;  // the Screenshot action's param this frame; -1: none
  // The file dialogs (file_dialogs.h): which is open, and what it was opened for.
  enum class Dialog { None, Open, SaveStyle, Export } dialog = Dialog::None;
  // The export running (Ctrl+E), a share of each frame's time; the scene waits for it.
  std::unique_ptr<ExportJob> exportJob;
  bool dialogAdds = false;           // the open dialog adds to the scene
  bool dialogJustOpened = false;     // give its path field the keyboard on its first frame
  // Enter pressed while a dialog is open, seen by our key callback: Dear ImGui 1.86 polls keys
  // once a frame and misses a press and release within one (xdotool's, a fast typist's).
  bool dialogEnter = false;
  std::vector<std::string> recent;   // files opened, newest first (the open dialog lists them)
  bool svgRequested = false;  // the overlay's "export lines (SVG)"
  StyleThumbnails styleThumbnails;  // the style menu's pictures
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
// A dropped or opened file by its kind: a .style is applied, a .palette (or palette folder)
// loaded, anything else loaded as a model (in place of the scene, or beside it with `add`). A
// failure keeps what was shown and is said in the message bar. True when a model was loaded.
bool openFile(Viewer& viewer, const std::string& path, bool add);
void takeScreenshot(Viewer& viewer, const std::filesystem::path& file);

}  // namespace npr
