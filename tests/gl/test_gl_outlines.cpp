// Hardware outlines and the charcoal rim (lines/hardware_outline_pass.h) on the headless
// context: each method draws ink only at and outside the silhouette, where the object-space
// silhouettes are, at the width asked for (the fattened and edge methods), and the rim only
// near the silhouette. The same measures at full size, with frame costs, are bench_styles.
// Hidden lines (--hidden-lines) are drawn only where the surface hides them, dashed.
// Intersection lines are drawn where two objects cross and nowhere else, found again when an
// object moves and not when the camera does. Line sets draw the kinds and parts they select in
// their own colour and width; strokes taper and dash along their whole chain of edges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "renderer/core/image_io.h"
#include "renderer/lines/stroke_textures.h"
#include "renderer/strokes/brush_shapes.h"
#include "renderer/mesh/mesh_builder.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/settings/choice_names.h"
#include "support/line_comparison.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::lineMask;
using test::LineMask;

constexpr int kSize = 320;

// One white entry on a white ground: the model disappears and only lines are ink.
Palette whitePalette() {
  Palette p = test::greyRamp(2);
  p.entries.resize(1);
  return p;
}

// A box with its corners at `lo` and `hi`, closed, twelve triangles.
Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 corners[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  std::vector<std::array<int, 3>> tris;
  for (const auto& f : faces) tris.push_back({f[0], f[1], f[2]});
  std::vector<glm::vec3> at;
  for (const glm::vec3& c : corners) at.push_back(glm::mix(lo, hi, 0.5f * (c + 1.0f)));
  Mesh m;
  buildTriMesh(at, tris, m);
  finalizeMesh(m);
  return m;
}

struct OutlineFixture : test::RendererFixture {
  Mesh sphere = icosphere(4), bunny;
  void SetUp() override {
    test::RendererFixture::SetUp();
    ASSERT_TRUE(r->palettes().setMain(whitePalette()));
    Result<Mesh> m = loadMesh(test::sourcePath("models/bunny.obj"));
    ASSERT_TRUE(m) << m.error();
    bunny = std::move(*m);
  }
  ImageRGBA8 draw(const Mesh& mesh, const LineSettings& lines) {
    r->scene().setOnly(&mesh);
    RenderSettings s;
    s.lines = lines;
    return test::renderImage(*r, test::testCamera(1.0f), s, kSize, kSize);
  }
  static LineSettings hardware(OutlineMethod m) {
    LineSettings l;
    l.hardware = true;
    l.outline = m;
    l.width = 3.0f;
    return l;
  }
  static LineSettings silhouettes() {
    LineSettings l;
    l.silhouettes = true;
    l.width = 3.0f;
    return l;
  }
  // The model's own pixels, eroded by `margin`: where no outline may draw.
  LineMask interior(const Mesh& mesh, int margin) {
    r->scene().setOnly(&mesh);
    const ImageRGBA32F eye = test::renderGeometry(*r, test::testCamera(1.0f), FrameOutput::EyePosition, kSize, kSize);
    LineMask m{kSize, kSize, std::vector<char>(std::size_t(kSize) * kSize)};
    auto covered = [&](int x, int y) {
      return x >= 0 && y >= 0 && x < kSize && y < kSize && eye.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4 + 3] != 0.0f;
    };
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        bool inside = true;
        for (int dy = -margin; dy <= margin && inside; ++dy)
          for (int dx = -margin; dx <= margin && inside; ++dx) inside = covered(x + dx, y + dy);
        m.ink[std::size_t(y) * kSize + std::size_t(x)] = inside;
      }
    return m;
  }
};

int overlap(const LineMask& a, const LineMask& b) {
  int n = 0;
  for (std::size_t i = 0; i < a.ink.size(); ++i) n += a.ink[i] && b.ink[i];
  return n;
}

TEST_F(OutlineFixture, EveryMethodInksOnlyAtTheSilhouette) {
  const LineMask inside = interior(sphere, 3);
  ASSERT_GT(inside.count(), kSize * kSize / 10);
  for (OutlineMethod m : {OutlineMethod::Fatten, OutlineMethod::Edges, OutlineMethod::Offset}) {
    SCOPED_TRACE(choiceName(m));
    const LineMask ink = lineMask(draw(sphere, hardware(m)));
    if (m != OutlineMethod::Offset) {
      EXPECT_GT(ink.count(), 300);  // a ring around a disc of about 100 pixels' radius
    }
    EXPECT_EQ(overlap(ink, inside), 0);
  }
}

// The offset method shows back faces where they come within k z of the front faces: nothing
// reaches past the silhouette on screen (moving a face along the rays does not move where it
// projects), so its lines lie inside it and widen with k, unevenly.
TEST_F(OutlineFixture, OffsetOutlinesWidenWithTheOffset) {
  const LineMask inside = interior(sphere, 3);
  int previous = 0;
  for (float k : {0.005f, 0.02f, 0.08f}) {
    LineSettings l = hardware(OutlineMethod::Offset);
    l.outlineOffset = k;
    const LineMask ink = lineMask(draw(sphere, l));
    const LineMask plain = lineMask(draw(sphere, LineSettings{}));
    std::printf("offset %.3f: %d ink pixels, %d of them in the interior\n", double(k), ink.count(), overlap(ink, inside));
    EXPECT_EQ(plain.count(), 0);
    EXPECT_GT(ink.count(), previous);
    previous = ink.count();
  }
}

TEST_F(OutlineFixture, FattenedAndEdgeOutlinesAgreeWithObjectSpaceSilhouettes) {
  for (const Mesh* mesh : {&sphere, &bunny}) {
    const LineMask object = lineMask(draw(*mesh, silhouettes()));
    for (OutlineMethod m : {OutlineMethod::Fatten, OutlineMethod::Edges}) {
      const LineMask hw = lineMask(draw(*mesh, hardware(m)));
      const double objectNearHardware = test::nearShare(object, hw, 1), hardwareNearObject = test::nearShare(hw, object, 1);
      std::printf("%s %s: object-space near hardware %.3f, hardware near object-space %.3f\n", mesh == &sphere ? "sphere" : "bunny",
                  choiceName(m), objectNearHardware, hardwareNearObject);
      // Measured 0.996-1.000 and (fatten) 0.93-0.94, (edges) 0.84-0.89: the edge quads of back
      // faces next to the silhouette reach past it too. (Before the joints inked each pixel once,
      // 0.96 and 0.88-0.92: the rims blended twice at every joint counted as ink; the bunny's
      // silhouettes have 8% fewer pixels over half ink since.)
      EXPECT_GT(objectNearHardware, 0.95);
      EXPECT_GT(hardwareNearObject, m == OutlineMethod::Fatten ? 0.92 : 0.82);
    }
  }
}

TEST_F(OutlineFixture, FattenedOutlinesAreAsWideAsAsked) {
  r->scene().setOnly(&bunny);
  const CameraMatrices cam = test::testCamera(1.0f);
  RenderSettings s;
  s.lines = silhouettes();
  const std::vector<FeatureLine> edges = r->featureLines(cam, s);
  for (float width : {2.0f, 5.0f}) {
    LineSettings l = hardware(OutlineMethod::Fatten);
    l.width = width;
    const test::Spread w = test::spreadOf(test::widthsAcross(lineMask(draw(bunny, l)), edges, cam));
    std::printf("fatten %.0f px: median %.1f, p10 %.1f, p90 %.1f over %d edges\n", double(width), double(w.median), double(w.p10),
                double(w.p90), w.samples);
    ASSERT_GT(w.samples, 100);
    EXPECT_NEAR(w.median, width, 1.0f);
    EXPECT_LE(w.p90 - w.p10, width);
  }
}

TEST_F(OutlineFixture, CharcoalRimDrawsTheDarkToneAroundTheSilhouetteOnly) {
  ASSERT_TRUE(r->palettes().setMain(test::greyRamp(4)));  // white, 2/3, 1/3, black: the rim's tone 1/3..0.37 is 1/3 grey
  ASSERT_TRUE(r->lighting().setToneModel(ToneModel::Charcoal, ToneParameters{}));
  LineSettings plain;
  LineSettings rim;
  rim.rim = true;
  rim.width = 4.0f;
  const ImageRGBA8 without = draw(sphere, plain), with = draw(sphere, rim);
  const LineMask inside = interior(sphere, 6);
  int changedInside = 0, changedOutside = 0, darkRim = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4;
      if (without.pixels[i] == with.pixels[i]) continue;
      (inside.at(x, y) ? changedInside : changedOutside)++;
      darkRim += with.pixels[i] < 100;  // 1/3 grey, 85
    }
  std::printf("rim: %d pixels changed outside the interior, %d inside, %d dark\n", changedOutside, changedInside, darkRim);
  EXPECT_GT(changedOutside, 500);
  EXPECT_EQ(changedInside, 0);
  EXPECT_GT(darkRim, changedOutside * 9 / 10);
}

TEST_F(OutlineFixture, HiddenLinesAreDrawnDashedOnlyWhereTheSurfaceHidesThem) {
  // A closed cube seen from above and aside: three of its twelve edges are behind it.
  const Mesh cube = boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f));
  LineSettings l;
  l.creases = true;
  l.creaseColour = glm::vec3(0.0f);
  l.width = 2.0f;
  const LineMask visible = lineMask(draw(cube, l));
  l.hidden = true;
  const LineMask both = lineMask(draw(cube, l));
  const LineMask inside = interior(cube, 0);
  int added = 0, outside = 0, lost = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (visible.at(x, y) && !both.at(x, y)) ++lost;
      if (!both.at(x, y) || visible.at(x, y)) continue;
      ++added;
      outside += !inside.at(x, y);
    }
  std::printf("visible crease ink %d pixels; hidden lines add %d, %d of them off the cube\n", visible.count(), added, outside);
  EXPECT_EQ(lost, 0) << "the visible lines changed";
  EXPECT_GT(added, 100) << "no hidden lines";
  EXPECT_EQ(outside, 0) << "hidden lines drawn where nothing hides them";
  // Three hidden edges, dashed and thinner, against nine solid visible ones.
  EXPECT_LT(added, visible.count() / 3);
}


TEST_F(OutlineFixture, IntersectionLinesDrawWhereTwoObjectsCrossOnly) {
  // A box and a bar through its face x = 0.5: they cross along the square x = 0.5, |y|, |z| <= 0.25.
  const Mesh cube = boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f)), bar = boxMesh({-0.5f, -0.25f, -0.25f}, {0.5f, 0.25f, 0.25f});
  r->scene().setOnly(&cube);
  const ModelId barId = r->scene().add(bar, glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)));
  RenderSettings s;
  s.lines.intersections = true;
  s.lines.intersectionColour = glm::vec3(1.0f, 0.0f, 0.0f);
  s.lines.width = 2.0f;
  const CameraMatrices cam = test::testCamera(1.0f, 60.0f, 25.0f);
  // Red ink, and how far each red pixel is from the square's outline on the screen.
  auto redAwayFrom = [&](const ImageRGBA8& img, const glm::vec3& squareCentre, int& red) {
    const glm::vec3 c[4] = {squareCentre + glm::vec3(0, -0.25f, -0.25f), squareCentre + glm::vec3(0, 0.25f, -0.25f),
                            squareCentre + glm::vec3(0, 0.25f, 0.25f), squareCentre + glm::vec3(0, -0.25f, 0.25f)};
    glm::vec2 w[4];
    for (int k = 0; k < 4; ++k) {
      const glm::vec4 p = cam.projection * cam.view * glm::vec4(c[k], 1.0f);
      w[k] = (glm::vec2(p) / p.w * 0.5f + 0.5f) * float(kSize);
      w[k].y = float(kSize) - w[k].y;  // rows top first
    }
    red = 0;
    float farthest = 0.0f;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const std::uint8_t* px = &img.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
        if (!(px[0] > 150 && px[1] < 110 && px[2] < 110)) continue;
        ++red;
        const glm::vec2 q(float(x) + 0.5f, float(y) + 0.5f);
        float nearest = INFINITY;
        for (int k = 0; k < 4; ++k) {
          const glm::vec2 a = w[k], d = w[(k + 1) % 4] - a;
          const float t = std::clamp(glm::dot(q - a, d) / glm::dot(d, d), 0.0f, 1.0f);
          nearest = std::min(nearest, glm::length(q - (a + t * d)));
        }
        farthest = std::max(farthest, nearest);
      }
    return farthest;
  };
  int red = 0;
  const float away = redAwayFrom(test::renderImage(*r, cam, s, kSize, kSize), glm::vec3(0.5f, 0, 0), red);
  EXPECT_EQ(r->stats().intersectionSearches, 1);
  std::printf("intersection lines: %d red pixels, the farthest %.2f px from the crossing's square\n", red, double(away));
  EXPECT_GT(red, 150) << "the square where the bar enters the box is about 4 x 40 px of line";
  EXPECT_LT(away, 2.5f) << "red ink away from where the objects cross";
  // The camera moves: nothing is searched again. The bar moves: its new crossing is drawn.
  (void)test::renderImage(*r, test::testCamera(1.0f, 50.0f, 25.0f), s, kSize, kSize);
  EXPECT_EQ(r->stats().intersectionSearches, 0);
  ASSERT_TRUE(r->scene().setTransform(barId, glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.15f, 0.0f))));
  const float moved = redAwayFrom(test::renderImage(*r, cam, s, kSize, kSize), glm::vec3(0.5f, 0.15f, 0), red);
  EXPECT_EQ(r->stats().intersectionSearches, 1);
  EXPECT_GT(red, 150);
  EXPECT_LT(moved, 2.5f);
  // Off: no red at all.
  s.lines.intersections = false;
  (void)redAwayFrom(test::renderImage(*r, cam, s, kSize, kSize), glm::vec3(0.5f, 0.15f, 0), red);
  EXPECT_EQ(red, 0);
}

TEST_F(OutlineFixture, LineSetsDrawTheirKindsAndPartsInTheirOwnStyle) {
  // A cube: its silhouettes in one set (red), its creases in another (blue, thin), its hidden
  // edges in a third (green, dashed). `lines none`: only the sets draw.
  const Mesh cube = boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f));
  auto count = [&](const ImageRGBA8& img, int channel) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
      const int c = img.pixels[i + std::size_t(channel)], o1 = img.pixels[i + std::size_t((channel + 1) % 3)], o2 = img.pixels[i + std::size_t((channel + 2) % 3)];
      n += c > 150 && o1 < 110 && o2 < 110;
    }
    return n;
  };
  LineSettings l;
  std::string why;
  ASSERT_TRUE(parseLineSets("silhouette width=2 colour=1,0,0", l.sets, &why)) << why;
  const ImageRGBA8 thin = draw(cube, l);
  ASSERT_TRUE(parseLineSets("silhouette width=6 colour=1,0,0", l.sets, &why)) << why;
  const ImageRGBA8 wide = draw(cube, l);
  ASSERT_TRUE(parseLineSets("silhouette width=6 colour=1,0,0; crease width=1 colour=0,0,1; silhouette,crease visibility=hidden width=2 colour=0,1,0 dash=4,4",
                            l.sets, &why)) << why;
  const ImageRGBA8 three = draw(cube, l);
  const LineMask inside = interior(cube, 0);
  int greenOutside = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::uint8_t* px = &three.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
      greenOutside += px[1] > 150 && px[0] < 110 && px[2] < 110 && !inside.at(x, y);
    }
  std::printf("line sets: silhouettes %d px at width 2, %d at width 6; creases %d px; hidden %d px (%d off the cube)\n", count(thin, 0), count(wide, 0),
              count(three, 2), count(three, 1), greenOutside);
  EXPECT_EQ(count(thin, 2) + count(thin, 1), 0) << "a silhouette set drew other kinds";
  EXPECT_GT(count(thin, 0), 200);
  EXPECT_NEAR(double(count(wide, 0)) / count(thin, 0), 3.0, 0.8) << "width is the set's";
  EXPECT_GT(count(three, 2), 50) << "the crease set drew nothing";
  EXPECT_GT(count(three, 1), 30) << "the hidden set drew nothing";
  EXPECT_EQ(greenOutside, 0) << "hidden lines drawn where nothing hides them";
  // A set that draws only the hidden parts adds nothing visible: without it, no green at all.
  l.sets.pop_back();
  EXPECT_EQ(count(draw(cube, l), 1), 0);
}

// Hidden lines limited by occlusion level (occlusion=LEVEL): a box's far edges lie behind one
// surface (its near side) and stay at level 1; a box inside another is behind the outer box's
// near side and, for its far edges, its own near side too (level 2).
TEST_F(OutlineFixture, HiddenLinesStopAtTheirOcclusionLevel) {
  const Mesh outer = boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f)), inner = boxMesh(glm::vec3(-0.2f), glm::vec3(0.2f));
  auto green = [&](const std::string& sets, bool nested, const char* picture = nullptr) {
    LineSettings l;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, l.sets, &why)) << why;
    r->scene().setOnly(&outer);
    if (nested) (void)r->scene().add(inner, glm::mat4(1.0f));
    RenderSettings s;
    s.lines = l;
    const ImageRGBA8 img = test::renderImage(*r, test::testCamera(1.0f), s, kSize, kSize);
    if (picture) {
      EXPECT_TRUE(writeImage(test::outputPath(picture), img));
    }
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) n += img.pixels[i + 1] > 150 && img.pixels[i] < 110 && img.pixels[i + 2] < 110;
    return n;
  };
  const std::string hidden = "silhouette,crease visibility=hidden width=2 colour=0,1,0";
  const int aloneAll = green(hidden, false), aloneLevel1 = green(hidden + " occlusion=1", false);
  const int nestedAll = green(hidden, true, "occlusion-all.png"), nested1 = green(hidden + " occlusion=1", true, "occlusion-1.png"),
            nested2 = green(hidden + " occlusion=2", true, "occlusion-2.png");
  std::printf("hidden line pixels: one box %d (all), %d (level 1); box in a box %d (all), %d (level 1), %d (level 2)\n", aloneAll, aloneLevel1,
              nestedAll, nested1, nested2);
  EXPECT_GT(aloneAll, 100);
  // One box: every hidden edge is behind its near side only.
  EXPECT_GE(aloneLevel1, aloneAll * 95 / 100);
  // Box in a box: level 1 leaves out the inner box's far edges (and what the inner box hides of
  // the outer's), level 2 brings back more, and all of them more still.
  EXPECT_LT(nested1, nestedAll * 90 / 100);
  EXPECT_GT(nested2, nested1 + 20);
  EXPECT_GE(nestedAll, nested2);
}

// A roof: a ridge along x (64 edges of about 4 pixels here) between two slopes at right angles,
// its crease one open chain.
Mesh roofMesh() {
  const int n = 64, m = 8;
  std::vector<glm::vec3> at;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = -0.8f + 1.6f * float(i) / float(n), z = -0.6f + 1.2f * float(j) / float(m);
      at.push_back({x, 0.2f - std::fabs(z), z});
    }
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      tris.push_back({a, c, b});
      tris.push_back({b, c, d});
    }
  Mesh mesh;
  buildTriMesh(at, tris, mesh);
  finalizeMesh(mesh);
  return mesh;
}

TEST_F(OutlineFixture, StrokesTaperAndDashAlongTheirWholeChain) {
  const Mesh roof = roofMesh();
  // Ink per column over the ridge's span: the ridge runs across the picture.
  struct Profile {
    int left = -1, right = -1;
    std::vector<int> ink;
  };
  auto profile = [&](const char* sets) {
    LineSettings l;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, l.sets, &why)) << why;
    const LineMask mask = lineMask(draw(roof, l));
    Profile p;
    p.ink.assign(kSize, 0);
    for (int x = 0; x < kSize; ++x) {
      for (int y = 0; y < kSize; ++y) p.ink[std::size_t(x)] += mask.at(x, y);
      if (p.ink[std::size_t(x)] > 0) {
        if (p.left < 0) p.left = x;
        p.right = x;
      }
    }
    return p;
  };
  const auto mean = [](const Profile& p, int from, int to) {
    double sum = 0.0;
    for (int x = from; x <= to; ++x) sum += p.ink[std::size_t(x)];
    return sum / double(to - from + 1);
  };
  const Profile blunt = profile("crease width=8 colour=0,0,0"), tapered = profile("crease width=8 taper=40 colour=0,0,0");
  ASSERT_GT(blunt.right - blunt.left, 150) << "the ridge is not across the picture";
  const int mid = (blunt.left + blunt.right) / 2;
  const double bluntEnds = 0.5 * (mean(blunt, blunt.left, blunt.left + 8) + mean(blunt, blunt.right - 8, blunt.right));
  const double taperEnds = 0.5 * (mean(tapered, blunt.left, blunt.left + 8) + mean(tapered, blunt.right - 8, blunt.right));
  const double bluntMid = mean(blunt, mid - 10, mid + 10), taperMid = mean(tapered, mid - 10, mid + 10);
  std::printf("taper: ink a column at the ends %.1f px tapered, %.1f blunt; in the middle %.1f and %.1f\n", taperEnds, bluntEnds, taperMid, bluntMid);
  EXPECT_LT(taperEnds, 0.5 * bluntEnds) << "the stroke does not narrow at its ends";
  EXPECT_NEAR(taperMid, bluntMid, 0.15 * bluntMid) << "the taper reaches into the middle of the stroke";
  // Dashes 8 on, 8 off along the whole stroke: about half its columns inked. Restarted at every
  // 4-pixel edge they would all be ink.
  const Profile dashed = profile("crease width=3 dash=8,8 colour=0,0,0");
  int inked = 0, span = 0;
  for (int x = blunt.left + 4; x <= blunt.right - 4; ++x, ++span) inked += dashed.ink[std::size_t(x)] > 0;
  std::printf("dashes 8,8 along the ridge: %d of %d columns inked\n", inked, span);
  EXPECT_GT(inked, span * 3 / 10);
  EXPECT_LT(inked, span * 7 / 10) << "dashes restart at each edge instead of running along the stroke";
}

// The joints of a chain ink each pixel once: the segments' quads reach half a width past their
// ends, and blending a partial coverage twice where they overlap left a darker bead at every
// joint (lines.vert's joint cuts). Along the roof's straight ridge (63 joints, about 4 pixels
// apart) the ink a column gets is then as even as along one quad; on a many-sided polygon the
// thin lines' darkest pixel is no darker than one quad's coverage.
TEST_F(OutlineFixture, AChainsJointsInkEachPixelOnce) {
  // A flat strip face on, turned 10 degrees, its long sides 64 collinear edges of about 3.5
  // pixels: the upper side's ink per column, over the middle of the picture.
  const int n = 64;
  std::vector<glm::vec3> at;
  const float c = std::cos(0.1745f), sn = std::sin(0.1745f);
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = -0.8f + 1.6f * float(i) / float(n), y = j ? 0.3f : -0.3f;
      at.push_back({c * x - sn * y, sn * x + c * y, 0.0f});
    }
  std::vector<std::array<int, 3>> tris;
  for (int i = 0; i < n; ++i) {
    tris.push_back({i, i + 1, i + n + 2});
    tris.push_back({i, i + n + 2, i + n + 1});
  }
  Mesh strip;
  buildTriMesh(at, tris, strip);
  finalizeMesh(strip);
  const CameraMatrices faceOn = test::testCamera(1.0f, 0.0f, 0.0f);
  r->scene().setOnly(&strip);
  RenderSettings s;
  const ImageRGBA8 plain = test::renderImage(*r, faceOn, s, kSize, kSize);
  std::string why;
  ASSERT_TRUE(parseLineSets("boundary width=3 colour=0,0,0", s.lines.sets, &why)) << why;
  const ImageRGBA8 lined = test::renderImage(*r, faceOn, s, kSize, kSize);
  auto darkness = [&](const ImageRGBA8& img, const ImageRGBA8& under, std::size_t i) {
    return std::max(0.0, (double(under.pixels[i * 4 + 1]) - double(img.pixels[i * 4 + 1])) / 255.0);
  };
  // The upper side runs from about y = 0.12 to 0.40 of the picture (the image's rows run down).
  std::vector<double> column(kSize, 0.0);
  for (int x = kSize / 4; x < 3 * kSize / 4; ++x)
    for (int y = 0; y < kSize / 2; ++y) column[std::size_t(x)] += darkness(lined, plain, std::size_t(y) * kSize + std::size_t(x));
  double sum = 0.0, squares = 0.0;
  int count = 0;
  for (int x = kSize / 4; x < 3 * kSize / 4; ++x, ++count) {
    sum += column[std::size_t(x)];
    squares += column[std::size_t(x)] * column[std::size_t(x)];
  }
  const double mean = sum / count, spread = std::sqrt(std::max(0.0, squares / count - mean * mean)) / mean;
  std::printf("ink a column along a straight chain 3 pixels wide: mean %.3f, spread %.4f of it\n", mean, spread);
  EXPECT_NEAR(mean, 3.0 / std::cos(0.1745), 0.1) << "the line is not as wide as asked";
  EXPECT_LT(spread, 0.01) << "the joints ink their overlapping pixels more than once";

  // A 48-sided polygon, face on, its boundary 0.5 pixels wide: one quad's coverage is at most
  // 0.75 at the line's centre, two blended where they overlap up to 0.94.
  const int sides = 48;
  at.assign(1, glm::vec3(0.0f));
  tris.clear();
  for (int i = 0; i < sides; ++i) {
    const float a = 6.2831853f * float(i) / float(sides);
    at.push_back({0.8f * std::cos(a), 0.8f * std::sin(a), 0.0f});
    tris.push_back({0, 1 + i, 1 + (i + 1) % sides});
  }
  Mesh polygon;
  buildTriMesh(at, tris, polygon);
  finalizeMesh(polygon);
  r->scene().setOnly(&polygon);
  s = RenderSettings{};
  const ImageRGBA8 flat = test::renderImage(*r, faceOn, s, kSize, kSize);
  ASSERT_TRUE(parseLineSets("boundary width=0.5 colour=0,0,0", s.lines.sets, &why)) << why;
  const ImageRGBA8 ring = test::renderImage(*r, faceOn, s, kSize, kSize);
  double darkest = 0.0;
  int inked = 0;
  for (std::size_t i = 0; i < std::size_t(kSize) * kSize; ++i) {
    const double d = std::max(0.0, (double(flat.pixels[i * 4 + 1]) - double(ring.pixels[i * 4 + 1])) / 255.0);
    darkest = std::max(darkest, d);
    inked += d > 0.05;
  }
  std::printf("a %d-gon's thin boundary: darkest pixel %.3f of full ink, %d pixels inked\n", sides, darkest, inked);
  ASSERT_GT(inked, 500) << "the polygon's boundary is not drawn";
  EXPECT_LT(darkest, 0.78) << "a joint inked a pixel twice";
}

// A file's own points and lines (Mesh::dots and segments: glTF POINTS and LINES) are drawn
// with no feature lines asked for: a segment as a stroke of the line width, a dot round, two
// and a half widths across.
TEST_F(OutlineFixture, AFilesPointsAndLinesAreDrawnAsStrokesAndRoundDots) {
  Mesh marked = boxMesh(glm::vec3(-0.2f), glm::vec3(0.2f));
  marked.segments = {{-0.9f, -0.6f, 0.0f}, {0.9f, -0.6f, 0.0f}};
  marked.dots = {{0.0f, 0.7f, 0.0f}};
  LineSettings none;
  r->scene().setOnly(&marked);
  RenderSettings s;
  s.lines = none;
  s.lines.width = 4.0f;
  const CameraMatrices faceOn = test::testCamera(1.0f, 0.0f, 0.0f);
  const ImageRGBA8 img = test::renderImage(*r, faceOn, s, kSize, kSize);
  Mesh bare = boxMesh(glm::vec3(-0.2f), glm::vec3(0.2f));
  r->scene().setOnly(&bare);
  const ImageRGBA8 plain = test::renderImage(*r, faceOn, s, kSize, kSize);
  // Ink per row and per column in the lower and upper thirds.
  double lineInk = 0.0, dotInk = 0.0;
  int lineRows = 0, dotLeft = kSize, dotRight = -1, dotTop = kSize, dotBottom = -1;
  std::vector<double> rowInk(kSize, 0.0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4 + 1;
      const double d = std::max(0.0, (double(plain.pixels[i]) - double(img.pixels[i])) / 255.0);
      if (y > 2 * kSize / 3) {
        lineInk += d;
        rowInk[std::size_t(y)] += d;
      } else if (y < kSize / 3) {
        dotInk += d;
        if (d > 0.5) dotLeft = std::min(dotLeft, x), dotRight = std::max(dotRight, x), dotTop = std::min(dotTop, y), dotBottom = std::max(dotBottom, y);
      }
    }
  for (double v : rowInk) lineRows += v > 1.0;
  std::printf("segment: ink %.1f over %d rows; dot: ink %.1f, %d x %d pixels over half ink\n", lineInk, lineRows, dotInk,
              dotRight - dotLeft + 1, dotBottom - dotTop + 1);
  // The segment spans 0.9 of the picture's width at 4 pixels: about 4 x 290 of ink over 4 or 5 rows.
  EXPECT_GT(lineInk, 0.8 * 4.0 * 0.9 * kSize) << "the file's line is not drawn";
  EXPECT_LT(lineInk, 1.25 * 4.0 * 0.9 * kSize);
  EXPECT_LE(lineRows, 6);
  // The dot: 10 pixels across, round: pi 25 of ink, not the 100 of a square.
  EXPECT_NEAR(dotRight - dotLeft + 1, 10, 1) << "the dot is not two and a half widths across";
  EXPECT_NEAR(dotBottom - dotTop + 1, 10, 1);
  EXPECT_NEAR(dotInk, 3.14159 * 25.0, 8.0) << "the dot is not round";
}

// A set's texture runs once along the whole chain, from one end to the other, and each pixel
// gets the texture's coverage once: the segments' overlapping caps at the ridge's 63 joints
// (each pixel lies under three quads) must not blend it again.
TEST_F(OutlineFixture, AStrokeTextureIsStretchedOnceAlongTheChainAndInkedOnce) {
  const Mesh roof = roofMesh();
  const std::string dir = ::testing::TempDir();
  auto texture = [&](const char* name, auto coverage) {
    ImageRGBA8 img{128, 16, std::vector<std::uint8_t>(128 * 16 * 4, 255)};
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        img.pixels[(std::size_t(y) * 128 + std::size_t(x)) * 4 + 3] = std::uint8_t(std::lround(255.0 * coverage(x)));
    const std::string path = dir + "/" + name + ".png";
    EXPECT_TRUE(writeImage(path, img));
    return path;
  };
  const std::string ramp = texture("stroke-ramp", [](int x) { return 1.0 - double(x) / 127.0; });
  const std::string half = texture("stroke-half", [](int) { return 0.5; });
  // Darkness the lines add, per column and at the stroke's darkest row of each column.
  LineSettings none;
  const ImageRGBA8 plain = draw(roof, none);
  struct Ink {
    std::vector<double> column, peak;
  };
  auto ink = [&](const std::string& sets) {
    LineSettings l;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, l.sets, &why)) << why;
    const ImageRGBA8 img = draw(roof, l);
    Ink out{std::vector<double>(kSize, 0.0), std::vector<double>(kSize, 0.0)};
    for (int x = 0; x < kSize; ++x)
      for (int y = 0; y < kSize; ++y) {
        const std::size_t i = (std::size_t(y) * kSize + std::size_t(x)) * 4 + 1;
        const double d = std::max(0.0, (double(plain.pixels[i]) - double(img.pixels[i])) / 255.0);
        out.column[std::size_t(x)] += d;
        // As a share of what full ink adds there (the plain picture's own brightness).
        if (plain.pixels[i] > 40) out.peak[std::size_t(x)] = std::max(out.peak[std::size_t(x)], d * 255.0 / double(plain.pixels[i]));
      }
    return out;
  };
  const Ink solid = ink("crease width=8 colour=0,0,0");
  int left = -1, right = -1;
  for (int x = 0; x < kSize; ++x)
    if (solid.column[std::size_t(x)] > 1.0) {
      if (left < 0) left = x;
      right = x;
    }
  ASSERT_GT(right - left, 150) << "the ridge is not across the picture";
  const int eighth = (right - left) / 8;
  auto mean = [](const std::vector<double>& v, int from, int to) {
    double sum = 0.0;
    for (int x = from; x <= to; ++x) sum += v[std::size_t(x)];
    return sum / double(to - from + 1);
  };
  const Ink ramped = ink("crease width=8 colour=0,0,0 texture=" + ramp);
  const double a = mean(ramped.column, left + 4, left + eighth), b = mean(ramped.column, right - eighth, right - 4);
  const double middle = mean(ramped.column, (left + right) / 2 - eighth / 2, (left + right) / 2 + eighth / 2);
  std::printf("a ramp along the ridge: ink a column %.2f at one end, %.2f in the middle, %.2f at the other (solid %.2f)\n", a, middle, b,
              mean(solid.column, left + 4, right - 4));
  EXPECT_GT(std::max(a, b), 5.0 * std::min(a, b)) << "the texture does not run from one end of the chain to the other";
  EXPECT_GT(middle, 1.5 * std::min(a, b));
  EXPECT_LT(middle, 0.75 * std::max(a, b)) << "the texture restarts along the chain";
  const Ink halfInk = ink("crease width=8 colour=0,0,0 texture=" + half);
  const double peak = mean(halfInk.peak, left + eighth, right - eighth), solidPeak = mean(solid.peak, left + eighth, right - eighth);
  std::printf("half coverage: %.2f of full ink at the stroke's centre (solid %.2f)\n", peak, solidPeak);
  EXPECT_NEAR(peak, 0.5 * solidPeak, 0.08) << "overlapping segments inked a pixel more than once";
}

// A texture file that cannot be read when the frame draws (removed after it was checked) is
// reported once, naming it; the set then draws plain lines, and the brush always loads.
TEST_F(OutlineFixture, AStrokeTextureThatFailsIsReportedOnceAndItsSetDrawsPlain) {
  StrokeTextures textures;
  const std::string gone = ::testing::TempDir() + "/no-such-stroke.png";
  Result<StrokeTexture> first = textures.find(gone);
  ASSERT_FALSE(first);
  EXPECT_NE(first.error().find("no-such-stroke.png"), std::string::npos) << first.error();
  Result<StrokeTexture> again = textures.find(gone);
  ASSERT_TRUE(again) << "reported twice";
  EXPECT_EQ(again->id, 0u);
  Result<StrokeTexture> brush = textures.find("brush");
  ASSERT_TRUE(brush) << brush.error();
  EXPECT_NE(brush->id, 0u);
  Result<StrokeCoverage> coverage = strokeCoverage("brush");
  ASSERT_TRUE(coverage);
  EXPECT_EQ(coverage->width, kBrushLength);
  EXPECT_EQ(coverage->height, kBrushWidth);
}

// colour=tone: a sphere lit from the right (eye space) with a two-entry palette whose bright
// entry averages yellow and dark entry navy: its silhouette set draws yellow on the lit right
// and navy on the unlit left, and a set with a fixed colour neither.
TEST_F(OutlineFixture, ALineSetColouredByToneTakesThePaletteEntryOfTheLitToneAtTheLine) {
  Palette p = test::greyRamp(2);
  p.entries[0].average = glm::vec3(1.0f, 1.0f, 0.2f);
  p.entries[1].average = glm::vec3(0.0f, 0.0f, 0.3f);
  ASSERT_TRUE(r->palettes().setMain(p));
  const float side[4] = {1, 0, 0, 0};
  r->lighting().setModelView(glm::mat4(1.0f));
  ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, side));
  auto count = [&](const char* sets) {
    LineSettings l;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, l.sets, &why)) << why;
    const ImageRGBA8 img = draw(sphere, l);
    struct {
      int yellowRight = 0, yellowLeft = 0, navyRight = 0, navyLeft = 0;
    } n;
    // A band about the middle row: there the outline's normal points left or right, at the
    // light or away (above and below it is across the light, dark on both sides).
    for (int y = kSize / 2 - kSize / 8; y < kSize / 2 + kSize / 8; ++y)
      for (int x = 0; x < kSize; ++x) {
        const std::uint8_t* px = &img.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
        const bool yellow = px[0] > 150 && px[1] > 150 && px[2] < 110, navy = px[0] < 40 && px[1] < 40 && px[2] > 45;
        const bool right = x > kSize / 2;
        (right ? n.yellowRight : n.yellowLeft) += yellow;
        (right ? n.navyRight : n.navyLeft) += navy;
      }
    return n;
  };
  const auto toned = count("silhouette width=4 colour=tone");
  std::printf("colour=tone: yellow %d px right, %d left; navy %d right, %d left\n", toned.yellowRight, toned.yellowLeft, toned.navyRight, toned.navyLeft);
  EXPECT_GT(toned.yellowRight, 80) << "the lit side's lines are not in the bright entry's colour";
  EXPECT_GT(toned.navyLeft, 80) << "the unlit side's lines are not in the dark entry's colour";
  EXPECT_LT(toned.yellowLeft, toned.yellowRight / 10);
  EXPECT_LT(toned.navyRight, toned.navyLeft / 10);
  const auto fixed = count("silhouette width=4 colour=0,0,0");
  EXPECT_EQ(fixed.yellowRight + fixed.yellowLeft + fixed.navyRight + fixed.navyLeft, 0);
  ASSERT_TRUE(r->palettes().setMain(whitePalette()));
}

// Width by curvature on a spindle (an ellipsoid 4 times longer than wide, along y): its
// curvature is about 4 times the median at the tips and the median along the middle, so a set
// with curvature=1 inks the tips' outline heavier than the middle's, and curvature=-1 lighter,
// against the same set without it.
TEST_F(OutlineFixture, ALineSetWithCurvatureDrawsTightBendsHeavier) {
  const Mesh spindle = ellipsoid(64, 64, glm::vec3(0.25f, 1.0f, 0.25f));
  int top = kSize, bottom = -1;
  {
    const LineMask plain = lineMask(draw(spindle, []() {
      LineSettings l;
      std::string why;
      EXPECT_TRUE(parseLineSets("silhouette width=3 colour=0,0,0", l.sets, &why));
      return l;
    }()));
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        if (plain.at(x, y)) top = std::min(top, y), bottom = std::max(bottom, y);
  }
  ASSERT_GT(bottom - top, 150) << "the spindle is not upright in the picture";
  const int band = (bottom - top) / 10;
  // Ink in the outer tenth at each end over ink in the middle fifth.
  auto tipsOverMiddle = [&](const char* sets) {
    LineSettings l;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, l.sets, &why)) << why;
    const LineMask mask = lineMask(draw(spindle, l));
    int tips = 0, middle = 0;
    const int centre = (top + bottom) / 2;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (!mask.at(x, y)) continue;
        if (y <= top + band || y >= bottom - band) ++tips;
        if (std::abs(y - centre) <= band) ++middle;
      }
    return double(tips) / double(std::max(middle, 1));
  };
  const double plain = tipsOverMiddle("silhouette width=3 colour=0,0,0");
  const double heavier = tipsOverMiddle("silhouette width=3 colour=0,0,0 curvature=1");
  const double lighter = tipsOverMiddle("silhouette width=3 colour=0,0,0 curvature=-1");
  std::printf("ink at the spindle's tips over its middle: %.2f plain, %.2f with curvature=1, %.2f with curvature=-1\n", plain, heavier, lighter);
  EXPECT_GT(heavier, 1.5 * plain) << "tight bends are not drawn heavier";
  EXPECT_LT(lighter, plain / 1.3) << "a negative gain does not draw them lighter";
}

TEST_F(OutlineFixture, ALineSetNamingMaterialsDrawsOnTheirFacesOnly) {
  // A cube whose top two triangles are "Lid" and the rest "Box". A set of silhouettes and creases
  // selecting Lid draws red only along the top's edges; one selecting Box* draws the others;
  // one naming no material of the cube draws nothing.
  Mesh cube = boxMesh(glm::vec3(-0.5f), glm::vec3(0.5f));
  cube.materials.resize(2);
  cube.materials[0].name = "Box";
  cube.materials[1].name = "Lid";
  cube.faceMaterials.assign(cube.triangleCount(), 0);
  for (std::size_t f = 0; f < cube.triangleCount(); ++f) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top = top && cube.positions[cube.indices[3 * f + std::size_t(k)]].y > 0.49f;
    if (top) cube.faceMaterials[f] = 1;
  }
  const CameraMatrices cam = test::testCamera(1.0f);
  const glm::mat4 mvp = cam.projection * cam.view;
  auto red = [&](const char* sets) {
    LineSettings l;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, l.sets, &why)) << why;
    const ImageRGBA8 img = draw(cube, l);
    // Red pixels, and how many lie within 3 pixels of the top's outline (y = 0.5 on screen).
    int n = 0, nearTop = 0;
    std::vector<glm::vec2> top;
    for (int i = 0; i <= 400; ++i) {  // the top square's four edges, sampled
      const float t = float(i % 100) / 100.0f;
      const int side = i / 100 % 4;
      const glm::vec3 corners[4] = {{-0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}};
      const glm::vec4 c = mvp * glm::vec4(glm::mix(corners[side], corners[(side + 1) % 4], t), 1.0f);
      top.push_back((glm::vec2(c) / c.w * 0.5f + 0.5f) * float(kSize));
    }
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const std::uint8_t* px = &img.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
        if (!(px[0] > 150 && px[1] < 110 && px[2] < 110)) continue;
        ++n;
        float d = 1e9f;
        // Image rows run down from the top; clip space's y runs up.
        for (const glm::vec2& p : top) d = std::min(d, glm::length(p - glm::vec2(float(x) + 0.5f, float(kSize - y) - 0.5f)));
        nearTop += d < 3.0f;
      }
    return std::pair{n, nearTop};
  };
  const auto [lid, lidNearTop] = red("silhouette,crease materials=Lid width=3 colour=1,0,0");
  const auto [box, boxNearTop] = red("silhouette,crease materials=Box* width=3 colour=1,0,0");
  const auto [all, allNearTop] = red("silhouette,crease width=3 colour=1,0,0");
  const auto [none, noneNearTop] = red("silhouette,crease materials=Glass width=3 colour=1,0,0");
  std::printf("material sets: Lid %d px (%d along the top), Box* %d (%d), every material %d, Glass %d\n", lid, lidNearTop, box, boxNearTop, all, none);
  EXPECT_GT(lid, 100);
  EXPECT_GE(lidNearTop, lid * 95 / 100) << "the Lid set drew off the lid's edges";
  EXPECT_GT(box, 2 * lid) << "the box has more edges than its lid";
  EXPECT_LE(std::abs(box - all), all / 20) << "every edge borders a Box face";
  EXPECT_EQ(none, 0) << "a set naming no material of the mesh drew";
}

TEST_F(OutlineFixture, ALaterSetLiesOverAnEarlierOneOnEveryObject) {
  // Two cubes overlapping on screen, "left" drawn first, "right" in front of it. A wide red set
  // on both, then a thin blue one on the left cube: blue is the last layer everywhere, so the
  // right cube's red, drawn after the left cube's lines, must not cover any of it (as it would
  // if each model drew all its sets before the next model).
  const Mesh cube = boxMesh(glm::vec3(-0.3f), glm::vec3(0.3f));
  r->scene().setOnly(nullptr);
  const ModelId left = r->scene().add(cube, glm::translate(glm::mat4(1.0f), glm::vec3(-0.25f, 0.0f, -0.2f)));
  const ModelId right = r->scene().add(cube, glm::translate(glm::mat4(1.0f), glm::vec3(0.25f, 0.1f, 0.4f)));
  ASSERT_TRUE(r->scene().setName(left, "left"));
  ASSERT_TRUE(r->scene().setName(right, "right"));
  const CameraMatrices cam = test::testCamera(1.0f, 20.0f, 15.0f);
  auto blue = [&](const char* sets) {
    RenderSettings s;
    std::string why;
    EXPECT_TRUE(parseLineSets(sets, s.lines.sets, &why)) << why;
    const ImageRGBA8 img = test::renderImage(*r, cam, s, kSize, kSize);
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) n += img.pixels[i + 2] > 150 && img.pixels[i] < 110 && img.pixels[i + 1] < 110;
    return n;
  };
  const int alone = blue("silhouette width=3 colour=0,0,1 objects=left");
  const int under = blue("silhouette width=12 colour=1,0,0; silhouette width=3 colour=0,0,1 objects=left");
  std::printf("the later set's blue: %d px alone, %d px over the earlier red set\n", alone, under);
  EXPECT_GT(alone, 200);
  // Blue rims blended over red instead of white count a few pixels differently; drawn model by
  // model, the right cube's red covered 41 of the 325 here.
  EXPECT_GE(under, alone * 98 / 100) << "an earlier set drawn on a later model covered a later set";
}

TEST_F(OutlineFixture, ALineSetNamingAnObjectDrawsOnThatObjectOnly) {
  // Two cubes side by side, "left" and "right": silhouettes in the base style (black), and a
  // set taking the left cube's silhouettes in red.
  const Mesh cube = boxMesh(glm::vec3(-0.3f), glm::vec3(0.3f));
  r->scene().setOnly(nullptr);
  const ModelId left = r->scene().add(cube, glm::translate(glm::mat4(1.0f), glm::vec3(-0.45f, 0.0f, 0.0f)));
  const ModelId right = r->scene().add(cube, glm::translate(glm::mat4(1.0f), glm::vec3(0.45f, 0.0f, 0.0f)));
  ASSERT_TRUE(r->scene().setName(left, "left"));
  ASSERT_TRUE(r->scene().setName(right, "right"));
  RenderSettings s;
  s.lines.silhouettes = true;
  s.lines.width = 3.0f;
  std::string why;
  ASSERT_TRUE(parseLineSets("silhouette width=3 colour=1,0,0 objects=le*", s.lines.sets, &why)) << why;
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  const ImageRGBA8 img = test::renderImage(*r, cam, s, kSize, kSize);
  // The screen's left half holds the left cube, the right half the right one.
  int red[2] = {0, 0}, black[2] = {0, 0};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::uint8_t* px = &img.pixels[(std::size_t(y) * kSize + std::size_t(x)) * 4];
      const int half = x < kSize / 2 ? 0 : 1;
      red[half] += px[0] > 150 && px[1] < 110 && px[2] < 110;
      black[half] += px[0] < 80 && px[1] < 80 && px[2] < 80;
    }
  std::printf("object line set: red %d left, %d right; black %d left, %d right\n", red[0], red[1], black[0], black[1]);
  EXPECT_GT(red[0], 200);
  EXPECT_EQ(red[1], 0) << "the set drew on an object it does not name";
  EXPECT_GT(black[1], 200);
  EXPECT_LT(black[0], black[1] / 10) << "the base style still drew the left cube's silhouettes";
}
}  // namespace
}  // namespace npr
