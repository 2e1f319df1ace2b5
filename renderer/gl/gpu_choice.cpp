// Device ranking and the --gpu request (see gpu_choice.h).
#include "renderer/gl/gpu_choice.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "renderer/core/printable.h"

namespace npr {
namespace {

std::string lowered(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::string deviceLabel(const GpuDevice& d) {
  std::string label = d.name.empty() ? "unnamed device" : d.name;
  if (!d.drmNode.empty() && d.drmNode != d.name) label += " (" + d.drmNode + ")";
  return label + (d.software ? " [software]" : " [hardware]");
}

namespace {

}  // namespace

Result<GpuRequest> parseGpuRequest(std::string_view text) {
  GpuRequest r;
  if (text.empty() || text == "auto") return r;
  if (text == "surfaceless") {
    r.kind = GpuRequest::Kind::Surfaceless;
    return r;
  }
  int index = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), index);
  if (ec == std::errc() && end == text.data() + text.size()) {
    if (index < 0) return Error{"--gpu '" + printable(text) + "': a device index is 0 or more"};
    r.kind = GpuRequest::Kind::Index;
    r.index = index;
    return r;
  }
  r.kind = GpuRequest::Kind::Name;
  r.name = std::string(text);
  return r;
}

Result<std::vector<int>> devicesToTry(const std::vector<GpuDevice>& devices, const GpuRequest& request) {
  std::vector<int> order;
  switch (request.kind) {
    case GpuRequest::Kind::Surfaceless:
      return order;
    case GpuRequest::Kind::Automatic:
      for (const GpuDevice& d : devices) order.push_back(d.index);
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const auto soft = [&](int i) {
          return std::find_if(devices.begin(), devices.end(), [&](const GpuDevice& d) { return d.index == i; })->software;
        };
        return !soft(a) && soft(b);
      });
      return order;
    case GpuRequest::Kind::Index:
      for (const GpuDevice& d : devices)
        if (d.index == request.index) return std::vector<int>{d.index};
      break;
    case GpuRequest::Kind::Name: {
      const std::string wanted = lowered(request.name);
      for (const GpuDevice& d : devices)
        if (lowered(deviceLabel(d)).find(wanted) != std::string::npos)
          order.push_back(d.index);
      if (!order.empty()) return order;
      break;
    }
  }
  const std::string asked = request.kind == GpuRequest::Kind::Index ? std::to_string(request.index)
                                                                    : "'" + printable(request.name) + "'";
  if (devices.empty())
    return Error{"--gpu " + asked + ": EGL lists no devices here (use --gpu auto or --gpu surfaceless)"};
  std::string list = describeDevices(devices);
  list.pop_back();
  return Error{"--gpu " + asked + " matches none of the EGL devices:\n" + list};
}

bool hasEglExtension(const char* list, std::string_view name) {
  if (!list || name.empty()) return false;
  const std::string_view all(list);
  for (std::size_t p = all.find(name); p != std::string_view::npos; p = all.find(name, p + 1)) {
    const std::size_t end = p + name.size();
    if ((p == 0 || all[p - 1] == ' ') && (end == all.size() || all[end] == ' ')) return true;
  }
  return false;
}

bool canEnumerateDevices(const char* clientExtensions) {
  return (hasEglExtension(clientExtensions, "EGL_EXT_device_enumeration") || hasEglExtension(clientExtensions, "EGL_EXT_device_base")) &&
         hasEglExtension(clientExtensions, "EGL_EXT_platform_device");
}

bool isSoftwareRenderer(std::string_view glRenderer) {
  const std::string r = lowered(glRenderer);
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "software rasterizer", "swiftshader", "lavapipe"})
    if (r.find(name) != std::string::npos) return true;
  return false;
}

std::string describeDevices(const std::vector<GpuDevice>& devices) {
  std::string out;
  for (const GpuDevice& d : devices) out += "  " + std::to_string(d.index) + ": " + deviceLabel(d) + "\n";
  return out;
}

}  // namespace npr
