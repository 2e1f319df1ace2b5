// Orbit camera maths (see camera.h).
#include "renderer/core/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace npr {

OrbitCamera::OrbitCamera(float yawDeg, float pitchDeg, float distance) {
  setYawPitchDistance(yawDeg, pitchDeg, distance);
  homeYaw_ = yaw_;
  homePitch_ = pitch_;
  homeDistance_ = distance_;
}

void OrbitCamera::setYawPitchDistance(float yawDeg, float pitchDeg, float distance) {
  yaw_ = std::isfinite(yawDeg) ? std::fmod(yawDeg, 360.0f) : 0.0f;
  pitch_ = std::isfinite(pitchDeg) ? std::clamp(pitchDeg, -kMaxPitch, kMaxPitch) : 0.0f;
  distance_ = std::isfinite(distance) ? std::clamp(distance, minDistance(), maxDistance()) : 3.0f * radius_;
}

void OrbitCamera::orbit(float dYaw, float dPitch) { setYawPitchDistance(yaw_ + dYaw, pitch_ + dPitch, distance_); }

glm::vec3 OrbitCamera::eyePosition() const {
  const float y = glm::radians(yaw_), p = glm::radians(pitch_);
  return target_ + distance_ * glm::vec3(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
}

void OrbitCamera::pan(const glm::vec2& ndcDelta, float aspect) {
  if (!std::isfinite(ndcDelta.x) || !std::isfinite(ndcDelta.y)) return;
  const CameraMatrices m = matrices(aspect);
  const glm::mat3 camToWorld = glm::transpose(glm::mat3(m.view));
  const float halfH = distance_ * std::tan(glm::radians(fovYDeg_) * 0.5f);
  target_ -= camToWorld * glm::vec3(ndcDelta.x * halfH * aspect, ndcDelta.y * halfH, 0.0f);
}

void OrbitCamera::zoom(float factor, const glm::vec2& cursorNdc, float aspect) {
  if (!(factor > 0.0f) || !std::isfinite(factor)) return;
  const float before = distance_;
  distance_ = std::clamp(distance_ * factor, minDistance(), maxDistance());
  // Keep the point under the cursor (on the target's plane) fixed: shift the target toward it
  // by the fraction of the distance removed.
  const float moved = 1.0f - distance_ / before;
  const CameraMatrices m = matrices(aspect);
  const glm::mat3 camToWorld = glm::transpose(glm::mat3(m.view));
  const float halfH = before * std::tan(glm::radians(fovYDeg_) * 0.5f);
  const glm::vec3 under = camToWorld * glm::vec3(cursorNdc.x * halfH * aspect, cursorNdc.y * halfH, 0.0f);
  if (std::isfinite(under.x) && std::isfinite(under.y) && std::isfinite(under.z)) target_ += under * moved;
}

void OrbitCamera::frame(float radius) {
  radius_ = std::isfinite(radius) && radius > 0.0f ? radius : 1.0f;
  target_ = homeTarget_ = glm::vec3(0.0f);
  // Fit the bounding sphere in the vertical field of view with a little margin.
  const float d = radius_ / std::sin(glm::radians(fovYDeg_) * 0.5f) * 1.05f;
  distance_ = std::clamp(d, minDistance(), maxDistance());
  homeDistance_ = distance_;
}

void OrbitCamera::frameSphere(const glm::vec3& centre, float radius) {
  if (!std::isfinite(centre.x + centre.y + centre.z) || !(radius > 0.0f) || !std::isfinite(radius)) return;
  target_ = centre;
  distance_ = std::clamp(radius / std::sin(glm::radians(fovYDeg_) * 0.5f) * 1.05f, minDistance(), maxDistance());
}

void OrbitCamera::framePoints(const std::vector<glm::vec3>& points, float aspect, float fill, bool everyYaw) {
  if (points.empty() || !(aspect > 0.0f) || !std::isfinite(aspect) || !(fill > 0.0f) || fill > 1.0f) return;
  const float tanY = std::tan(glm::radians(fovYDeg_) * 0.5f) * fill, tanX = tanY * aspect;
  const glm::vec3 worldUp(0.0f, 1.0f, 0.0f);
  // The eye's frame for a yaw at the current pitch: right, up and back (from the target to the eye).
  struct Basis {
    glm::vec3 right, up, back;
  };
  auto basis = [&](float yawDeg) {
    const float y = glm::radians(yawDeg), p = glm::radians(pitch_);
    Basis b;
    b.back = glm::vec3(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
    b.right = glm::normalize(glm::cross(worldUp, b.back));
    b.up = glm::cross(b.back, b.right);
    return b;
  };
  // The distance at which every point lies within the fill of the frame, seen from `target`.
  auto distanceFor = [&](const Basis& b, const glm::vec3& target) {
    float d = 0.0f, nearest = -std::numeric_limits<float>::infinity();
    for (const glm::vec3& q : points) {
      const glm::vec3 v = q - target;
      const float x = glm::dot(v, b.right), y = glm::dot(v, b.up), z = glm::dot(v, b.back);
      d = std::max(d, z + std::max(std::abs(x) / tanX, std::abs(y) / tanY));
      nearest = std::max(nearest, z);
    }
    // Never inside the model: a little beyond its nearest point.
    return std::max(d, nearest + 0.05f * radius_);
  };
  glm::vec3 target(0.0f);
  float d = 0.0f;
  if (everyYaw) {
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (const glm::vec3& q : points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    target = (lo + hi) * 0.5f;
    auto fitAll = [&] {
      float most = 0.0f;
      for (int k = 0; k < 24; ++k) most = std::max(most, distanceFor(basis(yaw_ + 15.0f * float(k)), target));
      return most;
    };
    d = fitAll();
    // The turning axis stays through the bounds' centre; its height moves to centre what every
    // yaw shows on screen (legs below a body, seen from above, sit low), then the fit again.
    for (int round = 0; round < 3 && std::isfinite(d); ++round) {
      float ylo = std::numeric_limits<float>::infinity(), yhi = -std::numeric_limits<float>::infinity();
      for (int k = 0; k < 24; ++k) {
        const Basis b = basis(yaw_ + 15.0f * float(k));
        for (const glm::vec3& q : points) {
          const glm::vec3 v = q - target;
          const float ndc = glm::dot(v, b.up) / (std::max(d - glm::dot(v, b.back), 1e-6f) * tanY);
          ylo = std::min(ylo, ndc), yhi = std::max(yhi, ndc);
        }
      }
      target.y += 0.5f * (ylo + yhi) * d * tanY / std::max(std::cos(glm::radians(pitch_)), 0.1f);
      d = fitAll();
    }
  } else {
    const Basis b = basis(yaw_);
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    for (const glm::vec3& q : points) {
      const glm::vec3 e(glm::dot(q, b.right), glm::dot(q, b.up), glm::dot(q, b.back));
      lo = glm::min(lo, e), hi = glm::max(hi, e);
    }
    const glm::vec3 c = (lo + hi) * 0.5f;
    target = b.right * c.x + b.up * c.y + b.back * c.z;
    d = distanceFor(b, target);
    // Perspective draws the near side larger: centre the projected bounds on the screen (the
    // target moved across the view by their offset at its depth), then fit again; three rounds
    // bring a long model seen obliquely within a pixel or two of centred.
    for (int round = 0; round < 3 && std::isfinite(d); ++round) {
      glm::vec2 nlo(std::numeric_limits<float>::infinity()), nhi(-std::numeric_limits<float>::infinity());
      for (const glm::vec3& q : points) {
        const glm::vec3 v = q - target;
        const float depth = std::max(d - glm::dot(v, b.back), 1e-6f);
        const glm::vec2 ndc(glm::dot(v, b.right) / (depth * tanX), glm::dot(v, b.up) / (depth * tanY));
        nlo = glm::min(nlo, ndc), nhi = glm::max(nhi, ndc);
      }
      const glm::vec2 mid = (nlo + nhi) * 0.5f;
      target += b.right * (mid.x * d * tanX) + b.up * (mid.y * d * tanY);
      d = distanceFor(b, target);
    }
  }
  if (!std::isfinite(d) || !std::isfinite(target.x + target.y + target.z)) return;
  target_ = homeTarget_ = target;
  distance_ = std::clamp(d, minDistance(), maxDistance());
  homeDistance_ = distance_;
}

void OrbitCamera::reset() {
  target_ = homeTarget_;
  setYawPitchDistance(homeYaw_, homePitch_, homeDistance_);
}

float projectedSphereArea(const CameraMatrices& camera, float radius, const glm::ivec4& viewport) {
  const float full = float(std::max(viewport.z, 0)) * float(std::max(viewport.w, 0));
  // The clip w of the centre is its distance along the view for a perspective projection and 1
  // for an orthographic one; the disc's radius in pixels is P[1][1] r / w of the half height.
  const float w = (camera.projection * camera.view * glm::vec4(0, 0, 0, 1)).w;
  if (!(w > radius) || !std::isfinite(w)) return full;
  const float r = radius * std::abs(camera.projection[1][1]) * 0.5f * float(viewport.w) / w;
  const float disc = 3.14159265f * r * r;
  return std::isfinite(disc) ? std::min(disc, full) : full;
}

bool sphereBeyondNearPlane(const CameraMatrices& camera, float radius) {
  const glm::mat4& p = camera.projection;
  // The near plane's distance: perspective P[3][2] / (P[2][2] - 1), orthographic (P[3][2] + 1) / P[2][2].
  const bool perspective = p[2][3] == -1.0f && p[3][3] == 0.0f;
  const bool orthographic = p[2][3] == 0.0f && p[3][3] == 1.0f;
  if (!perspective && !orthographic) return false;
  const float nearP = perspective ? p[3][2] / (p[2][2] - 1.0f) : (p[3][2] + 1.0f) / p[2][2];
  const float ahead = -(camera.view * glm::vec4(0, 0, 0, 1)).z;  // the centre's distance along the view
  return std::isfinite(nearP) && std::isfinite(ahead) && ahead - radius > nearP;
}

bool sphereOutsideView(const CameraMatrices& camera, float radius, glm::vec2 margin) {
  // The planes of the clip volume, -w <= x, y, z <= w, in the sphere's own space: row 3 of the
  // projection times the view, plus or minus rows 0 to 2.
  const glm::mat4 m = camera.projection * camera.view;
  const glm::vec4 w(m[0][3], m[1][3], m[2][3], m[3][3]);
  for (int axis = 0; axis < 3; ++axis) {
    const glm::vec4 row(m[0][axis], m[1][axis], m[2][axis], m[3][axis]);
    for (const float sign : {1.0f, -1.0f}) {
      const glm::vec4 plane = w * (1.0f + (axis < 2 ? margin[axis] : 0.0f)) + sign * row;  // inside where dot(plane, (p, 1)) >= 0
      const float length = glm::length(glm::vec3(plane));
      if (!(length > 0.0f) || !std::isfinite(length)) return false;
      if (plane.w / length < -radius) return true;  // the centre (the origin) lies beyond it by more than the radius
    }
  }
  return false;
}

CameraMatrices OrbitCamera::matrices(float aspect) const {
  CameraMatrices m;
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) aspect = 1.0f;
  m.view = glm::lookAt(eyePosition(), target_, glm::vec3(0, 1, 0));
  const float nearP = std::max(distance_ - 2.0f * radius_, distance_ * 1e-3f);
  const float farP = distance_ + 2.0f * radius_ + glm::length(target_);
  m.projection = glm::perspective(glm::radians(fovYDeg_), aspect, nearP, farP);
  return m;
}

}  // namespace npr
