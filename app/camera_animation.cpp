// Scripted camera motion (see camera_animation.h).
#include "app/camera_animation.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace npr {
namespace {

bool number(const std::string& s, float& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtof(s.c_str(), &end);
  return *end == '\0' && std::isfinite(out);
}

}  // namespace

Result<CameraAnimation> parseCameraAnimation(const std::string& spec) {
  CameraAnimation a;
  const std::string usage = "use orbit:DEGREES, pan:DX,DY or zoom:FACTOR, comma-separated";
  // Split on commas, then re-join pan's second number (pan:DX,DY) to its first.
  std::vector<std::string> parts;
  std::stringstream ss(spec);
  for (std::string p; std::getline(ss, p, ',');) {
    if (!parts.empty() && parts.back().rfind("pan:", 0) == 0 && parts.back().find(',') == std::string::npos && p.find(':') == std::string::npos)
      parts.back() += "," + p;
    else
      parts.push_back(p);
  }
  if (parts.empty()) return Error{"--animate is empty: " + usage};
  bool orbit = false, pan = false, zoom = false;
  for (const std::string& p : parts) {
    const std::size_t colon = p.find(':');
    const std::string kind = p.substr(0, colon), value = colon == std::string::npos ? "" : p.substr(colon + 1);
    if (kind == "orbit" && !orbit) {
      orbit = true;
      if (!number(value, a.orbitDegrees) || std::fabs(a.orbitDegrees) > 90.0f)
        return Error{"--animate orbit:DEGREES needs a number of degrees per frame in [-90, 90], got '" + value + "'"};
    } else if (kind == "pan" && !pan) {
      pan = true;
      const std::size_t comma = value.find(',');
      if (comma == std::string::npos || !number(value.substr(0, comma), a.panPixels.x) || !number(value.substr(comma + 1), a.panPixels.y))
        return Error{"--animate pan:DX,DY needs two numbers of pixels per frame, got '" + value + "'"};
    } else if (kind == "zoom" && !zoom) {
      zoom = true;
      if (!number(value, a.zoom) || !(a.zoom > 0.5f && a.zoom < 2.0f))
        return Error{"--animate zoom:FACTOR needs a factor per frame in (0.5, 2), got '" + value + "'"};
    } else {
      return Error{"--animate: '" + p + "' is not understood (or given twice): " + usage};
    }
  }
  return a;
}

std::string frameFileName(const std::string& dir, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%04d.png", index);
  return (std::filesystem::path(dir) / name).string();
}

void stepCameraAnimation(OrbitCamera& camera, const CameraAnimation& a, const glm::ivec2& size) {
  if (size.x < 1 || size.y < 1) return;
  const float aspect = float(size.x) / float(size.y);
  if (a.orbitDegrees != 0.0f) camera.orbit(a.orbitDegrees, 0.0f);
  if (a.panPixels != glm::vec2(0.0f)) camera.pan(glm::vec2(2.0f * a.panPixels.x / float(size.x), -2.0f * a.panPixels.y / float(size.y)), aspect);
  if (a.zoom != 1.0f) camera.zoom(1.0f / a.zoom, glm::vec2(0.0f), aspect);
}

}  // namespace npr
