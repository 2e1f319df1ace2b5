// GL tier: two-dimensional palettes (palette.h's axis, X-Toon). On generated scenes whose
// geometry says which row each surface point needs: two spheres at different distances take
// the near and the far row whole in every path; on one sphere every pixel of the per-pixel
// paths takes the row its own distance or facing gives (the renderer's CPU formula, fed the
// interpolated eye-space position and normal the pass sees), the per-triangle paths agree
// with it away from row boundaries, the column stays the one the tone picks, and the smooth
// path blends neighbouring rows by the position between them.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "support/test_util.h"

namespace npr {
namespace {

using RowsFixture = test::RendererFixture;
constexpr int kSize = 160;
constexpr int kColumns = 3;

// Rows of kColumns greys, white to black; row r's texels keep red and scale green and blue by
// 1 - r / (rows - 1), so the colour tells the row (the first row grey, the last red).
Palette rowsPalette(PaletteAxisKind kind, float from, float to, int rows) {
  Palette p;
  p.name = "rows";
  for (int r = 0; r < rows; ++r) {
    const Palette ramp = test::greyRamp(kColumns);
    const float keep = rows > 1 ? 1.0f - float(r) / float(rows - 1) : 1.0f;
    for (PaletteEntry e : ramp.entries) {
      for (std::size_t k = 0; k < e.image.pixels.size(); k += 4) {
        e.image.pixels[k + 1] = std::uint8_t(std::lround(float(e.image.pixels[k + 1]) * keep));
        e.image.pixels[k + 2] = std::uint8_t(std::lround(float(e.image.pixels[k + 2]) * keep));
      }
      p.entries.push_back(std::move(e));
    }
  }
  p.axis = PaletteAxis{kind, from, to, rows};
  return p;
}

bool covered(const ImageRGBA32F& g, std::size_t i) { return g.pixels[4 * i + 2] != 0.0f; }
glm::vec3 at(const ImageRGBA32F& g, std::size_t i) { return glm::vec3(g.pixels[4 * i], g.pixels[4 * i + 1], g.pixels[4 * i + 2]); }

CameraMatrices lookFrom(const glm::vec3& eye) {
  CameraMatrices c;
  c.view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  c.projection = glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 20.0f);
  return c;
}

// Two small spheres on the x axis, one near the eye and one far: with the axis' ends between
// them, the near one is all first row and the far one all last row, in every path; the
// column is the one the same frame shows without the axis.
TEST_F(RowsFixture, TwoObjectsAtDifferentDistancesTakeTheirOwnRows) {
  const Mesh sphere = icosphere(3);
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(0.3f));
  r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, 0.0f, 0.0f)) * scale);
  r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(-0.9f, 0.0f, 0.0f)) * scale);
  // The scene's bounding sphere: centred at the origin, radius 1.2. Distances from the eye are
  // about 1.6 and 3.2, so 1.34 and 2.7 radii, each sphere +-0.25.
  const float radius = 1.2f;
  ASSERT_TRUE(r->palettes().setMain(rowsPalette(PaletteAxisKind::Depth, 1.8f, 2.2f, 2)));
  const CameraMatrices cam = lookFrom(glm::vec3(2.2f, 0.3f, 0.9f));
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel}) {
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 entries = test::renderEntries(*r, cam, s, kSize, kSize);
    EXPECT_NEAR(r->palettes().main()->axisMap().x, 1.0f / (0.4f * radius), 1e-4f) << "a depth axis counts in scene radii";
    s.paletteAxis = false;
    const ImageRGBA8 columns = test::renderEntries(*r, cam, s, kSize, kSize);
    int near = 0, far = 0, wrongRow = 0, wrongColumn = 0;
    for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
      if (!covered(pos, i)) continue;
      const bool isNear = glm::length(at(pos, i)) < 2.4f;
      (isNear ? near : far) += 1;
      const int layer = entries.pixels[4 * i];
      wrongRow += layer / kColumns != (isNear ? 0 : 1);
      wrongColumn += layer % kColumns != columns.pixels[4 * i];
    }
    EXPECT_GT(near, 300) << pathInfo(path).name;
    EXPECT_GT(far, 100) << pathInfo(path).name;
    EXPECT_EQ(wrongRow, 0) << pathInfo(path).name;
    EXPECT_EQ(wrongColumn, 0) << pathInfo(path).name;
  }
  // The stencil path draws the per-triangle choice as the triangle path does: the same picture.
  RenderSettings tri, stencil;
  tri.path = RenderPath::Triangle;
  stencil.path = RenderPath::Stencil;
  const ImageRGBA8 a = test::renderImage(*r, cam, tri, kSize, kSize), b = test::renderImage(*r, cam, stencil, kSize, kSize);
  EXPECT_LE(test::countDiffering(a, b), kSize * kSize / 500);
  // ... and its far sphere is red (the last row), its near one grey.
  int redFar = 0, far = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i)
    if (covered(pos, i) && glm::length(at(pos, i)) >= 2.4f && b.pixels[4 * i] > 40) {
      ++far;
      redFar += b.pixels[4 * i + 1] < 3;
    }
  EXPECT_GT(far, 50);
  EXPECT_EQ(redFar, far);
}

// Per-material detail (--material-detail): faces of a material with its own detail take that
// row, the others their object's, in every path; a material without a detail of its own follows
// the object's as it changes.
TEST_F(RowsFixture, EachMaterialsDetailPicksItsRow) {
  Mesh sphere = icosphere(3);
  sphere.materials.resize(2);
  sphere.materials[0].name = "west";
  sphere.materials[1].name = "east";
  for (std::size_t t = 0; t < sphere.triangleCount(); ++t) sphere.faceMaterials.push_back(sphere.faceCentroids[t].x < 0.0f ? 0 : 1);
  const ModelId id = r->scene().add(sphere);
  ASSERT_TRUE(r->palettes().setMain(rowsPalette(PaletteAxisKind::Detail, 0.0f, 1.0f, 3)));
  const CameraMatrices cam = lookFrom(glm::vec3(0.0f, 0.4f, 3.0f));
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  const glm::mat4 toObject = glm::inverse(cam.view);
  const auto rowsOf = [&](RenderPath path, int& westRow, int& eastRow) {
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 entries = test::renderEntries(*r, cam, s, kSize, kSize);
    westRow = eastRow = -1;
    for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
      if (!covered(pos, i)) continue;
      const float x = (toObject * glm::vec4(at(pos, i), 1.0f)).x;
      if (std::fabs(x) < 0.15f) continue;  // faces are split by their centroids: not near the seam
      int& row = x < 0.0f ? westRow : eastRow;
      const int got = entries.pixels[4 * i] / kColumns;
      row = row == -1 || row == got ? got : 99;  // 99: mixed rows on one material
    }
  };
  r->palettes().setMaterialDetail("west", 1.0f);
  EXPECT_TRUE(r->scene().setDetail(id, 0.5f));
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Stencil}) {
    int west = 0, east = 0;
    rowsOf(path, west, east);
    EXPECT_EQ(west, 2) << pathInfo(path).name;
    EXPECT_EQ(east, 1) << pathInfo(path).name;
  }
  EXPECT_TRUE(r->scene().setDetail(id, 0.0f));
  r->palettes().setMaterialDetail("west", 0.5f);
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Pixel}) {
    int west = 0, east = 0;
    rowsOf(path, west, east);
    EXPECT_EQ(west, 1) << pathInfo(path).name;
    EXPECT_EQ(east, 0) << pathInfo(path).name;
  }
}

// A palette with rows by detail: each object's own value picks its row, in every path, and
// changing it changes only that object's row.
TEST_F(RowsFixture, EachObjectsDetailPicksItsRow) {
  const Mesh sphere = icosphere(3);
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(0.4f));
  const ModelId left = r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, 0.0f, 0.0f)) * scale);
  const ModelId right = r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)) * scale);
  ASSERT_TRUE(r->palettes().setMain(rowsPalette(PaletteAxisKind::Detail, 0.0f, 1.0f, 3)));
  const CameraMatrices cam = lookFrom(glm::vec3(0.0f, 0.4f, 3.0f));
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  const auto rowsOf = [&](RenderPath path, int& leftRow, int& rightRow) {
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 entries = test::renderEntries(*r, cam, s, kSize, kSize);
    leftRow = rightRow = -1;
    for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
      if (!covered(pos, i)) continue;
      int& row = at(pos, i).x < 0.0f ? leftRow : rightRow;
      const int got = entries.pixels[4 * i] / kColumns;
      row = row == -1 || row == got ? got : 99;  // 99: mixed rows on one object
    }
  };
  EXPECT_TRUE(r->scene().setDetail(left, 1.0f));
  EXPECT_TRUE(r->scene().setDetail(right, 0.5f));
  EXPECT_FALSE(r->scene().setDetail(right + 100, 0.5f));
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel}) {
    int a = 0, b = 0;
    rowsOf(path, a, b);
    EXPECT_EQ(a, 2) << pathInfo(path).name;
    EXPECT_EQ(b, 1) << pathInfo(path).name;
  }
  // Only the changed object moves (the per-triangle rows are worked out again for it).
  EXPECT_TRUE(r->scene().setDetail(left, 0.0f));
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Pixel}) {
    int a = 0, b = 0;
    rowsOf(path, a, b);
    EXPECT_EQ(a, 0) << pathInfo(path).name;
    EXPECT_EQ(b, 1) << pathInfo(path).name;
  }
  // Out of range and not finite: clamped, and 0.
  EXPECT_TRUE(r->scene().setDetail(left, 7.0f));
  EXPECT_FLOAT_EQ(r->scene().find(left)->detail(), 1.0f);
  EXPECT_TRUE(r->scene().setDetail(left, std::nanf("")));
  EXPECT_FLOAT_EQ(r->scene().find(left)->detail(), 0.0f);
}

// Every pixel of the pixel and vertex paths takes the nearest row to its own axis value, by
// depth and by facing; the triangle path, choosing per triangle, agrees away from boundaries.
TEST_F(RowsFixture, EachPixelTakesTheRowItsDistanceOrFacingGives) {
  const Mesh sphere = icosphere(4);
  r->scene().add(sphere);
  const CameraMatrices cam = test::testCamera(1.0f);
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  const ImageRGBA32F nrm = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, kSize, kSize);
  struct Case {
    PaletteAxisKind kind;
    float from, to;
  };
  // The unit sphere seen from 3 radii: its visible depths 2 to 2.9, its facing 0 to 1.
  for (const Case c : {Case{PaletteAxisKind::Depth, 2.15f, 2.75f}, Case{PaletteAxisKind::Facing, 0.15f, 0.75f}}) {
    ASSERT_TRUE(r->palettes().setMain(rowsPalette(c.kind, c.from, c.to, 3)));
    for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Triangle}) {
      RenderSettings s;
      s.path = path;
      const ImageRGBA8 entries = test::renderEntries(*r, cam, s, kSize, kSize);
      int checked = 0, wrong = 0, rowCount[3] = {0, 0, 0};
      for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
        if (!covered(pos, i)) continue;
        const float want = r->palettes().main()->rowPosition(at(pos, i), at(nrm, i));
        // Per pixel: only where rounding is in doubt (the interpolated values of the two passes
        // agree to float rounding). Per triangle: a centroid's row may differ near a boundary.
        const float margin = path == RenderPath::Triangle ? 0.25f : 0.01f;
        if (std::abs(want - std::floor(want) - 0.5f) < margin) continue;
        const int row = entries.pixels[4 * i] / kColumns;
        ++checked;
        ++rowCount[std::min(row, 2)];
        wrong += row != int(want + 0.5f);
      }
      const char* name = pathInfo(path).name;
      EXPECT_GT(checked, kSize * kSize / 8) << name;
      for (int row = 0; row < 3; ++row) EXPECT_GT(rowCount[row], checked / 20) << name << " row " << row << " " << paletteAxisName(c.kind);
      if (path == RenderPath::Triangle) {
        EXPECT_LE(wrong, checked / 50) << name << " " << paletteAxisName(c.kind);
      } else {
        EXPECT_LE(wrong, checked / 1000) << name << " " << paletteAxisName(c.kind);
      }
    }
  }
}

// The smooth path blends the two rows about each pixel's position: with a grey first row and a
// red last row, green is the grey's share, 1 - position, wherever the pixel is lit.
TEST_F(RowsFixture, TheSmoothPathBlendsNeighbouringRows) {
  const Mesh sphere = icosphere(4);  // the renderer keeps a pointer to it
  r->scene().add(sphere);
  const CameraMatrices cam = test::testCamera(1.0f);
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  const ImageRGBA32F nrm = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, kSize, kSize);
  ASSERT_TRUE(r->palettes().setMain(rowsPalette(PaletteAxisKind::Facing, 0.2f, 0.8f, 2)));
  RenderSettings s;
  s.path = RenderPath::Smooth;
  const ImageRGBA8 img = test::renderImage(*r, cam, s, kSize, kSize);
  int checked = 0, between = 0, wrong = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
    const float red = img.pixels[4 * i] / 255.0f, green = img.pixels[4 * i + 1] / 255.0f;
    if (!covered(pos, i) || red < 0.25f) continue;
    const float f = r->palettes().main()->rowPosition(at(pos, i), at(nrm, i));
    ++checked;
    between += f > 0.1f && f < 0.9f;
    wrong += std::abs(green - (1.0f - f) * red) > 4.0f / 255.0f;
  }
  EXPECT_GT(checked, kSize * kSize / 8);
  EXPECT_GT(between, checked / 5);
  EXPECT_LE(wrong, checked / 200);
}

}  // namespace
}  // namespace npr
