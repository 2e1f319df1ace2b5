// GL tier: anti-aliasing (--aa). Against the same still drawn at 4x and box-filtered (ssaa4:
// line widths and the pattern's texel times 4), the mean error at the pixels lines and tone
// edges cross must fall with the shader's tone edges (edges) where the tone bands are the
// edges, at least halve with ssaa2 and fall further with ssaa3 (at most 0.07), and fall with the
// post-process filter (fxaa) where the edges are the shading's and the outlines; the pattern
// inside a palette's tone must come out as drawn (each texel covers whole blocks, and the
// shader's edges show each entry at the pixel's own texel).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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

// The pixels at least two pixels from any geometric edge: the background, or a jump in depth
// of more than 3% (silhouettes, one part over another). Tone edges there are the shading's.
std::vector<bool> awayFromGeometricEdges(const ImageRGBA32F& eye) {
  std::vector<bool> mask(std::size_t(kW * kH), false);
  auto depth = [&](int x, int y) { return eye.pixels[4 * std::size_t(y * kW + x) + 2]; };
  auto covered = [&](int x, int y) { return eye.pixels[4 * std::size_t(y * kW + x) + 3] != 0.0f; };
  for (int y = 2; y + 2 < kH; ++y)
    for (int x = 2; x + 2 < kW; ++x) {
      bool away = true;
      for (int dy = -2; dy <= 2 && away; ++dy)
        for (int dx = -2; dx <= 2 && away; ++dx)
          away = covered(x + dx, y + dy) && std::abs(depth(x + dx, y + dy) - depth(x, y)) <= 0.03f * std::abs(depth(x, y));
      mask[std::size_t(y * kW + x)] = away;
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
    auto at = [&](AntiAliasing aa) {
      RenderSettings s = state.settings;
      s.aa = aa;
      return test::renderImage(*r, cam, s, kW, kH);
    };
    const ImageRGBA8 reference = at(AntiAliasing::Ssaa4), off = at(AntiAliasing::Off), edgesImage = at(AntiAliasing::Edges),
                     ssaa2 = at(AntiAliasing::Ssaa2), ssaa3 = at(AntiAliasing::Ssaa3), fxaa = at(AntiAliasing::Fxaa);
    const std::vector<bool> near = edgeMask(reference), edges = edgeMask(reference, true);
    // The edges the shading draws inside the surface: the tone bands'.
    std::vector<bool> toneEdgePixels = awayFromGeometricEdges(test::renderGeometry(*r, cam, FrameOutput::EyePosition, kW, kH));
    for (std::size_t i = 0; i < edges.size(); ++i) toneEdgePixels[i] = toneEdgePixels[i] && edges[i];
    const double eOff = meanError(off, reference, edges), eEdges = meanError(edgesImage, reference, edges),
                 e2 = meanError(ssaa2, reference, edges), e3 = meanError(ssaa3, reference, edges),
                 eFxaa = meanError(fxaa, reference, edges);
    std::printf("%-10s mean error against ssaa4 at %5zu edge pixels: off %.3f, edges %.3f, ssaa2 %.3f, ssaa3 %.3f; within a pixel of an "
                "edge (%zu): %.3f, %.3f, %.3f, %.3f; fxaa %.3f, near %.3f\n",
                style, std::size_t(std::count(edges.begin(), edges.end(), true)), eOff, eEdges, e2, e3,
                std::size_t(std::count(near.begin(), near.end(), true)), meanError(off, reference, near),
                meanError(edgesImage, reference, near), meanError(ssaa2, reference, near), meanError(ssaa3, reference, near), eFxaa,
                meanError(fxaa, reference, near));
    EXPECT_GT(eOff, 0.015) << style << ": the aliased frame is already close: the test says nothing";
    // The tone bands' edges (cel's flat bands, drawn per pixel): the shader's edges must cut
    // their error by 40% at least, to within 0.05; no style may come out worse anywhere.
    const double toneOff = meanError(off, reference, toneEdgePixels), toneEdges = meanError(edgesImage, reference, toneEdgePixels);
    std::printf("%-10s tone edges only (%zu pixels): off %.3f, edges %.3f, ssaa2 %.3f\n", style,
                std::size_t(std::count(toneEdgePixels.begin(), toneEdgePixels.end(), true)), toneOff, toneEdges,
                meanError(ssaa2, reference, toneEdgePixels));
    if (std::string(style) == "cel") {
      EXPECT_GT(toneOff, 0.05) << style << ": the tone edges are already close: the test says nothing";
      EXPECT_LT(toneEdges, 0.6 * toneOff) << style;
      EXPECT_LE(toneEdges, 0.05) << style;
    }
    EXPECT_LE(toneEdges, toneOff + 0.002) << style;
    EXPECT_LE(eEdges, eOff + 0.002) << style;
    EXPECT_LE(eEdges, 0.07) << style;
    EXPECT_LT(e2, 0.5 * eOff) << style;
    EXPECT_LT(e3, e2) << style;
    EXPECT_LE(e3, 0.07) << style;
    // The post-process filter smooths the edges it finds: where they are the shading's bands and
    // the outlines (cel, technical), by a fifth at least against the shader's edges alone. It
    // cannot tell the pattern's strokes from edges, and softens them (crosshatch: the error
    // within a pixel of an edge rises; printed above).
    if (std::string(style) != "crosshatch") {
      EXPECT_LT(eFxaa, 0.8 * eEdges) << style;
    }
    ASSERT_TRUE(writeImage(test::outputPath(std::string("aa-") + style + "-off.png"), off));
    ASSERT_TRUE(writeImage(test::outputPath(std::string("aa-") + style + "-edges.png"), edgesImage));
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
  s.aa = AntiAliasing::Off;
  const ImageRGBA8 off = test::renderImage(*r, cam, s, kW, kH);
  for (AntiAliasing aa : {AntiAliasing::Edges, AntiAliasing::Ssaa2}) {
    s.aa = aa;
    const ImageRGBA8 smoothed = test::renderImage(*r, cam, s, kW, kH);
    // The square's inside, away from its edges and from tone steps: most pixels equal.
    int same = 0, n = 0;
    for (int y = kH / 4; y < 3 * kH / 4; ++y)
      for (int x = kW / 4; x < 3 * kW / 4; ++x) {
        const std::size_t i = std::size_t(y * kW + x);
        ++n;
        same += off.pixels[4 * i] == smoothed.pixels[4 * i] && off.pixels[4 * i + 1] == smoothed.pixels[4 * i + 1];
      }
    std::printf("pattern pixels equal with aa %d: %d of %d\n", int(aa), same, n);
    EXPECT_GE(same, n * 9 / 10) << int(aa);
  }
}

}  // namespace
}  // namespace npr
