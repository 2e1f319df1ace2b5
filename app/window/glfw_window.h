// The GLFW side of the window, owned in one place: initialisation, an OpenGL 3.3 core window
// with depth and an 8-bit stencil, its current context, and teardown in the destructor (so
// every early return cleans up). Also the Dear ImGui context and its GLFW/OpenGL3 backends.
#pragma once

#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "renderer/core/result.h"

struct GLFWwindow;

namespace npr {

class GlfwWindow {
 public:
  // Opens the window and makes its context current; fails with a message a user can act on.
  [[nodiscard]] static Result<std::unique_ptr<GlfwWindow>> open(const glm::ivec2& size, const std::string& title);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  glm::ivec2 framebufferSize() const;
  glm::ivec2 windowSize() const;
  // The monitor's content scale (1 on a standard screen, 2 on most high-DPI ones).
  float contentScale() const;

 private:
  GlfwWindow() = default;
  GLFWwindow* window_ = nullptr;
};

// Dear ImGui for a window: context plus backends, shut down in reverse order on destruction.
// Install the window's own callbacks first: the GLFW backend chains to them. The font is
// kFontPixels at content scale 1 and that times the scale above it; widgets scale with it.
class ImGuiSession {
 public:
  static constexpr float kFontPixels = 13.0f;  // Dear ImGui's default font's own size

  explicit ImGuiSession(GLFWwindow* window);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
  void newFrame();
  void endFrame();  // finishes the UI: call before drawing the scene
  void draw();      // draws the finished UI over the framebuffer
};

}  // namespace npr
