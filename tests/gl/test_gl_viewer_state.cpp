// GL tier, app level: the viewer's scene state on the headless context. A model or palette
// that fails to load leaves the current one drawing exactly as before.
#include <gtest/gtest.h>

#include "app/viewer_state.h"
#include "gl/gl_test_env.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::renderImage;
using test::sourcePath;
using test::testCamera;

using Fixture = test::RendererFixture;
using test::countDiffering;

TEST_F(Fixture, FailedPaletteLoadKeepsTheCurrentOne) {
  ViewerState state;
  const Mesh mesh = test::icosphere(3);
  r->setMesh(&mesh);
  ASSERT_TRUE(state.loadPalette(sourcePath("palettes/cel/cel.palette"), *r));
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.match = state.settings.match;
  const ImageRGBA8 before = renderImage(*r, testCamera(1.0f), s, 64, 64);
  test::TempDir d;
  EXPECT_FALSE(state.loadPalette(d.write("broken.palette", "missing.png\n"), *r));
  EXPECT_FALSE(state.loadModel(d.write("broken.obj", "v 0 0 0\n"), *r));
  EXPECT_EQ(state.palette->name, "Cel (4 tones)");
  const ImageRGBA8 after = renderImage(*r, testCamera(1.0f), s, 64, 64);
  EXPECT_EQ(countDiffering(before, after), 0);
  EXPECT_GE(state.messages.size(), 2u);  // both failures are reported for the overlay
}

}  // namespace
}  // namespace npr
