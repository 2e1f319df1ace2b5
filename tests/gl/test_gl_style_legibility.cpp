// GL tier, app level: every shipped style reads on models no one tuned it for. On a near-black
// model, a near-white one, a scene of both and a long thin one (OBJ files with their own
// materials, written here), framed as a still is framed, each style must give the model
//   - a mean lightness between 0.25 and 0.92 of the paper's (not a silhouette, not blank),
//   - visible tonal spread inside it (its light and form),
//   - an edge that stands off its surroundings (outlined, or set apart from ground and paper),
//   - a screen extent of at least 60% of the frame.
// Lightness here is the encoded (sRGB) luma averaged over the pixels, so a hatching's black
// and white pixels count as the grey they read as.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/settings/style_file.h"
#include "app/viewer_state.h"
#include "gl/gl_test_env.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/core/image_io.h"
#include "support/test_util.h"

namespace npr {
namespace {

constexpr int kW = 240, kH = 160;

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// An OBJ of `body` (vertex and face lines) drawn in one material of diffuse grey `kd`.
std::string writeModel(const test::TempDir& d, const std::string& name, const std::string& body, float kd) {
  const std::string k = std::to_string(kd);
  d.write(name + ".mtl", "newmtl m\nKa 0 0 0\nKd " + k + " " + k + " " + k + "\nKs 0.2 0.2 0.2\nNs 20\n");
  return d.write(name + ".obj", "mtllib " + name + ".mtl\nusemtl m\n" + body);
}

std::string objBody(const Mesh& m) {
  std::string out;
  char line[160];
  for (const glm::vec3& p : m.positions) {
    std::snprintf(line, sizeof line, "v %g %g %g\n", double(p.x), double(p.y), double(p.z));
    out += line;
  }
  for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    std::snprintf(line, sizeof line, "f %u %u %u\n", m.indices[i] + 1, m.indices[i + 1] + 1, m.indices[i + 2] + 1);
    out += line;
  }
  return out;
}

float luma(const ImageRGBA8& img, int i) {
  return (0.2126f * img.pixels[4 * i] + 0.7152f * img.pixels[4 * i + 1] + 0.0722f * img.pixels[4 * i + 2]) / 255.0f;
}

struct Legibility {
  float lightness = 0, spread = 0, standoff = 0, extent = 0;
};

// The figures above, from the picture, the model's coverage and the paper's luma.
Legibility measure(const ImageRGBA8& img, const std::vector<bool>& cover, float paper) {
  Legibility out;
  auto covered = [&](int x, int y) { return x >= 0 && y >= 0 && x < kW && y < kH && cover[std::size_t(y * kW + x)]; };
  // Distance in pixels (Chebyshev) to the nearest pixel of the other kind: the two-pass
  // chessboard distance transform, once for each kind.
  std::vector<int> toOther(std::size_t(kW * kH));
  for (const bool kind : {true, false}) {
    std::vector<int> d(std::size_t(kW * kH));
    auto at = [&](int x, int y) -> int& { return d[std::size_t(y * kW + x)]; };
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) at(x, y) = covered(x, y) == kind ? 1 << 20 : 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        for (const auto& [dx, dy] : {std::pair{-1, 0}, {-1, -1}, {0, -1}, {1, -1}})
          if (x + dx >= 0 && x + dx < kW && y + dy >= 0) at(x, y) = std::min(at(x, y), at(x + dx, y + dy) + 1);
    for (int y = kH - 1; y >= 0; --y)
      for (int x = kW - 1; x >= 0; --x)
        for (const auto& [dx, dy] : {std::pair{1, 0}, {1, 1}, {0, 1}, {-1, 1}})
          if (x + dx >= 0 && x + dx < kW && y + dy < kH) at(x, y) = std::min(at(x, y), at(x + dx, y + dy) + 1);
    for (std::size_t i = 0; i < d.size(); ++i)
      if (cover[i] == kind) toOther[i] = d[i];
  }
  auto distanceToOther = [&](int x, int y) { return toOther[std::size_t(y * kW + x)]; };
  double sum = 0, inner = 0, outer = 0;
  int n = 0, nInner = 0, nOuter = 0, x0 = kW, x1 = -1, y0 = kH, y1 = -1;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float l = luma(img, y * kW + x);
      if (covered(x, y)) {
        sum += l;
        ++n;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        if (distanceToOther(x, y) <= 2) inner += l, ++nInner;
      } else if (const int d = distanceToOther(x, y); d >= 4 && d <= 8) {
        outer += l, ++nOuter;
      }
    }
  if (n == 0) return out;
  out.lightness = float(sum / n) / paper;
  out.standoff = std::abs(float(inner / std::max(nInner, 1) - outer / std::max(nOuter, 1))) / paper;
  out.extent = std::max(float(x1 - x0 + 1) / kW, float(y1 - y0 + 1) / kH);
  // Tonal spread: the 10th to 90th percentile of 8x8 blocks' mean lightness inside the model.
  std::vector<float> blocks;
  for (int by = 0; by + 8 <= kH; by += 8)
    for (int bx = 0; bx + 8 <= kW; bx += 8) {
      double b = 0;
      bool whole = true;
      for (int y = by; y < by + 8 && whole; ++y)
        for (int x = bx; x < bx + 8; ++x) {
          if (!covered(x, y)) {
            whole = false;
            break;
          }
          b += luma(img, y * kW + x);
        }
      if (whole) blocks.push_back(float(b / 64.0) / paper);
    }
  if (blocks.size() >= 4) {
    std::sort(blocks.begin(), blocks.end());
    out.spread = blocks[blocks.size() * 9 / 10] - blocks[blocks.size() / 10];
  }
  return out;
}

struct Case {
  std::string name;
  std::vector<std::string> files;
};

using LegibilityFixture = test::RendererFixture;

TEST_F(LegibilityFixture, EveryStyleReadsOnDarkBrightAndLongModels) {
  test::TempDir d;
  const std::string bunny = readText(test::sourcePath("models/bunny.obj"));
  const std::string teapot = readText(test::sourcePath("models/teapot.obj"));
  const std::string dark = writeModel(d, "dark", bunny, 0.05f);
  const std::string bright = writeModel(d, "bright", teapot, 0.95f);
  const std::string longThin = writeModel(d, "long", objBody(ellipsoid(48, 24, {3.0f, 0.3f, 0.3f})), 0.5f);
  const std::vector<Case> cases{{"dark", {dark}}, {"bright", {bright}}, {"dark+bright", {dark, bright}}, {"long", {longThin}}};
  const std::vector<std::string> styles = discoverStyles();
  ASSERT_GE(styles.size(), 10u);
  int failures = 0;
  std::printf("%-14s %-12s %9s %7s %9s %7s\n", "style", "model", "lightness", "spread", "standoff", "extent");
  for (const std::string& file : styles) {
    const std::string style = std::filesystem::path(file).stem().string();
    // The style applied once (its palettes decoded once), then each model in its place.
    ViewerState state;
    Result<Style> loaded = loadStyle(file);
    ASSERT_TRUE(loaded) << loaded.error();
    ASSERT_TRUE(applyStyle(*loaded, state, *r)) << file;
    for (const Case& c : cases) {
      ASSERT_TRUE(state.loadModels(c.files, false, *r));
      state.scene.setLayout(Layout::File, *r);
      if (c.files.size() > 1) state.scene.setLayout(Layout::Row, *r);
      state.viewAspect = float(kW) / kH;
      state.frameScene();
      const CameraMatrices cam = state.view(state.viewAspect);
      ASSERT_TRUE(state.applyLight(*r, cam));
      // One frame: the tone fit is the frame's own (no settling over frames).
      const ImageRGBA8 img = test::renderImage(*r, cam, state.settings, kW, kH);
      const ImageRGBA32F geometry = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kW, kH);
      std::vector<bool> cover(std::size_t(kW * kH));
      for (std::size_t i = 0; i < cover.size(); ++i) cover[i] = geometry.pixels[4 * i + 2] != 0.0f;
      const glm::vec3 p = state.palette->backgroundColour;
      const float paper = std::max(0.05f, 0.2126f * p.r + 0.7152f * p.g + 0.0722f * p.b);
      const Legibility m = measure(img, cover, paper);
      const bool ok = m.lightness >= 0.25f && m.lightness <= 0.92f && m.spread >= 0.05f && m.standoff >= 0.15f && m.extent >= 0.6f;
      std::printf("%-14s %-12s %9.2f %7.2f %9.2f %7.2f %s\n", style.c_str(), c.name.c_str(), double(m.lightness), double(m.spread),
                  double(m.standoff), double(m.extent), ok ? "" : "<-");
      failures += !ok;
      // Every picture, for the contact sheet (docs/) and for looking at a failure.
      ASSERT_TRUE(writeImage(test::outputPath("legibility-" + style + "-" + c.name + ".png"), img));
    }
    ASSERT_TRUE(r->lighting().setToneModel(ToneModel::OpenGL, r->lighting().toneParameters()));
    r->palettes().clearControl(ControlParameter::Shadow);
    r->palettes().clearControl(ControlParameter::Occlusion);
  }
  EXPECT_EQ(failures, 0) << "pictures of the failing cases are in " << test::outputPath("");
}

}  // namespace
}  // namespace npr
