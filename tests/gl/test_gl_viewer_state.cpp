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

struct Fixture : ::testing::Test {
  std::unique_ptr<Renderer> r;
  void SetUp() override {
    auto made = Renderer::create();
    ASSERT_TRUE(made) << made.error();
    r = std::move(*made);
    applyDefaultMaterial(r->lighting());
    const float pos[4] = {2.0f, 2.5f, 3.0f, 1.0f};
    r->lighting().setModelView(testCamera(1.0f).view);
    ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos));
  }
};

int countDiffering(const ImageRGBA8& a, const ImageRGBA8& b) {
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4)
    if (a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] || a.pixels[i + 2] != b.pixels[i + 2]) ++n;
  return n;
}

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
