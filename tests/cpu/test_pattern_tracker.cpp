// CPU tier: the anchored pattern's tracker (renderer/patterns/pattern_tracker.h) in a close-up.
// A camera zooming 300x into a square it faces: a few hundred points spread over the square
// leave none in view long before the end, so the tracker must draw points from what the view
// shows; the frame's scale then follows the zoom exactly (a facing plane moves as a
// similarity) and the point under the cursor stays where it is.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/core/camera.h"
#include "renderer/patterns/pattern_tracker.h"
#include "support/test_util.h"

namespace npr {
namespace {

TEST(PatternTracker, FollowsAZoomIntoACloseUp) {
  const Mesh square = test::square();
  PatternTracker tracker;
  tracker.setMesh(&square);
  const float aspect = 4.0f / 3.0f;
  const glm::ivec4 viewport(0, 0, 640, 480);
  OrbitCamera cam(0.0f, 0.0f, 3.0f);
  cam.frame(1.4f);
  const glm::vec2 cursorNdc(0.3f, 0.2f);
  const glm::vec2 cursorPx = (cursorNdc * 0.5f + 0.5f) * glm::vec2(viewport.z, viewport.w);
  double zoom = 1.0;
  int resampled = 0, fewest = PatternTracker::kSamples;
  (void)tracker.update(cam.matrices(aspect), viewport, true);
  for (int frame = 1; frame <= 60; ++frame) {
    cam.zoom(1.0f / 1.1f, cursorNdc, aspect);
    zoom *= 1.1;
    const PatternFit& fit = tracker.update(cam.matrices(aspect), viewport, true);
    fewest = std::min(fewest, fit.samplesUsed);
    resampled += fit.resampled;
    const PatternFrame& f = tracker.frame();
    ASSERT_NEAR(std::log(f.scale), std::log(zoom), 0.01) << "frame " << frame << ", " << fit.samplesUsed << " samples";
    const float c = std::cos(f.rotation), s = std::sin(f.rotation);
    const glm::vec2 moved = f.scale * glm::vec2(c * cursorPx.x - s * cursorPx.y, s * cursorPx.x + c * cursorPx.y) + f.translation;
    ASSERT_LT(glm::length(moved - cursorPx), 0.5f) << "frame " << frame;
  }
  EXPECT_GE(fewest, PatternTracker::kCloseUpBelow / 2);
  EXPECT_GE(resampled, 2);  // 300x: the points drawn from the view run out too, and are drawn again
  std::printf("zoom %.0fx: fewest samples %d, drawn from the view %d times\n", zoom, fewest, resampled);

  // Back out to the whole square: the fixed samples take over again.
  for (int frame = 0; frame < 60; ++frame) {
    cam.zoom(1.1f, cursorNdc, aspect);
    zoom /= 1.1;
    const PatternFit& fit = tracker.update(cam.matrices(aspect), viewport, true);
    ASSERT_NEAR(std::log(tracker.frame().scale), std::log(zoom), 0.02) << "out, frame " << frame;
    ASSERT_FALSE(fit.resampled && frame > 50);
  }
}

}  // namespace
}  // namespace npr
