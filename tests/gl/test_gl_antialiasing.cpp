// GL tier: anti-aliasing by supersampling (--aa ssaaK). Against the same still drawn at 4x and
// box-filtered (ssaa4: line widths and the pattern's texel times 4), the mean error at the
// pixels lines and tone edges cross must at least halve with ssaa2 and fall further with ssaa3
// (at most 0.07); the
// pattern inside a palette's tone must come out as drawn (each texel covers whole blocks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/settings/style_file.h"
#include "app/viewer_state.h"
#include "gl/gl_test_env.h"
#include "renderer/core/image_io.h"
#include "support/test_util.h"

namespace npr {
namespace {

constexpr int kW = 200, kH = 150;

float luma(const ImageRGBA8& img, int i) {
  return (0.2126f * img.pixels[4 * i] + 0.7152f * img.pixels[4 * i + 1] + 0.0722f * img.pixels[4 * i + 2]) / 255.0f;
}

// Pixels at an edge of the reference: their 3x3 neighbourhood spans more than 0.15 in luma.
// `mixed`: only those the edge crosses, partly covered in the reference (its luma a tenth of
// the span or more away from both ends): where an aliased frame errs.
std::vector<bool> edgeMask(const ImageRGBA8& reference, bool mixed = false) {
  std::vector<bool> mask(std::size_t(kW * kH), false);
  for (int y = 1; y + 1 < kH; ++y)
    for (int x = 1; x + 1 < kW; ++x) {
      float lo = 1.0f, hi = 0.0f;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const float l = luma(reference, (y + dy) * kW + x + dx);
          lo = std::min(lo, l), hi = std::max(hi, l);
        }
      const float l = luma(reference, y * kW + x), margin = 0.1f * (hi - lo);
      mask[std::size_t(y * kW + x)] = hi - lo > 0.15f && (!mixed || (l > lo + margin && l < hi - margin));
    }
  return mask;
}

// Mean absolute channel error over the masked pixels (0..1).
double meanError(const ImageRGBA8& a, const ImageRGBA8& b, const std::vector<bool>& mask) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    for (int c = 0; c < 3; ++c) sum += std::abs(int(a.pixels[4 * i + c]) - int(b.pixels[4 * i + c])) / 255.0;
    n += 3;
  }
  return n ? sum / n : 0.0;
}

using AaFixture = test::RendererFixture;

TEST_F(AaFixture, SupersamplingBringsEdgesCloseToTheFourTimesReference) {
  for (const char* style : {"cel", "crosshatch", "technical"}) {
    ViewerState state;
    Result<Style> loaded = loadStyle(*findStyle(style));
    ASSERT_TRUE(loaded) << loaded.error();
    ASSERT_TRUE(applyStyle(*loaded, state, *r));
    ASSERT_TRUE(state.loadModel(test::sourcePath("models/teapot.obj"), *r));
    state.viewAspect = float(kW) / kH;
    state.frameScene();
    const CameraMatrices cam = state.view(state.viewAspect);
    ASSERT_TRUE(state.applyLight(*r, cam));
    auto at = [&](int k) {
      RenderSettings s = state.settings;
      s.supersample = k;
      return test::renderImage(*r, cam, s, kW, kH);
    };
    const ImageRGBA8 reference = at(4), off = at(1), ssaa2 = at(2), ssaa3 = at(3);
    const std::vector<bool> near = edgeMask(reference), edges = edgeMask(reference, true);
    const double eOff = meanError(off, reference, edges), e2 = meanError(ssaa2, reference, edges), e3 = meanError(ssaa3, reference, edges);
    std::printf("%-10s mean error against ssaa4 at %5zu edge pixels: off %.3f, ssaa2 %.3f, ssaa3 %.3f; within a pixel of an edge (%zu): %.3f, %.3f, %.3f\n",
                style, std::size_t(std::count(edges.begin(), edges.end(), true)), eOff, e2, e3,
                std::size_t(std::count(near.begin(), near.end(), true)), meanError(off, reference, near), meanError(ssaa2, reference, near),
                meanError(ssaa3, reference, near));
    EXPECT_GT(eOff, 0.015) << style << ": the aliased frame is already close: the test says nothing";
    EXPECT_LT(e2, 0.5 * eOff) << style;
    EXPECT_LT(e3, e2) << style;
    EXPECT_LE(e3, 0.07) << style;
    ASSERT_TRUE(writeImage(test::outputPath(std::string("aa-") + style + "-off.png"), off));
    ASSERT_TRUE(writeImage(test::outputPath(std::string("aa-") + style + "-ssaa3.png"), ssaa3));
    ASSERT_TRUE(r->lighting().setToneModel(ToneModel::OpenGL, r->lighting().toneParameters()));
  }
}

// Inside a tone, far from edges, the pattern is as the aliased frame draws it: a texel covers
// whole k x k blocks of the supersampled frame, which the box filter averages to itself.
TEST_F(AaFixture, SupersamplingKeepsThePatternAsDrawn) {
  ViewerState state;
  ASSERT_TRUE(state.loadPalette(defaultPalettePath(), *r));
  const Mesh plane = test::square(8);
  r->scene().setOnly(&plane);
  RenderSettings s = state.settings;
  s.lines = LineSettings{};
  s.toneRange = ToneRange::Fixed;
  const CameraMatrices cam = test::testCamera(float(kW) / kH, 0.0f, 0.0f);
  const ImageRGBA8 off = test::renderImage(*r, cam, s, kW, kH);
  s.supersample = 2;
  const ImageRGBA8 ssaa2 = test::renderImage(*r, cam, s, kW, kH);
  // The square's inside, away from its edges and from tone steps: most pixels equal.
  const std::vector<bool> edges = edgeMask(off);
  int same = 0, n = 0;
  for (int y = kH / 4; y < 3 * kH / 4; ++y)
    for (int x = kW / 4; x < 3 * kW / 4; ++x) {
      const std::size_t i = std::size_t(y * kW + x);
      ++n;
      same += off.pixels[4 * i] == ssaa2.pixels[4 * i] && off.pixels[4 * i + 1] == ssaa2.pixels[4 * i + 1];
    }
  std::printf("pattern pixels equal with ssaa2: %d of %d\n", same, n);
  (void)edges;
  EXPECT_GE(same, n * 9 / 10);
}

}  // namespace
}  // namespace npr
