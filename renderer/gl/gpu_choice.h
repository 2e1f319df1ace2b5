// Which EGL device a headless context opens: the request a user gives (--gpu, NPR_GPU) and the
// ranking of the devices EGL lists. Kept apart from EGL so that the choice is tested on
// made-up device lists (a GPU server's list cannot be produced on a machine without one).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "renderer/core/result.h"

namespace npr {

// One device from eglQueryDevicesEXT, as far as its extensions describe it.
struct GpuDevice {
  int index = 0;          // its place in EGL's list: what --gpu INDEX names
  std::string name;       // EGL_EXT_device_query_name's renderer, else the DRM node, else ""
  std::string drmNode;    // /dev/dri/renderD128, when the device has one
  bool software = false;  // EGL_MESA_device_software: llvmpipe and friends
};

// What the user asked for. Automatic: hardware devices before software ones, then Mesa's
// surfaceless platform. Index/Name: that device only (an error when it fails or is absent).
// Surfaceless: Mesa's surfaceless platform, the software path that needs no device list.
struct GpuRequest {
  enum class Kind { Automatic, Index, Name, Surfaceless };
  Kind kind = Kind::Automatic;
  int index = -1;
  std::string name;  // matched case-insensitively against deviceLabel (so 'hardware' and 'renderD129' work too)
};

// Parses "auto", "surfaceless", a device index or a part of a device's name.
[[nodiscard]] Result<GpuRequest> parseGpuRequest(std::string_view text);

// The devices to try, in order, for the request: every device for Automatic (hardware first,
// EGL's order kept within each kind), the one asked for otherwise; an error naming the listed
// devices when the request matches none. Surfaceless gives an empty list.
[[nodiscard]] Result<std::vector<int>> devicesToTry(const std::vector<GpuDevice>& devices, const GpuRequest& request);

// Whether `name` is one of the space-separated EGL extensions in `list` (null: none).
bool hasEglExtension(const char* list, std::string_view name);

// Whether EGL's client extensions let the devices be listed and opened: device enumeration,
// which NVIDIA's driver advertises only inside EGL_EXT_device_base (Mesa names both), and
// the device platform.
bool canEnumerateDevices(const char* clientExtensions);

// Whether a GL_RENDERER string names a software rasterizer (llvmpipe, softpipe, swrast, ...).
bool isSoftwareRenderer(std::string_view glRenderer);

// "NVIDIA H100 (/dev/dri/renderD128) [hardware]", "unnamed device (...) [software]".
std::string deviceLabel(const GpuDevice& device);

// "0: NVIDIA H100 (/dev/dri/renderD128)" lines, one per device, for messages and --gl-info.
std::string describeDevices(const std::vector<GpuDevice>& devices);

}  // namespace npr
