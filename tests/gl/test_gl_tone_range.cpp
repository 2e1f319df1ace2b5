// GL tier: the automatic tone range on a real, dark model (assimp's spider, textures of albedo
// about 0.2): with the palette's own range it is drawn with the darkest few levels of the
// crosshatch; fitted, with at least five; and orbiting it, the fit moves smoothly. Crisp tone
// (--tone-blend threshold): the smooth path's strokes stay whole at the same mean tone, and
// palettes without a threshold map are blended as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/core/colour.h"
#include "renderer/mesh/mesh_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

using ToneFixture = test::RendererFixture;
constexpr int kSize = 256;

// Palette entries covering at least 0.5% of the model's pixels.
int levelsUsed(Renderer& r, const CameraMatrices& cam, const RenderSettings& s) {
  const ImageRGBA8 entries = test::renderEntries(r, cam, s, kSize, kSize);
  const ImageRGBA32F cover = test::renderGeometry(r, cam, FrameOutput::EyePosition, kSize, kSize);
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
  r->scene().setOnly(&*spider);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  RenderSettings s;
  s.path = RenderPath::Triangle;
  const CameraMatrices cam = test::testCamera(1.0f);
  const int fixed = levelsUsed(*r, cam, s);
  s.toneRange = ToneRange::Auto;
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
  s.toneRange = ToneRange::Fixed;
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_FALSE(r->toneRange());
}

// A dark object beside a bright one: fitted as one scene, the bright one stretches the range
// and the dark one keeps a few dark levels; per object, each is fitted to its own tones, the
// dark one gets as many levels as the bright one, and the bright one draws as before.
TEST_F(ToneFixture, PerObjectFitsEachObjectToItsOwnTones) {
  const Mesh bright = icosphere(4);
  Mesh dark = icosphere(4);
  dark.colours.assign(dark.positions.size(), glm::vec3(0.12f));  // albedo 0.12: a dark object
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(0.45f));
  r->scene().add(bright, glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, 0.0f, 0.0f)) * scale);
  const ModelId darkId = r->scene().add(dark, glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)) * scale);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  const ImageRGBA32F cover = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  // Levels covering at least 2% of each object's pixels (left: the bright one, right: the dark).
  const auto levels = [&](const RenderSettings& s, int& left, int& right) {
    ImageRGBA8 entries;
    for (int frame = 0; frame < 12; ++frame) entries = test::renderEntries(*r, cam, s, kSize, kSize);  // let the fit settle
    std::map<int, int> count[2];
    int pixels[2] = {0, 0};
    for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
      if (cover.pixels[4 * i + 2] == 0.0f) continue;
      const glm::vec3 eye(cover.pixels[4 * i], cover.pixels[4 * i + 1], cover.pixels[4 * i + 2]);
      const int side = glm::vec3(glm::inverse(cam.view) * glm::vec4(eye, 1.0f)).x < 0.0f ? 0 : 1;
      ++pixels[side];
      ++count[side][entries.pixels[4 * i]];
    }
    int used[2] = {0, 0};
    for (int k = 0; k < 2; ++k)
      for (const auto& [entry, n] : count[k]) used[k] += n * 50 >= pixels[k];
    left = used[0];
    right = used[1];
  };
  RenderSettings s;
  s.path = RenderPath::Triangle;
  s.toneRange = ToneRange::Auto;
  int sceneBright = 0, sceneDark = 0, ownBright = 0, ownDark = 0;
  levels(s, sceneBright, sceneDark);
  s.toneRange = ToneRange::PerObject;
  levels(s, ownBright, ownDark);
  std::printf("levels used (2%% of an object's pixels): fitted as a scene bright %d, dark %d; per object bright %d, dark %d\n", sceneBright,
              sceneDark, ownBright, ownDark);
  EXPECT_LT(sceneDark, sceneBright) << "the scene's fit does not leave the dark object short: the test says nothing";
  EXPECT_GE(ownDark, ownBright - 1);
  EXPECT_GT(ownDark, sceneDark);
  EXPECT_GE(ownBright, sceneBright - 1);
  // Orbiting 40 frames at 3 degrees, the dark object's own range moves little per frame.
  ASSERT_TRUE(r->scene().find(darkId)->toneTarget);
  glm::vec2 last = *r->scene().find(darkId)->toneTarget;
  float worst = 0.0f;
  for (int f = 0; f < 40; ++f) {
    (void)test::renderImage(*r, test::testCamera(1.0f, 3.0f * float(f), 10.0f), s, 64, 64);
    const glm::vec2 now = *r->scene().find(darkId)->toneTarget;
    worst = std::max(worst, std::max(std::abs(now.x - last.x), std::abs(now.y - last.y)));
    last = now;
  }
  std::printf("the dark object's own range: largest change per frame while orbiting %.4f (query axis 0..3)\n", double(worst));
  EXPECT_LT(worst, 0.05f);
  // Back to one range for the scene: the dark object is as short of levels as before.
  s.toneRange = ToneRange::Auto;
  int againBright = 0, againDark = 0;
  levels(s, againBright, againDark);
  EXPECT_EQ(againDark, sceneDark);
}

// The bunny through the smooth path, mix against threshold: the threshold frame has fewer
// mid-grey pixels on the model (strokes whole, not faded) at about the same mean light; a
// palette that is a ramp (Gooch) has no thresholds and draws the same frame either way.
TEST_F(ToneFixture, ThresholdKeepsStrokesWholeAtTheSameToneAndRampsAreBlended) {
  auto bunny = loadMesh(test::sourcePath("models/bunny.obj"));
  ASSERT_TRUE(bunny) << bunny.error();
  r->scene().setOnly(&*bunny);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  ASSERT_TRUE(r->palettes().main()->hasToneThresholds()) << r->palettes().main()->toneThresholdNote();
  RenderSettings s;
  s.path = RenderPath::Smooth;
  const CameraMatrices cam = test::testCamera(1.0f);
  const ImageRGBA32F cover = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  const ImageRGBA8 mixed = test::renderImage(*r, cam, s, kSize, kSize);
  s.toneBlend = ToneBlend::Threshold;
  const ImageRGBA8 crisp = test::renderImage(*r, cam, s, kSize, kSize);
  // Mid grey: a pixel's mean channel between a quarter and three quarters of the way from ink
  // (the darkest on the model) to paper (the lightest).
  const auto measure = [&](const ImageRGBA8& img) {
    std::vector<float> v;
    for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i)
      if (cover.pixels[4 * i + 2] != 0.0f) v.push_back((img.pixels[4 * i] + img.pixels[4 * i + 1] + img.pixels[4 * i + 2]) / 765.0f);
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    double grey = 0, light = 0;
    for (float x : v) {
      const float u = (x - *lo) / std::max(1e-6f, *hi - *lo);
      grey += u > 0.25f && u < 0.75f;
      light += srgbToLinear(x);
    }
    return std::pair{grey / double(v.size()), light / double(v.size())};
  };
  // The yardstick: the pixel path, one whole level per pixel (its own strokes' antialiased edges
  // are all the grey it has).
  RenderSettings single = s;
  single.path = RenderPath::Pixel;
  const auto [levelGrey, levelLight] = measure(test::renderImage(*r, cam, single, kSize, kSize));
  const auto [mixGrey, mixLight] = measure(mixed);
  const auto [crispGrey, crispLight] = measure(crisp);
  std::printf("smooth path on the bunny, crosshatch: mid-grey pixels %.1f%% (mix), %.1f%% (threshold), %.1f%% (pixel path: whole "
              "levels); mean light %.3f, %.3f, %.3f\n",
              100.0 * mixGrey, 100.0 * crispGrey, 100.0 * levelGrey, mixLight, crispLight, levelLight);
  EXPECT_LT(crispGrey, levelGrey * 1.05);
  EXPECT_GT(mixGrey, levelGrey * 1.05);
  EXPECT_NEAR(crispLight, mixLight, 0.02);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  EXPECT_FALSE(r->palettes().main()->hasToneThresholds());
  s.match = MatchMode::Intensity;
  const ImageRGBA8 rampCrisp = test::renderImage(*r, cam, s, kSize, kSize);
  s.toneBlend = ToneBlend::Mix;
  EXPECT_EQ(test::countDiffering(rampCrisp, test::renderImage(*r, cam, s, kSize, kSize)), 0);
}

}  // namespace
}  // namespace npr
