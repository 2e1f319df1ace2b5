// Mouse, keyboard and drop callbacks of the window (see input_callbacks.h).
#include "app/window/input_callbacks.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/window/export_dialog.h"

namespace npr {
namespace {

Viewer* viewerOf(GLFWwindow* w) { return static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }

void onKey(GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
  if (action == GLFW_RELEASE) return;
  // While an export runs the view and the look stay as it took them: Esc cancels it, nothing
  // else acts.
  if (viewerOf(w)->exportJob) {
    if (key == GLFW_KEY_ESCAPE) cancelExport(*viewerOf(w));
    return;
  }
  // Esc in a file dialog closes the dialog, not the viewer; Enter confirms it.
  if (viewerOf(w)->dialog != Viewer::Dialog::None) {
    if (key == GLFW_KEY_ESCAPE) {
      viewerOf(w)->dialog = Viewer::Dialog::None;
      return;
    }
    if (key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) viewerOf(w)->dialogEnter = true;
  }
  const auto a = actionForKey(key, mods);
  if (!a) return;
  // While an overlay widget has the keyboard (a slider being typed into) keys go to it, except
  // F1, Esc and F12: otherwise the overlay could not be hidden, nor the viewer closed, until the
  // user clicked elsewhere (found by the soak test).
  const bool always = key == GLFW_KEY_F1 || key == GLFW_KEY_ESCAPE || key == GLFW_KEY_F12;
  if (ImGui::GetIO().WantCaptureKeyboard && !always) return;
  // Only light movement repeats while a key is held; toggles fire once per press.
  if (action == GLFW_REPEAT && a->action != Action::MoveLight) return;
  applyAction(*viewerOf(w), *a);
}

// The cursor in the scene view's normalised device coordinates (left of the docked panel; in
// split view, within the half it is over).
glm::vec2 cursorNdc(const Viewer& v, double x, double y) {
  const glm::ivec2 ws = v.window->windowSize();
  const double sceneWidth = std::max(1.0, double(ws.x) - (v.overlay ? double(v.panelWidth) : 0.0));
  glm::vec2 ndc(float(x / sceneWidth) * 2.0f - 1.0f, 1.0f - float(y / std::max(1, ws.y)) * 2.0f);
  if (v.state.splitView) ndc.x = ndc.x < 0.0f ? ndc.x * 2.0f + 1.0f : ndc.x * 2.0f - 1.0f;
  return ndc;
}

// Double-click: frames the object under the cursor (the whole scene where there is none).
void frameObjectAt(Viewer& v, double x, double y) {
  ViewerState& s = v.state;
  const std::optional<std::size_t> hit = s.scene.pick(s.view(v.aspect()), cursorNdc(v, x, y));
  s.fileCamera.reset();
  if (hit) {
    const glm::vec4 sphere = s.scene.sphere(*hit);
    s.camera.frameSphere(glm::vec3(sphere), sphere.w);
    s.note("framed " + s.scene.objects()[*hit].name + " (F frames the scene)");
  } else {
    s.camera.frame(1.0f);
  }
  v.renderer->resetPattern();
}

void onMouseButton(GLFWwindow* w, int button, int action, int mods) {
  Viewer& v = *viewerOf(w);
  if (action == GLFW_PRESS && ImGui::GetIO().WantCaptureMouse) return;
  if (button < 0 || button > 2) return;
  v.dragging[button] = action == GLFW_PRESS;
  if (button == GLFW_MOUSE_BUTTON_LEFT) v.lightDrag = action == GLFW_PRESS && (mods & GLFW_MOD_CONTROL);
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS && !(mods & GLFW_MOD_CONTROL)) {
    // Two presses within 0.35 s a few pixels apart (GLFW reports no double-clicks).
    const double now = glfwGetTime();
    if (now - v.lastClickTime < 0.35 && glm::length(glm::dvec2(x, y) - v.lastClick) < 5.0) {
      frameObjectAt(v, x, y);
      v.lastClickTime = -1.0;
    } else {
      v.lastClickTime = now;
      v.lastClick = {x, y};
    }
  }
  v.lastCursor = {x, y};
}

void onCursor(GLFWwindow* w, double x, double y) {
  Viewer& v = *viewerOf(w);
  const glm::dvec2 d = glm::dvec2(x, y) - v.lastCursor;
  v.lastCursor = {x, y};
  const glm::ivec2 ws = v.window->windowSize();
  if (ws.x <= 0 || ws.y <= 0) return;
  ViewerState& s = v.state;
  if (v.dragging[GLFW_MOUSE_BUTTON_LEFT] && v.lightDrag) {
    const CameraMatrices cam = s.camera.matrices(v.aspect());
    const glm::mat3 camToWorld = glm::transpose(glm::mat3(cam.view));
    const float scale = 2.0f * s.camera.distance() * std::tan(glm::radians(s.camera.fovY()) * 0.5f) / float(ws.y);
    const glm::vec3 delta(float(d.x) * scale, -float(d.y) * scale, 0.0f);
    s.light += s.lightFollowsCamera ? delta : camToWorld * delta;
  } else if (v.dragging[GLFW_MOUSE_BUTTON_LEFT]) {
    s.fileCamera.reset();  // moving the view leaves the file's camera for the orbit camera
    s.camera.orbit(-float(d.x) * 0.4f, float(d.y) * 0.4f);
  } else if (v.dragging[GLFW_MOUSE_BUTTON_RIGHT] || v.dragging[GLFW_MOUSE_BUTTON_MIDDLE]) {
    s.fileCamera.reset();
    s.camera.pan(glm::vec2(float(d.x) * 2.0f / float(ws.y) , -float(d.y) * 2.0f / float(ws.y)) * glm::vec2(1.0f / v.aspect(), 1.0f), v.aspect());
  }
}

void onScroll(GLFWwindow* w, double /*dx*/, double dy) {
  if (ImGui::GetIO().WantCaptureMouse) return;
  Viewer& v = *viewerOf(w);
  const glm::ivec2 ws = v.window->windowSize();
  if (ws.x <= 0 || ws.y <= 0) return;
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  const glm::vec2 ndc = cursorNdc(v, x, y);
  v.state.fileCamera.reset();
  v.state.camera.zoom(std::pow(0.88f, float(dy)), ndc, v.aspect());
}

// Models dropped together make one scene; with Shift held they join the scene shown.
void onDrop(GLFWwindow* w, int count, const char** paths) {
  const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  bool replaced = false;
  for (int i = 0; i < count; ++i) replaced = openFile(*viewerOf(w), paths[i], shift || replaced) || replaced;
}

}  // namespace

void installInputCallbacks(Viewer& v) {
  GLFWwindow* w = v.window->handle();
  glfwSetWindowUserPointer(w, &v);
  glfwSetKeyCallback(w, onKey);
  glfwSetMouseButtonCallback(w, onMouseButton);
  glfwSetCursorPosCallback(w, onCursor);
  glfwSetScrollCallback(w, onScroll);
  glfwSetDropCallback(w, onDrop);
}

}  // namespace npr
