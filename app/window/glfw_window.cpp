// GLFW window and Dear ImGui lifetime (see glfw_window.h).
#include "app/window/glfw_window.h"

// The app makes no GL calls of its own (the renderer does): GLFW must not pull in GL headers.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace npr {

Result<std::unique_ptr<GlfwWindow>> GlfwWindow::open(const glm::ivec2& size, const std::string& title) {
  glfwSetErrorCallback([](int code, const char* msg) { std::fprintf(stderr, "GLFW error %d: %s\n", code, msg); });
  if (!glfwInit()) return Error{"cannot open a window (no display?); use --headless to render without one"};
  std::unique_ptr<GlfwWindow> w(new GlfwWindow());  // from here on, the destructor terminates GLFW
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  w->window_ = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
  if (!w->window_) return Error{"could not create an OpenGL 3.3 core window with an 8-bit stencil buffer"};
  glfwMakeContextCurrent(w->window_);
  glfwSwapInterval(1);
  return w;
}

GlfwWindow::~GlfwWindow() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

glm::ivec2 GlfwWindow::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {w, h};
}

float GlfwWindow::contentScale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  return std::isfinite(x) && x > 0.0f ? x : 1.0f;
}

glm::ivec2 GlfwWindow::windowSize() const {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  return {w, h};
}

ImGuiSession::ImGuiSession(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
  // On a high-DPI screen the overlay keeps its physical size: widgets scaled, and the font
  // rasterised at the scaled size rather than magnified (which blurs it).
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(window, &sx, &sy);
  const float scale = std::isfinite(sx) && sx > 0.0f ? std::clamp(sx, 1.0f, 4.0f) : 1.0f;
  if (scale != 1.0f) {
    ImGui::GetStyle().ScaleAllSizes(scale);
    ImFontConfig font;
    font.SizePixels = kFontPixels * scale;
    ImGui::GetIO().Fonts->AddFontDefault(&font);
  }
  ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the window's own callbacks
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiSession::newFrame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiSession::endFrame() { ImGui::Render(); }

void ImGuiSession::draw() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

}  // namespace npr
