// GL tier: one headless EGL context for the whole test program, checked for GL errors
// after every test (KHR_debug), plus render-and-read-back helpers.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "renderer/core/camera.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/renderer.h"

namespace npr::test {

// Fails the current test if GL errors were recorded since the last call.
class GlErrorCheck : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& info) override;
};

// Renders one frame at w x h and reads it back.
ImageRGBA8 renderImage(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h);
// The selection and geometry outputs (Renderer::renderSelection, renderGeometry) into a
// target cleared to zero: entries from an 8-bit target, geometry as floats.
ImageRGBA8 renderEntries(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h);
ImageRGBA32F renderGeometry(Renderer& r, const CameraMatrices& cam, FrameOutput output, int w, int h);
// Renderer::renderStrokeAngles into a float target: (angle, valid) per pixel.
ImageRGBA32F renderStrokeAngles(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h);
// Pixels whose colour differs (alpha ignored).
int countDiffering(const ImageRGBA8& a, const ImageRGBA8& b);

// A renderer with the viewer's default material and a point light at (2, 2.5, 3) in the
// standard test view.
struct RendererFixture : ::testing::Test {
  std::unique_ptr<Renderer> r;
  void SetUp() override;
};

// The standard test view of a mesh fitted to the unit sphere.
CameraMatrices testCamera(float aspect, float yaw = 30.0f, float pitch = 20.0f);

std::string sourcePath(const std::string& relative);
// A palette shipped in palettes/NAME/NAME.palette (a failed load fails the test).
Palette shippedPalette(const std::string& name);
// A palette of `n` solid grey entries from white to black (on a solid background): tone
// without pattern, for tests that measure tone.
Palette greyRamp(int n);
// One entry whose texels spell their own index in their colour: level 0 is 64x64 with
// (R, G) = 4 (i, j) and B = 0, its level 1 is 32x32 with (R, G) = 8 (i, j) and B = 255. What the
// object pattern's tests read the texel under each pixel from.
Palette texelIndexPalette();
// Compares with tests/golden/NAME.png: at most `failFraction` of the pixels may differ by
// more than 2/255 in a channel, and the mean channel difference must stay under `meanDiff`.
// A failure writes NAME-actual.png and NAME-diff.png (4x amplified) in build/test-output.
// NPR_UPDATE_GOLDEN=1 rewrites the goldens instead (then look at them before committing).
void expectGolden(const std::string& name, const ImageRGBA8& img, double failFraction, double meanDiff);

}  // namespace npr::test
