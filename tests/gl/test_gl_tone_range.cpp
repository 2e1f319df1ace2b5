// GL tier: the automatic tone range on a real, dark model (assimp's spider, textures of albedo
// about 0.2): with the palette's own range it is drawn with the darkest few levels of the
// crosshatch; fitted, with at least five; and orbiting it, the fit moves smoothly.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "gl/gl_test_env.h"
#include "renderer/mesh/mesh_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

using ToneFixture = test::RendererFixture;
constexpr int kSize = 256;

// Palette entries covering at least 0.5% of the model's pixels.
int levelsUsed(Renderer& r, const CameraMatrices& cam, const RenderSettings& s) {
  const ImageRGBA8 entries = test::renderEntries(r, cam, s, kSize, kSize);
  const ImageRGBA32F cover = test::renderGeometry(r, cam, GeometryOutput::EyePosition, kSize, kSize);
  std::map<int, int> count;
  int model = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
    if (cover.pixels[4 * i + 2] == 0.0f) continue;
    ++model;
    ++count[entries.pixels[4 * i]];
  }
  int used = 0;
  for (const auto& [entry, n] : count) used += n * 200 >= model;
  return used;
}

TEST_F(ToneFixture, TheSpiderUsesFiveLevelsOrMoreAndTheFitNeverPumps) {
  auto spider = loadMesh("/usr/share/assimp/models/OBJ/spider.obj");
  ASSERT_TRUE(spider) << spider.error();
  r->setMesh(&*spider);
  ASSERT_TRUE(r->setPalette(test::shippedPalette("crosshatch")));
  RenderSettings s;
  s.path = RenderPath::Triangle;
  const CameraMatrices cam = test::testCamera(1.0f);
  const int fixed = levelsUsed(*r, cam, s);
  s.autoToneRange = true;
  const int fitted = levelsUsed(*r, cam, s);
  EXPECT_LT(fixed, 5) << "the spider is not dark with the palette's own range: the test says nothing";
  EXPECT_GE(fitted, 5);
  ASSERT_TRUE(r->toneRange());
  // An orbit of 60 frames, 3 degrees each: the fitted range moves by little per frame.
  float worst = 0.0f;
  glm::vec2 last = *r->toneRange();
  for (int f = 0; f < 60; ++f) {
    (void)test::renderImage(*r, test::testCamera(1.0f, 30.0f + 3.0f * float(f)), s, 64, 64);
    const glm::vec2 now = *r->toneRange();
    worst = std::max(worst, std::max(std::abs(now.x - last.x), std::abs(now.y - last.y)));
    last = now;
  }
  std::printf("tone range: fixed %d levels, auto %d; largest change per frame while orbiting %.4f (query axis 0..3)\n", fixed,
              fitted, double(worst));
  EXPECT_LT(worst, 0.05f);
  // Fixed again: no target.
  s.autoToneRange = false;
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_FALSE(r->toneRange());
}

}  // namespace
}  // namespace npr
