// GL tier: the vignette (renderer/features/vignette/). In every path the frame's corners turn
// to the paper and its centre keeps the picture; at strength 0, or off, nothing changes.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "support/test_util.h"

namespace npr {
namespace {

using VignetteFixture = test::RendererFixture;
constexpr int kSize = 96;

glm::vec3 pixel(const ImageRGBA8& img, int x, int y) {
  const std::size_t i = 4 * (std::size_t(y) * std::size_t(img.width) + std::size_t(x));
  return glm::vec3(img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]) / 255.0f;
}

TEST_F(VignetteFixture, CornersTurnToThePaperAndTheCentreKeepsThePicture) {
  const Mesh sphere = icosphere(3);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  r->scene().add(sphere);
  // Unlit (ambient only): the surface is dark everywhere, corners included.
  ASSERT_TRUE(r->lighting().Disable(GL_LIGHT0));
  // Close enough that the sphere covers the whole frame, corners included.
  OrbitCamera orbit(0.0f, 0.0f, 3.0f);
  orbit.frame(1.0f);
  orbit.setYawPitchDistance(0.0f, 0.0f, 1.5f);
  const CameraMatrices cam = orbit.matrices(1.0f);
  const glm::vec3 paper = r->palettes().main()->averages().front();
  for (RenderPath path : userRenderPaths()) {
    if (!pathInfo(path).usesPalette) continue;
    RenderSettings s;
    s.path = path;
    s.materials = false;
    const ImageRGBA8 plain = test::renderImage(*r, cam, s, kSize, kSize);
    // The sphere darkens the corners without the vignette (else the test could not fail).
    ASSERT_GT(glm::length(pixel(plain, 0, 0) - paper) + glm::length(pixel(plain, kSize - 1, kSize - 1) - paper), 0.1f)
        << renderPathName(path) << ": the corners already show the paper";
    s.vignette.on = true;
    s.vignette.radius = 0.3f;
    s.vignette.softness = 0.3f;
    const ImageRGBA8 faded = test::renderImage(*r, cam, s, kSize, kSize);
    for (glm::ivec2 c : {glm::ivec2(0, 0), glm::ivec2(kSize - 1, 0), glm::ivec2(0, kSize - 1), glm::ivec2(kSize - 1, kSize - 1)})
      EXPECT_LT(glm::length(pixel(faded, c.x, c.y) - paper), 2.0f / 255.0f) << renderPathName(path) << " corner " << c.x << "," << c.y;
    // Within the radius (r < 0.3 of the half-diagonal) the picture is untouched.
    for (int y = kSize / 2 - 8; y < kSize / 2 + 8; ++y)
      for (int x = kSize / 2 - 8; x < kSize / 2 + 8; ++x)
        ASSERT_EQ(pixel(faded, x, y), pixel(plain, x, y)) << renderPathName(path) << " at " << x << "," << y;
    s.vignette.strength = 0.0f;
    EXPECT_EQ(test::countDiffering(test::renderImage(*r, cam, s, kSize, kSize), plain), 0) << renderPathName(path);
  }
}

}  // namespace
}  // namespace npr
