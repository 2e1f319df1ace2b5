// GL tier: the depth cue (renderer/features/depth_cue/). In every path the far model of a
// scene turns lighter (toward the paper) and the near one keeps its tone; off, nothing changes.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "support/test_util.h"

namespace npr {
namespace {

using DepthCueFixture = test::RendererFixture;
constexpr int kSize = 160;

float meanLuminance(const ImageRGBA8& img, const ImageRGBA32F& geometry, bool nearHalf) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
    const float z = geometry.pixels[4 * i + 2];
    if (z == 0.0f || (z > -3.0f) != nearHalf) continue;  // eye z: the scene's centre is 3 away
    sum += (0.2126 * img.pixels[4 * i] + 0.7152 * img.pixels[4 * i + 1] + 0.0722 * img.pixels[4 * i + 2]) / 255.0;
    ++n;
  }
  EXPECT_GT(n, 300) << (nearHalf ? "near" : "far") << " model barely visible";
  return n ? float(sum / n) : 0.0f;
}

TEST_F(DepthCueFixture, TheFarModelFadesTowardThePaperInEveryPath) {
  const Mesh sphere = icosphere(3);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(0.4f));
  r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(-0.45f, 0.0f, 0.6f)) * scale);
  r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.45f, 0.0f, -0.6f)) * scale);
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 0.0f);
  const ImageRGBA32F geometry = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  for (RenderPath path : userRenderPaths()) {
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 plain = test::renderImage(*r, cam, s, kSize, kSize);
    s.depthCue.on = true;
    s.depthCue.start = 0.35f;
    s.depthCue.end = 0.8f;
    s.depthCue.strength = 0.8f;
    const ImageRGBA8 cued = test::renderImage(*r, cam, s, kSize, kSize);
    EXPECT_GT(meanLuminance(cued, geometry, false), meanLuminance(plain, geometry, false) + 0.1f) << renderPathName(path);
    EXPECT_NEAR(meanLuminance(cued, geometry, true), meanLuminance(plain, geometry, true), 0.02f) << renderPathName(path);
    s.depthCue.strength = 0.0f;
    EXPECT_EQ(test::countDiffering(test::renderImage(*r, cam, s, kSize, kSize), plain), 0) << renderPathName(path);
  }
}

}  // namespace
}  // namespace npr
