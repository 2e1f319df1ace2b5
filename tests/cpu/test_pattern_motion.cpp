// CPU tier: the benchmark's floor for the anchored pattern's slide (support/pattern_motion.h):
// the least slide any 2D similarity has between two frames. Zero where the screen moves as one
// similarity (a plane panned, zoomed or turned in the view); where two depths are interleaved
// pixel by pixel under a pan (parallax no similarity follows), what the least mean leaves.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "support/pattern_motion.h"

namespace npr {
namespace {

constexpr int kSize = 64;

// Eye-space positions of what the camera at the origin sees: each pixel's surface at
// depth(x, y) (negative z), covering the whole view.
template <class Depth>
ImageRGBA32F surfaceAt(const CameraMatrices& camera, Depth depth) {
  ImageRGBA32F img{kSize, kSize, std::vector<float>(size_t(kSize) * kSize * 4)};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float z = depth(x, y);
      const glm::vec2 ndc((float(x) + 0.5f) / kSize * 2.0f - 1.0f, (float(kSize - y) - 0.5f) / kSize * 2.0f - 1.0f);
      float* p = &img.pixels[(size_t(y) * kSize + size_t(x)) * 4];
      p[0] = ndc.x * -z / camera.projection[0][0];
      p[1] = ndc.y * -z / camera.projection[1][1];
      p[2] = z;
      p[3] = 1.0f;
    }
  return img;
}

// Pixels a point at eye depth z moves across the view when the camera steps `dx` sideways.
float panPixels(const CameraMatrices& camera, float z, float dx) { return camera.projection[0][0] * dx / -z * 0.5f * kSize; }

TEST(LeastSimilaritySlide, ZeroWhereTheScreenMovesAsOneSimilarity) {
  CameraMatrices now;
  now.projection = glm::perspective(glm::radians(50.0f), 1.0f, 0.1f, 100.0f);
  CameraMatrices next = now;
  next.view = glm::translate(glm::mat4(1.0f), glm::vec3(-0.2f, 0.05f, 0.0f));
  const ImageRGBA32F plane = surfaceAt(now, [](int, int) { return -5.0f; });
  EXPECT_GT(panPixels(now, -5.0f, 0.2f), 2.0f);  // it does move
  EXPECT_LT(test::leastSimilaritySlide(plane, now, next, 1), 1e-3);
  // A pure zoom (the camera moving toward a plane facing it) is a similarity too.
  next.view = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 0.5f));
  EXPECT_LT(test::leastSimilaritySlide(plane, now, next, 1), 1e-3);
  // And so is the view turning about its axis.
  next.view = glm::rotate(glm::mat4(1.0f), glm::radians(3.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_LT(test::leastSimilaritySlide(plane, now, next, 1), 1e-3);
}

TEST(LeastSimilaritySlide, InterleavedDepthsUnderAPanLeaveHalfTheirDifference) {
  CameraMatrices now;
  now.projection = glm::perspective(glm::radians(50.0f), 1.0f, 0.1f, 100.0f);
  CameraMatrices next = now;
  const float dx = 0.2f;
  next.view = glm::translate(glm::mat4(1.0f), glm::vec3(-dx, 0.0f, 0.0f));
  // Columns alternate between a near and a far plane: every near pixel has a far neighbour one
  // pixel away, so no similarity moves them apart by the parallax.
  const ImageRGBA32F stripes = surfaceAt(now, [](int x, int) { return x % 2 ? -8.0f : -2.0f; });
  const double parallax = double(panPixels(now, -2.0f, dx) - panPixels(now, -8.0f, dx));
  ASSERT_GT(parallax, 2.0);
  const double least = test::leastSimilaritySlide(stripes, now, next, 1);
  EXPECT_GT(least, 0.47 * parallax);
  EXPECT_LT(least, 0.505 * parallax);
  // One column in four near: the least mean slide follows the three far ones and leaves the
  // near quarter its whole parallax (a least-squares fit would split it: 0.375 of it).
  const ImageRGBA32F sparse = surfaceAt(now, [](int x, int) { return x % 4 ? -8.0f : -2.0f; });
  const double leastSparse = test::leastSimilaritySlide(sparse, now, next, 1);
  EXPECT_GT(leastSparse, 0.23 * parallax);
  EXPECT_LT(leastSparse, 0.27 * parallax);
}

}  // namespace
}  // namespace npr
