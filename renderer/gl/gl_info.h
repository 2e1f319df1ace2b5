// What an OpenGL context runs on (GL_VENDOR, GL_RENDERER, GL_VERSION and, headless, the EGL
// device): for --gl-info, the benchmark's report and the window's panel.
#pragma once

#include <string>
#include <vector>

#include "renderer/gl/gpu_choice.h"

namespace npr {

struct GlInfo {
  std::string vendor, renderer, version;
  std::string device;              // "EGL device 0: ...", "Mesa surfaceless platform", or "" (a window's)
  std::vector<GpuDevice> devices;  // every device EGL listed (headless only)
  bool software = false;           // GL_RENDERER is a software rasterizer
  // A software rasterizer renders although EGL listed a hardware device: worth a warning.
  bool softwareWhileHardwareExists() const;
  std::string line() const;  // "GL_VENDOR ...; GL_RENDERER ...; GL_VERSION ...[; via ...]"
};

// The current context's strings (the device fields left empty).
GlInfo currentGlInfo();

}  // namespace npr
