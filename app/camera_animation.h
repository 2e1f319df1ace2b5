// Scripted camera motion for --animate, in headless runs and in the window: a yaw per frame
// (orbit), a pan in pixels per frame at the model's centre depth, a zoom factor per frame,
// combinable ("orbit:1,zoom:1.01"). Turntables, motion tests and the benchmark use it.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "renderer/core/camera.h"
#include "renderer/core/result.h"

namespace npr {

struct CameraAnimation {
  float orbitDegrees = 0.0f;  // yaw added per frame
  glm::vec2 panPixels{0.0f};  // image pixels per frame, x right, y down (the model moves so)
  float zoom = 1.0f;          // magnification per frame (> 1 closer)
  bool active() const { return orbitDegrees != 0.0f || panPixels != glm::vec2(0.0f) || zoom != 1.0f; }
};

// "orbit:DEGREES", "pan:DX,DY", "zoom:FACTOR", comma-separated; each at most once. Refuses
// non-finite values, a zoom outside (0.5, 2) per frame and an orbit beyond 90 degrees per frame.
[[nodiscard]] Result<CameraAnimation> parseCameraAnimation(const std::string& spec);

// DIR/frame-0000.png: the name of frame `index` for --save-frames.
std::string frameFileName(const std::string& dir, int index);

// Moves the camera by one frame of `a` for a viewport of `size` pixels.
void stepCameraAnimation(OrbitCamera& camera, const CameraAnimation& a, const glm::ivec2& size);

}  // namespace npr
