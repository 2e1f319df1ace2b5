// The orbit camera users know from MeshLab and Blender: yaw and pitch about a target, a
// distance, panning of the target, zoom toward the cursor. Pitch stops short of the poles so
// the view never flips. Pure maths: the app maps input to these calls, tests check them.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace npr {

struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
};

// What shaders/view_distance.glsl needs to turn `projection`'s window depths into distances
// along the view axis: P[2][2], P[3][2], and 1 for perspective or 0 for orthographic.
inline glm::vec3 depthDistanceMap(const glm::mat4& projection) {
  return {projection[2][2], projection[3][2], projection[3][3] == 0.0f ? 1.0f : 0.0f};
}

class OrbitCamera {
 public:
  static constexpr float kMaxPitch = 89.5f;  // degrees: the view direction never reaches the up axis

  OrbitCamera() = default;
  OrbitCamera(float yawDeg, float pitchDeg, float distance);

  void orbit(float dYawDeg, float dPitchDeg);
  void pan(const glm::vec2& ndcDelta, float aspect);  // moves the target with the cursor
  // Zooms by `factor` (< 1 closer) toward the point under the cursor (ndc in [-1,1]^2).
  void zoom(float factor, const glm::vec2& cursorNdc, float aspect);
  // Frames a model of bounding radius `radius` centred at the origin.
  void frame(float radius);
  // Looks at a sphere of the scene (a picked object) from the current direction, filling the
  // view with it; the scene's radius (near and far planes) stays.
  void frameSphere(const glm::vec3& centre, float radius);
  // Frames `points` (the scene's vertices, or a sample of them) from the current yaw and pitch,
  // or from every yaw of a turntable (`everyYaw`: the target then stays at their bounds' centre
  // whatever the yaw): the target at the centre of their projected bounds and the distance at
  // which their larger screen extent fills `fill` of a frame of `aspect` (width / height). A
  // long model fills the frame instead of its bounding sphere's disc. Nothing changes for no
  // points or a degenerate aspect.
  void framePoints(const std::vector<glm::vec3>& points, float aspect, float fill = 0.9f, bool everyYaw = false);
  void reset();

  void setYawPitchDistance(float yawDeg, float pitchDeg, float distance);
  float yaw() const { return yaw_; }
  float pitch() const { return pitch_; }
  float distance() const { return distance_; }
  const glm::vec3& target() const { return target_; }
  glm::vec3 eyePosition() const;
  float fovY() const { return fovYDeg_; }

  // Near and far planes follow the distance and the model's radius, so depth precision is
  // spent on the model however far away it is.
  CameraMatrices matrices(float aspect) const;

  float modelRadius() const { return radius_; }
  float minDistance() const { return radius_ * 1e-3f; }
  float maxDistance() const { return radius_ * 1e3f; }

 private:
  float yaw_ = 0.0f, pitch_ = 0.0f, distance_ = 3.0f;
  glm::vec3 target_{0.0f};
  float radius_ = 1.0f;
  float fovYDeg_ = 40.0f;
  float homeYaw_ = 0.0f, homePitch_ = 0.0f, homeDistance_ = 3.0f;
  glm::vec3 homeTarget_{0.0f};
};

// Pixels of `viewport` the disc of a sphere of `radius` about the model's origin covers on
// screen (clipped to the viewport's area; the whole viewport when the eye is inside it or the
// projection is degenerate): a bound on what the model covers, for choosing per-vertex or
// per-pixel work by how many pixels a triangle spans.
float projectedSphereArea(const CameraMatrices& camera, float radius, const glm::ivec4& viewport);
// Whether the sphere of `radius` about the origin lies wholly beyond the near plane (perspective
// or orthographic projections): the eye is outside it and no clipping cuts into what it holds.
bool sphereBeyondNearPlane(const CameraMatrices& camera, float radius);
// Whether the sphere of `radius` about the origin lies wholly outside the view volume (beyond
// one of its six planes): nothing of what it holds can be drawn. `margin` widens the volume's
// sides by that share of its half-width and half-height (what is drawn past the surface, as a
// line's width, reaches in from there). Conservative: false where the matrices are degenerate.
bool sphereOutsideView(const CameraMatrices& camera, float radius, glm::vec2 margin = glm::vec2(0.0f));

}  // namespace npr
