// GL tier: pattern scale and palette mip levels. At a pattern scale of 1/2 the screen shows
// the palette's next mip level texel for pixel; the model's tone stays put from 1/4 to 4 pixels
// a texel with drawn and with reduced mip levels; the stencil path's quads sit where the
// triangle path's pattern does at any scale; every path draws scaled and anchored-and-scaled
// patterns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "gl/gl_test_env.h"
#include "renderer/core/colour.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/palette/palette_mipmaps.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::renderImage;
using test::shippedPalette;
using test::sourcePath;
using test::testCamera;
using Fixture = test::RendererFixture;

// One entry of random opaque texels with a level 1 of its own, unrelated to level 0, so a
// pixel that shows level 1 cannot be mistaken for a filtered level 0.
Palette noisePalette() {
  std::mt19937 rng(7);
  auto noise = [&](int n) {
    ImageRGBA8 img{n, n, std::vector<std::uint8_t>(size_t(n) * size_t(n) * 4, 255)};
    for (size_t i = 0; i < img.pixels.size(); ++i)
      if (i % 4 != 3) img.pixels[i] = std::uint8_t(rng() & 255);
    return img;
  };
  Palette p;
  PaletteEntry e;
  e.image = noise(64);
  e.mips.push_back(noise(32));
  e.average = glm::vec3(0.5f);
  e.intensity = 1.5f;
  p.entries.push_back(std::move(e));
  return p;
}

TEST_F(Fixture, HalfScaleShowsTheNextMipLevelTexelForPixel) {
  const Mesh sq = test::square();
  r->scene().setOnly(&sq);
  const Palette p = noisePalette();
  ASSERT_TRUE(r->palettes().setMain(p));
  const int w = 160, h = 120;
  OrbitCamera cam(0.0f, 0.0f, 3.0f);
  cam.frame(0.5f);  // the square fills the frame
  int done = 0;
  for (float scale : {0.5f, 1.0f, 0.5f}) {
    RenderSettings s;
    s.path = RenderPath::Pixel;
    s.patternScale = scale;
    s.patternLinearFilter = scale == 0.5f && done++ > 0;  // the second time, filtered: at texel centres it is the texel
    const ImageRGBA8 img = renderImage(*r, cam.matrices(float(w) / h), s, w, h);
    const ImageRGBA8& level = scale == 1.0f ? p.entries[0].image : p.entries[0].mips[0];
    const int n = level.width;
    int same = 0, total = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        // Window row y (top first) is GL row h - 1 - y; texel rows are stored top first too.
        const int gx = x % n, gy = (h - 1 - y) % n;
        const std::uint8_t* a = &img.pixels[(size_t(y) * w + size_t(x)) * 4];
        const std::uint8_t* b = &level.pixels[(size_t(n - 1 - gy) * size_t(n) + size_t(gx)) * 4];
        ++total;
        same += std::abs(a[0] - b[0]) <= 1 && std::abs(a[1] - b[1]) <= 1 && std::abs(a[2] - b[2]) <= 1;
      }
    EXPECT_GT(same, total * 99 / 100) << "scale " << scale << ": " << same << " of " << total << " pixels show the level's texel";
  }
}

// A view drawn into part of the framebuffer (the viewer's split view draws two side by side):
// a scaled pattern still tiles from the window's corner, so the mesh passes, which place it from
// clip positions (pattern_vertex.glsl), must add the viewport's corner. Checked texel for pixel
// at half scale (level 1, one texel a pixel) and at scale 2 (level 0, one texel per 2x2 pixels),
// on a square of two triangles (placed per vertex) and of 45,000 (under a pixel each: per pixel).
TEST_F(Fixture, ScaledPatternTilesFromTheWindowCornerInAViewportAwayFromIt) {
  for (int cells : {1, 150}) {
    const Mesh sq = test::square(cells);
    r->scene().setOnly(&sq);
    const Palette p = noisePalette();
    ASSERT_TRUE(r->palettes().setMain(p));
    const int ox = 37, oy = 21, w = 160, h = 120, fw = ox + w + 5, fh = oy + h + 9;
    OrbitCamera cam(0.0f, 0.0f, 3.0f);
    cam.frame(0.5f);
    auto target = OffscreenTarget::create(fw, fh);
    ASSERT_TRUE(target) << target.error();
    for (RenderPath path : {RenderPath::Pixel, RenderPath::Triangle, RenderPath::Stencil})
      for (float scale : {0.5f, 2.0f}) {
        RenderSettings s;
        s.path = path;
        s.patternScale = scale;
        target->bind();
        ASSERT_TRUE(r->render(cam.matrices(float(w) / h), s, {ox, oy, w, h}));
        EXPECT_EQ(r->palettes().main()->variant(MatchMode::Intensity, r->patternPlacement()).patternPerVertex, cells == 1) << cells << " cells";
        const ImageRGBA8 img = target->readRGBA8();
        const ImageRGBA8& level = scale < 1.0f ? p.entries[0].mips[0] : p.entries[0].image;
        const int n = level.width;
        int same = 0, total = 0;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            const int wx = ox + x, wy = oy + y;  // window pixel, GL rows (bottom first)
            const int gx = (scale < 1.0f ? wx : wx / 2) % n, gy = (scale < 1.0f ? wy : wy / 2) % n;
            const std::uint8_t* a = &img.pixels[(size_t(fh - 1 - wy) * size_t(fw) + size_t(wx)) * 4];
            const std::uint8_t* b = &level.pixels[(size_t(n - 1 - gy) * size_t(n) + size_t(gx)) * 4];
            ++total;
            same += std::abs(a[0] - b[0]) <= 1 && std::abs(a[1] - b[1]) <= 1 && std::abs(a[2] - b[2]) <= 1;
          }
        EXPECT_GT(same, total * 99 / 100) << cells << " cells, " << pathInfo(path).name << " at scale " << scale << ": " << same << " of "
                                          << total << " pixels show the window pixel's texel";
      }
  }
}

// Mean linear luminance of an image.
double meanLight(const ImageRGBA8& img) {
  double sum = 0;
  for (size_t i = 0; i < img.pixels.size(); i += 4)
    sum += 0.2126 * srgbToLinear(img.pixels[i] / 255.0f) + 0.7152 * srgbToLinear(img.pixels[i + 1] / 255.0f) +
           0.0722 * srgbToLinear(img.pixels[i + 2] / 255.0f);
  return sum / double(img.pixels.size() / 4);
}

// One level of a palette as a palette of its own (with the background and mip levels).
Palette onlyEntry(const Palette& p, size_t i) {
  Palette one = p;
  one.entries = {p.entries[i]};
  return one;
}

// A square filling a 768-pixel frame shows each level at scales whose tiles fit the frame a
// whole number of times, so the frame's mean is the tiled pattern's: within 0.01 of white of
// what it shows texel for pixel, magnified (bilinear in linear light) or minified (its mip
// levels), for drawn levels and for levels reduced from a plain image.
TEST_F(Fixture, ToneHoldsFromAQuarterToThreePixelsATexel) {
  const Mesh sq = test::square();
  r->scene().setOnly(&sq);
  const int n = 768;
  OrbitCamera cam(0.0f, 0.0f, 3.0f);
  cam.frame(0.5f);
  for (const char* name : {"crosshatch", "stipple", "wood"}) {
    const Palette p = shippedPalette(name);
    const float tile = float(p.entries[0].image.width);
    for (size_t i : {size_t(2), p.entries.size() - 2}) {
      ASSERT_TRUE(r->palettes().setMain(onlyEntry(p, i)));
      RenderSettings s;
      s.path = RenderPath::Pixel;
      const double base = meanLight(renderImage(*r, cam.matrices(1.0f), s, n, n));
      for (float scale : {0.25f, 0.5f, 0.75f, 1.5f, 3.0f})
        for (bool linear : {false, true}) {
          if (std::fmod(float(n), tile * scale) != 0.0f) continue;  // wood's 128-texel tiles at some scales
          s.patternScale = scale;
          s.patternLinearFilter = linear;
          const double tone = meanLight(renderImage(*r, cam.matrices(1.0f), s, n, n));
          EXPECT_NEAR(tone, base, 0.01) << name << " entry " << i << " at pattern scale " << scale << (linear ? " linear" : " nearest");
        }
    }
  }
}

TEST_F(Fixture, StencilQuadsFollowThePatternScale) {
  auto mesh = loadMesh(sourcePath("models/bunny.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  const int w = 320, h = 240;
  const CameraMatrices cam = testCamera(float(w) / h);
  for (float scale : {0.5f, 1.5f, 3.0f}) {
    RenderSettings s;
    s.patternScale = scale;
    s.patternLinearFilter = scale == 1.5f;
    s.path = RenderPath::Stencil;
    const ImageRGBA8 stencil = renderImage(*r, cam, s, w, h);
    s.path = RenderPath::Triangle;
    const ImageRGBA8 triangle = renderImage(*r, cam, s, w, h);
    s.patternScale = 1.0f;
    const ImageRGBA8 unscaled = renderImage(*r, cam, s, w, h);
    EXPECT_LE(test::countDiffering(stencil, triangle), w * h / 1000) << "scale " << scale;
    EXPECT_GT(test::countDiffering(triangle, unscaled), w * h / 20) << "scale " << scale << " changed nothing";
  }
}

TEST_F(Fixture, EveryPathDrawsScaledAndAnchoredScaledPatterns) {
  auto mesh = loadMesh(sourcePath("models/bunny.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("wood")));  // 128-texel entries on a solid background
  const int w = 200, h = 150;
  const CameraMatrices cam = testCamera(float(w) / h);
  for (RenderPath path : userRenderPaths())
    for (PatternSpace space : {PatternSpace::Screen, PatternSpace::Anchored})
      for (float scale : {0.3f, 2.5f}) {
        RenderSettings s;
        s.path = path;
        s.pattern = space;
        s.patternScale = scale;
        s.patternLinearFilter = scale > 1.0f;
        s.orient.source = OrientSource::Fixed;  // turned lookups too, where entries have a direction
        const ImageRGBA8 img = renderImage(*r, cam, s, w, h);
        EXPECT_EQ(img.width, w) << renderPathName(path);
      }
}

}  // namespace
}  // namespace npr
