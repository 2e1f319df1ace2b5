// CPU tier: the orbit camera's maths, the key bindings and the scripted camera motion (--animate), without a window.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <vector>
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <filesystem>

#include "app/camera_animation.h"
#include "app/window/frame_timer.h"
#include "app/window/input_map.h"
#include "renderer/core/camera.h"

namespace npr {
namespace {

bool finiteMatrix(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// The larger of the points' projected extents, as a fraction of the frame (x over its width,
// y over its height), and whether every point is in front of the eye.
float screenExtent(const OrbitCamera& c, const std::vector<glm::vec3>& points, float aspect, float* outermost = nullptr) {
  const CameraMatrices m = c.matrices(aspect);
  glm::vec2 lo(1e9f), hi(-1e9f);
  float most = 0.0f;
  for (const glm::vec3& p : points) {
    const glm::vec4 clip = m.projection * m.view * glm::vec4(p, 1.0f);
    EXPECT_GT(clip.w, 0.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    lo = glm::min(lo, ndc), hi = glm::max(hi, ndc);
    most = std::max({most, std::abs(ndc.x), std::abs(ndc.y)});
  }
  if (outermost) *outermost = most;
  return std::max(hi.x - lo.x, hi.y - lo.y) / 2.0f;
}

TEST(Camera, FramingFitsALongModelsProjectedBoundsNotItsSphere) {
  // A stick four units long and a fifth thick, off the origin: framed by its bounding sphere
  // it fills under half the frame's width; framed by its points, 90% of it.
  std::vector<glm::vec3> stick;
  for (int i = 0; i <= 40; ++i)
    for (glm::vec2 yz : {glm::vec2(-0.1f, -0.1f), glm::vec2(0.1f, 0.1f)}) stick.push_back(glm::vec3(0.5f + 0.1f * float(i) - 2.0f, yz.x + 0.3f, yz.y));
  const float aspect = 16.0f / 9.0f;
  OrbitCamera sphere(0.0f, 10.0f, 3.0f);
  sphere.frame(2.05f);
  EXPECT_LT(screenExtent(sphere, stick, aspect), 0.55f);
  // (The scene's radius, 2.05, sets the near and far planes.)
  OrbitCamera c(0.0f, 10.0f, 3.0f);
  c.frame(2.05f);
  c.framePoints(stick, aspect, 0.9f);
  float outermost = 0.0f;
  EXPECT_NEAR(screenExtent(c, stick, aspect, &outermost), 0.9f, 0.02f);
  EXPECT_LE(outermost, 0.9f + 1e-4f);
  // Seen end on (yaw 90), the stick is small on screen: the frame closes in on it, the eye staying
  // outside it.
  OrbitCamera end(90.0f, 0.0f, 3.0f);
  end.frame(2.05f);
  end.framePoints(stick, aspect, 0.9f);
  EXPECT_GT(screenExtent(end, stick, aspect), 0.6f);
  // A turntable: every yaw keeps the whole stick inside the frame, and the widest fills it.
  OrbitCamera turn(0.0f, 20.0f, 3.0f);
  turn.frame(2.05f);
  turn.framePoints(stick, aspect, 0.9f, true);
  float widest = 0.0f;
  for (int k = 0; k < 24; ++k) {
    float most = 0.0f;
    widest = std::max(widest, screenExtent(turn, stick, aspect, &most));
    EXPECT_LE(most, 0.9f + 1e-4f) << "yaw " << turn.yaw();
    turn.orbit(15.0f, 0.0f);
  }
  EXPECT_GT(widest, 0.6f);
  // Nothing to frame, or a degenerate frame: nothing changes.
  const float before = c.distance();
  c.framePoints({}, aspect);
  c.framePoints(stick, 0.0f);
  EXPECT_EQ(c.distance(), before);
}

TEST(Camera, OrbitNeverFlipsAtThePoles) {
  OrbitCamera cam(0.0f, 0.0f, 3.0f);
  for (int i = 0; i < 100; ++i) cam.orbit(0.0f, 10.0f);
  EXPECT_LE(cam.pitch(), OrbitCamera::kMaxPitch);
  const CameraMatrices m = cam.matrices(1.0f);
  EXPECT_TRUE(finiteMatrix(m.view));
  // The camera's up vector still points up (no flip): view-space y of world up is positive.
  EXPECT_GT((m.view * glm::vec4(0, 1, 0, 0)).y, 0.0f);
  for (int i = 0; i < 100; ++i) cam.orbit(0.0f, -10.0f);
  EXPECT_GE(cam.pitch(), -OrbitCamera::kMaxPitch);
  EXPECT_GT((cam.matrices(1.0f).view * glm::vec4(0, 1, 0, 0)).y, 0.0f);
}

TEST(Camera, ZoomIsLimitedAndTowardTheCursor) {
  OrbitCamera cam(0.0f, 0.0f, 3.0f);
  cam.frame(1.0f);
  for (int i = 0; i < 500; ++i) cam.zoom(0.5f, {0, 0}, 1.0f);
  EXPECT_GE(cam.distance(), cam.minDistance());
  for (int i = 0; i < 500; ++i) cam.zoom(2.0f, {0, 0}, 1.0f);
  EXPECT_LE(cam.distance(), cam.maxDistance());
  cam.frame(1.0f);
  // Zooming in at the right edge moves the target to the right (toward the cursor).
  cam.zoom(0.5f, {1.0f, 0.0f}, 1.0f);
  EXPECT_GT(cam.target().x, 0.0f);
  // Degenerate factors change nothing.
  const float d = cam.distance();
  cam.zoom(std::nanf(""), {0, 0}, 1.0f);
  cam.zoom(0.0f, {0, 0}, 1.0f);
  EXPECT_EQ(cam.distance(), d);
}

TEST(Camera, FramesTinyAndHugeModels) {
  for (float r : {1e-6f, 1.0f, 1e6f}) {
    OrbitCamera cam(30.0f, 20.0f, 3.0f);
    cam.frame(r);
    const CameraMatrices m = cam.matrices(16.0f / 9.0f);
    EXPECT_TRUE(finiteMatrix(m.view) && finiteMatrix(m.projection)) << r;
    // The whole bounding sphere is in front of the near plane and within the far plane.
    const glm::vec4 centre = m.view * glm::vec4(0, 0, 0, 1);
    const glm::vec4 clipNear = m.projection * glm::vec4(0, 0, centre.z + r, 1);
    const glm::vec4 clipFar = m.projection * glm::vec4(0, 0, centre.z - r, 1);
    EXPECT_LE(clipNear.z / clipNear.w, 1.0f);
    EXPECT_GE(clipNear.z / clipNear.w, -1.0f) << r;
    EXPECT_LE(clipFar.z / clipFar.w, 1.0f) << r;
    // The sphere fits the vertical field of view.
    EXPECT_GE(cam.distance() * std::sin(glm::radians(cam.fovY() * 0.5f)), r * 0.999f);
  }
  OrbitCamera bad;
  bad.frame(std::nanf(""));
  EXPECT_TRUE(std::isfinite(bad.distance()));
}

// What chooses per-vertex or per-pixel pattern placement: a unit sphere 10 units down a 90
// degree view spans 10 pixels of a 200-pixel-high viewport's radius; orthographic views use w
// = 1; the eye inside the sphere, or a disc larger than the viewport, gives the viewport's area.
TEST(Camera, ProjectedSphereAreaIsTheDiscWithinTheViewport) {
  CameraMatrices m;
  m.view = glm::lookAt(glm::vec3(0, 0, 10), glm::vec3(0.0f), glm::vec3(0, 1, 0));
  m.projection = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
  EXPECT_NEAR(projectedSphereArea(m, 1.0f, {0, 0, 200, 200}), 3.14159265f * 100.0f, 0.05f);
  EXPECT_NEAR(projectedSphereArea(m, 1.0f, {50, 30, 300, 200}), 3.14159265f * 100.0f, 0.05f);  // the corner does not matter
  EXPECT_FLOAT_EQ(projectedSphereArea(m, 20.0f, {0, 0, 200, 200}), 40000.0f);                   // the eye inside
  EXPECT_NEAR(projectedSphereArea(m, 9.0f, {0, 0, 200, 200}), 3.14159265f * 8100.0f, 1.0f);    // a disc within
  m.projection = glm::perspective(glm::radians(30.0f), 1.0f, 0.1f, 100.0f);
  EXPECT_FLOAT_EQ(projectedSphereArea(m, 4.0f, {0, 0, 200, 200}), 40000.0f);                    // a disc past the edges
  m.projection = glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, 0.1f, 100.0f);
  EXPECT_NEAR(projectedSphereArea(m, 0.5f, {0, 0, 200, 200}), 3.14159265f * 12.5f * 12.5f, 0.05f);
  m.projection = glm::mat4(0.0f);  // degenerate: no w
  EXPECT_FLOAT_EQ(projectedSphereArea(m, 1.0f, {0, 0, 200, 100}), 20000.0f);
}

TEST(Camera, ResetReturnsHome) {
  OrbitCamera cam(30.0f, 20.0f, 3.0f);
  cam.frame(1.0f);
  const float d = cam.distance();
  cam.orbit(50.0f, 30.0f);
  cam.pan({0.3f, 0.1f}, 1.5f);
  cam.reset();
  EXPECT_FLOAT_EQ(cam.yaw(), 30.0f);
  EXPECT_FLOAT_EQ(cam.pitch(), 20.0f);
  EXPECT_FLOAT_EQ(cam.distance(), d);
  EXPECT_EQ(cam.target(), glm::vec3(0.0f));
}

TEST(InputMap, KeysMapToTheDocumentedActions) {
  EXPECT_EQ(actionForKey(GLFW_KEY_ESCAPE, 0), (KeyAction{Action::Quit}));
  EXPECT_EQ(actionForKey(GLFW_KEY_3, 0), (KeyAction{Action::SelectPalette, 2}));
  EXPECT_EQ(actionForKey(GLFW_KEY_RIGHT_BRACKET, 0), (KeyAction{Action::NextPalette}));
  EXPECT_EQ(actionForKey(GLFW_KEY_LEFT_BRACKET, 0), (KeyAction{Action::PreviousPalette}));
  EXPECT_EQ(actionForKey(GLFW_KEY_M, 0), (KeyAction{Action::CycleMatch}));
  EXPECT_EQ(actionForKey(GLFW_KEY_EQUAL, GLFW_MOD_SHIFT), (KeyAction{Action::RangeScaleUp}));
  EXPECT_EQ(actionForKey(GLFW_KEY_KP_SUBTRACT, 0), (KeyAction{Action::RangeScaleDown}));
  EXPECT_EQ(actionForKey(GLFW_KEY_P, 0), (KeyAction{Action::CyclePath}));
  EXPECT_EQ(actionForKey(GLFW_KEY_B, 0), (KeyAction{Action::ToggleSplit}));
  EXPECT_EQ(actionForKey(GLFW_KEY_F, 0), (KeyAction{Action::FrameModel}));
  EXPECT_EQ(actionForKey(GLFW_KEY_R, 0), (KeyAction{Action::ResetView}));
  EXPECT_EQ(actionForKey(GLFW_KEY_F1, 0), (KeyAction{Action::ToggleOverlay}));
  EXPECT_EQ(actionForKey(GLFW_KEY_TAB, 0), (KeyAction{Action::ToggleOverlay}));
  EXPECT_EQ(actionForKey(GLFW_KEY_F12, 0), (KeyAction{Action::Screenshot}));
  EXPECT_EQ(actionForKey(GLFW_KEY_W, 0), (KeyAction{Action::MoveLight, 3}));  // +y
  EXPECT_EQ(actionForKey(GLFW_KEY_A, 0), (KeyAction{Action::MoveLight, 0}));  // -x
  EXPECT_EQ(actionForKey(GLFW_KEY_E, 0), (KeyAction{Action::MoveLight, 5}));  // +z
  EXPECT_FALSE(actionForKey(GLFW_KEY_Z, 0));
  EXPECT_GE(keyBindings().size(), 15u);
}

TEST(FrameTimer, MeanAndWorstOverTheLastSecond) {
  FrameTimer t;
  for (int i = 0; i < 99; ++i) t.add(10.0 + i * 0.01, 10.0);
  t.add(10.995, 50.0);
  EXPECT_NEAR(t.meanMs(), (99 * 10.0 + 50.0) / 100.0, 1e-9);
  EXPECT_DOUBLE_EQ(t.worst1PercentMs(), 50.0);
  t.add(20.0, 5.0);  // older samples leave the window
  EXPECT_DOUBLE_EQ(t.meanMs(), 5.0);
}

}  // namespace
}  // namespace npr

namespace npr {
namespace {

TEST(CameraAnimation, ParsesEachMotionAndRefusesBadSpecs) {
  auto a = parseCameraAnimation("orbit:1.5,pan:3,-2,zoom:1.01");
  ASSERT_TRUE(a) << a.error();
  EXPECT_EQ(a->orbitDegrees, 1.5f);
  EXPECT_EQ(a->panPixels, glm::vec2(3.0f, -2.0f));
  EXPECT_EQ(a->zoom, 1.01f);
  EXPECT_TRUE(a->active());
  auto p = parseCameraAnimation("pan:-4,0");
  ASSERT_TRUE(p) << p.error();
  EXPECT_EQ(p->panPixels, glm::vec2(-4.0f, 0.0f));
  for (const char* bad : {"", "orbit", "orbit:x", "orbit:nan", "orbit:100", "pan:3", "pan:1,2,3", "zoom:0", "zoom:3",
                          "orbit:1,orbit:2", "spin:1"})
    EXPECT_FALSE(parseCameraAnimation(bad)) << bad;
}

// The model's centre, projected, moves by exactly the pan's pixels each frame; orbit turns the
// yaw; zoom magnifies by the factor.
TEST(CameraAnimation, StepsMoveTheCameraByTheScript) {
  const glm::ivec2 size(400, 300);
  auto centreOnScreen = [&](const OrbitCamera& c) {
    const CameraMatrices m = c.matrices(float(size.x) / float(size.y));
    const glm::vec4 p = m.projection * m.view * glm::vec4(0, 0, 0, 1);
    return glm::vec2((p.x / p.w + 1.0f) * 0.5f * float(size.x), (1.0f - p.y / p.w) * 0.5f * float(size.y));  // y down
  };
  OrbitCamera cam(30.0f, 20.0f, 3.0f);
  cam.frame(1.0f);
  const glm::vec2 before = centreOnScreen(cam);
  const CameraAnimation pan = *parseCameraAnimation("pan:5,-3");
  for (int i = 0; i < 4; ++i) stepCameraAnimation(cam, pan, size);
  const glm::vec2 moved = centreOnScreen(cam) - before;
  EXPECT_NEAR(moved.x, 20.0f, 0.05f);
  EXPECT_NEAR(moved.y, -12.0f, 0.05f);

  OrbitCamera orbit(30.0f, 20.0f, 3.0f);
  stepCameraAnimation(orbit, *parseCameraAnimation("orbit:2"), size);
  EXPECT_NEAR(orbit.yaw(), 32.0f, 1e-4f);
  const float d = orbit.distance();
  stepCameraAnimation(orbit, *parseCameraAnimation("zoom:1.25"), size);
  EXPECT_NEAR(orbit.distance(), d / 1.25f, 1e-4f);
  EXPECT_EQ(frameFileName("out", 7), (std::filesystem::path("out") / "frame-0007.png").string());
}

}  // namespace
}  // namespace npr
