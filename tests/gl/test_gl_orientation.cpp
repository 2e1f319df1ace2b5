// GL tier: hatching orientation. A cylinder lying across the view, drawn with the one-direction
// hatch palette (horizontal strokes) and --orient curvature, shows strokes around it (vertical
// on screen), along the wanted angles, in every path; a fixed angle and the light's gradient
// turn strokes where they say; palettes with no stroke direction cost nothing; the selection
// is the same turned or not; the direction field is computed once per mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gl/gl_test_env.h"
#include "renderer/core/image_io.h"
#include "renderer/mesh/mesh_generators.h"
#include "renderer/paths/path_table.h"
#include "renderer/palette/palette_orientation.h"
#include "support/stroke_alignment.h"
#include "support/test_util.h"

namespace npr {
namespace {

using Fixture = test::RendererFixture;
constexpr int kSize = 256;

// The generated cylinder turned to lie along x, so the curvature's direction (around it) is
// vertical on screen while the palette's strokes are horizontal.
Mesh lyingCylinder() {
  Mesh m = cylinder(96, 48);
  for (glm::vec3& p : m.positions) p = glm::vec3(-p.y, p.x, p.z);
  finalizeMesh(m);
  return m;
}

// Every valid pixel of `wanted` given the angle `radians` instead.
ImageRGBA32F constantAngle(ImageRGBA32F wanted, float radians) {
  for (std::size_t i = 0; i < wanted.pixels.size(); i += 4) wanted.pixels[i] = radians;
  return wanted;
}

struct Orientation : Fixture {
  Mesh mesh = lyingCylinder();
  void SetUp() override {
    Fixture::SetUp();
    ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
    r->scene().setOnly(&mesh);
  }
  CameraMatrices camera() const { return test::testCamera(1.0f, 0.0f, 10.0f); }
  // What `path` draws with strokes along the curvature, and the stroke angles it wanted.
  struct Turned {
    RenderSettings settings;
    ImageRGBA8 image;
    ImageRGBA32F wanted;
  };
  Turned renderTurned(RenderPath path) {
    Turned t;
    t.settings.path = path;
    t.settings.orient.source = OrientSource::Curvature;
    t.image = test::renderImage(*r, camera(), t.settings, kSize, kSize);
    t.wanted = test::renderStrokeAngles(*r, camera(), t.settings, kSize, kSize);
    return t;
  }
};

TEST_F(Orientation, CylinderStrokesFollowTheCurvatureInEveryPath) {
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Smooth, RenderPath::Triangle, RenderPath::Stencil}) {
    SCOPED_TRACE(pathInfo(path).name);
    const Turned t = renderTurned(path);
    const ImageRGBA8& img = t.image;
    const ImageRGBA32F& wanted = t.wanted;
    const test::Alignment along = test::strokeAlignment(img, wanted);
    const test::Alignment texture = test::strokeAlignment(img, constantAngle(wanted, 0.0f));
    EXPECT_GT(along.pixels, 8000u);
    EXPECT_LE(along.medianDegrees, 10.0);
    EXPECT_GE(texture.medianDegrees, 60.0);  // not the palette's own horizontal strokes
    if (HasFailure()) (void)writeImage(test::outputPath(std::string("orient-cylinder-") + pathInfo(path).name + ".png"), img);
  }
  // Unturned, the same frame shows the texture's horizontal strokes.
  RenderSettings none;
  const ImageRGBA8 img = test::renderImage(*r, camera(), none, kSize, kSize);
  RenderSettings curvature;
  curvature.orient.source = OrientSource::Curvature;
  const ImageRGBA32F wanted = test::renderStrokeAngles(*r, camera(), curvature, kSize, kSize);
  EXPECT_LE(test::strokeAlignment(img, constantAngle(wanted, 0.0f)).medianDegrees, 10.0);
  EXPECT_GE(test::strokeAlignment(img, wanted).medianDegrees, 60.0);
}

TEST_F(Orientation, FixedAngleTurnsStrokesInEveryPath) {
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Stencil, RenderPath::Triangle}) {
    SCOPED_TRACE(pathInfo(path).name);
    RenderSettings s;
    s.path = path;
    s.orient = *parseOrient("60");
    const ImageRGBA8 img = test::renderImage(*r, camera(), s, kSize, kSize);
    const ImageRGBA32F wanted = test::renderStrokeAngles(*r, camera(), s, kSize, kSize);
    EXPECT_LE(test::strokeAlignment(img, constantAngle(wanted, float(M_PI / 3.0))).medianDegrees, 10.0);
  }
}

TEST_F(Orientation, LightStrokesRunAlongTheLightsGradient) {
  const Mesh sphere = icosphere(4);
  r->scene().setOnly(&sphere);
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Stencil}) {
    SCOPED_TRACE(pathInfo(path).name);
    RenderSettings s;
    s.path = path;
    s.orient.source = OrientSource::Light;
    const ImageRGBA8 img = test::renderImage(*r, test::testCamera(1.0f), s, kSize, kSize);
    const ImageRGBA32F wanted = test::renderStrokeAngles(*r, test::testCamera(1.0f), s, kSize, kSize);
    const test::Alignment a = test::strokeAlignment(img, wanted);
    EXPECT_GT(a.pixels, 5000u);
    EXPECT_LE(a.medianDegrees, 10.0);
  }
  r->scene().setOnly(&mesh);
}

TEST_F(Orientation, AnchoredPatternsStayAlongTheField) {
  // The anchored pattern turns with the object; the orientation takes that turn out.
  RenderSettings s;
  s.orient.source = OrientSource::Curvature;
  s.pattern = PatternSpace::Anchored;
  OrbitCamera cam(0.0f, 70.0f, 3.0f);  // from above: orbiting turns the image
  cam.frame(1.0f);
  for (int f = 0; f < 12; ++f) {
    (void)test::renderImage(*r, cam.matrices(1.0f), s, kSize, kSize);
    cam.orbit(4.0f, 0.0f);
  }
  ASSERT_GT(std::fabs(r->scene().first()->patterns().frame().rotation), 0.3f);
  const ImageRGBA8 img = test::renderImage(*r, cam.matrices(1.0f), s, kSize, kSize);
  const ImageRGBA32F wanted = test::renderStrokeAngles(*r, cam.matrices(1.0f), s, kSize, kSize);
  EXPECT_LE(test::strokeAlignment(img, wanted).medianDegrees, 10.0);
}

TEST_F(Orientation, PalettesWithoutStrokeDirectionsAreNotTurned) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("stipple")));
  RenderSettings none, curvature;
  curvature.orient.source = OrientSource::Curvature;
  const ImageRGBA8 a = test::renderImage(*r, camera(), none, kSize, kSize);
  const ImageRGBA8 b = test::renderImage(*r, camera(), curvature, kSize, kSize);
  EXPECT_EQ(test::countDiffering(a, b), 0);
  EXPECT_EQ(r->scene().first()->directionFieldIfComputed(), nullptr);  // nothing asked for it
}

TEST_F(Orientation, SelectionIsTheSameTurnedOrNot) {
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Triangle}) {
    RenderSettings none, curvature;
    none.path = curvature.path = path;
    curvature.orient.source = OrientSource::Curvature;
    (void)test::renderImage(*r, camera(), curvature, kSize, kSize);  // leaves the palette oriented
    EXPECT_EQ(test::countDiffering(test::renderEntries(*r, camera(), none, kSize, kSize),
                                   test::renderEntries(*r, camera(), curvature, kSize, kSize)),
              0)
        << pathInfo(path).name;
  }
}

// The hatch palette with every second stroked entry mirrored across its diagonal, so that its
// strokes run at 90 degrees instead of 0: the entries no longer share one angle.
Palette hatchAtTwoAngles(std::vector<int>& mirrored) {
  Palette p = test::shippedPalette("hatch");
  for (std::size_t k = 0; k < p.entries.size(); ++k) {
    PaletteEntry& e = p.entries[k];
    if (!e.orientation.oriented() || k % 2 == 0) continue;
    const ImageRGBA8 src = e.image;
    for (int y = 0; y < src.height; ++y)
      for (int x = 0; x < src.width; ++x)
        for (int c = 0; c < 4; ++c) e.image.pixels[(size_t(y) * src.width + x) * 4 + c] = src.pixels[(size_t(x) * src.width + y) * 4 + c];
    e.mips.clear();
    e.orientation = textureOrientation(e.image, p.backgroundColour);
    mirrored.push_back(int(k));
  }
  return p;
}

// `wanted` kept only where `entries` (renderEntries' image) shows one of `keep`.
ImageRGBA32F onlyEntries(ImageRGBA32F wanted, const ImageRGBA8& entries, const std::vector<int>& keep) {
  for (std::size_t i = 0; i < wanted.pixels.size() / 4; ++i)
    if (std::find(keep.begin(), keep.end(), int(entries.pixels[i * 4])) == keep.end()) wanted.pixels[i * 4 + 1] = 0.0f;
  return wanted;
}

TEST_F(Orientation, EntriesWithDifferentStrokeAnglesAreEachTurnedByTheirOwn) {
  std::vector<int> mirrored;
  const Palette p = hatchAtTwoAngles(mirrored);
  ASSERT_GE(mirrored.size(), 2u);
  std::vector<TextureOrientation> angles;
  for (const PaletteEntry& e : p.entries) angles.push_back(e.orientation);
  ASSERT_FALSE(sharedStrokeDegrees(angles).has_value());  // the per-entry form is the one drawn
  ASSERT_TRUE(r->palettes().setMain(p));
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Triangle, RenderPath::Stencil}) {
    SCOPED_TRACE(pathInfo(path).name);
    const Turned t = renderTurned(path);
    RenderSettings entriesOf = t.settings;
    entriesOf.path = path == RenderPath::Stencil ? RenderPath::Triangle : path;  // the same per-triangle choice
    const ImageRGBA32F mirroredOnly = onlyEntries(t.wanted, test::renderEntries(*r, camera(), entriesOf, kSize, kSize), mirrored);
    const test::Alignment a = test::strokeAlignment(t.image, mirroredOnly);
    EXPECT_GT(a.pixels, 2000u);
    EXPECT_LE(a.medianDegrees, 10.0);
  }
}

TEST_F(Orientation, EntriesWithoutAStrokeDirectionStayUnturnedBesideTurnedOnes) {
  // Crosshatch: its single-family entries share one angle (the per-pixel turn is found once),
  // its dense ones have no dominant direction and must be drawn as they are.
  const Palette p = test::shippedPalette("crosshatch");
  std::vector<TextureOrientation> angles;
  std::vector<int> unturned;
  for (std::size_t k = 0; k < p.entries.size(); ++k) {
    angles.push_back(p.entries[k].orientation);
    if (!p.entries[k].orientation.oriented()) unturned.push_back(int(k));
  }
  ASSERT_TRUE(sharedStrokeDegrees(angles).has_value());
  ASSERT_TRUE(r->palettes().setMain(p));
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Smooth, RenderPath::Triangle}) {
    SCOPED_TRACE(pathInfo(path).name);
    RenderSettings none, curvature;
    none.path = curvature.path = path;
    curvature.orient.source = OrientSource::Curvature;
    RenderSettings entriesOf = none;
    entriesOf.path = path == RenderPath::Smooth ? RenderPath::Pixel : path;
    const ImageRGBA8 entries = test::renderEntries(*r, camera(), entriesOf, kSize, kSize);
    const ImageRGBA8 a = test::renderImage(*r, camera(), none, kSize, kSize);
    const ImageRGBA8 b = test::renderImage(*r, camera(), curvature, kSize, kSize);
    std::size_t same[2] = {0, 0}, count[2] = {0, 0};  // [0]: unturned entries, [1]: turned
    for (std::size_t i = 0; i < entries.pixels.size() / 4; ++i) {
      if (entries.pixels[i * 4 + 3] == 0) continue;  // background
      const bool turned = std::find(unturned.begin(), unturned.end(), int(entries.pixels[i * 4])) == unturned.end();
      ++count[turned];
      same[turned] += std::equal(&a.pixels[i * 4], &a.pixels[i * 4 + 3], &b.pixels[i * 4]);
    }
    ASSERT_GT(count[0], 1000u);
    ASSERT_GT(count[1], 1000u);
    if (path != RenderPath::Smooth) {
      EXPECT_EQ(same[0], count[0]);  // smooth: blends with turned neighbours
    }
    EXPECT_LT(double(same[1]), 0.7 * double(count[1]));
  }
}

TEST_F(Orientation, DirectionFieldIsComputedOncePerMesh) {
  RenderSettings s;
  s.orient.source = OrientSource::Curvature;
  (void)test::renderImage(*r, camera(), s, 64, 64);
  ASSERT_NE(r->scene().first()->directionFieldIfComputed(), nullptr);
  EXPECT_GT(r->stats().cpuFieldMs, 0.0);
  EXPECT_EQ(r->scene().first()->directionFieldIfComputed()->directions.size(), mesh.positions.size());
  (void)test::renderImage(*r, camera(), s, 64, 64);
  EXPECT_EQ(r->stats().cpuFieldMs, 0.0);
  const Mesh other = icosphere(2);
  r->scene().setOnly(&other);
  EXPECT_EQ(r->scene().first()->directionFieldIfComputed(), nullptr);
  (void)test::renderImage(*r, camera(), s, 64, 64);
  ASSERT_NE(r->scene().first()->directionFieldIfComputed(), nullptr);
  EXPECT_EQ(r->scene().first()->directionFieldIfComputed()->directions.size(), other.positions.size());
  r->scene().setOnly(&mesh);
}

TEST_F(Orientation, StencilMasksWriteTheSurfaceBuffersInAFramebufferTheyShare) {
  // In a framebuffer of ours (what the window draws into where a frame needs these buffers) the
  // masks write the stroke angles and the object pattern's coordinates as they mark: no pass of
  // their own. Drawn by passes of their own instead (masks bucket by bucket) the frame is the same.
  RenderSettings s;
  s.path = RenderPath::Stencil;
  s.orient.source = OrientSource::Curvature;
  s.pattern = PatternSpace::Object;
  const ImageRGBA8 fromMasks = test::renderImage(*r, camera(), s, kSize, kSize);
  EXPECT_EQ(r->stats().surfaceBuffers, 2);
  EXPECT_EQ(r->stats().surfaceBufferPasses, 0);
  s.stencilMasksFirst = false;
  const ImageRGBA8 fromPasses = test::renderImage(*r, camera(), s, kSize, kSize);
  EXPECT_EQ(r->stats().surfaceBuffers, 2);
  EXPECT_EQ(r->stats().surfaceBufferPasses, 2);
  EXPECT_EQ(test::countDiffering(fromMasks, fromPasses), 0);
  s.pattern = PatternSpace::Screen;
  s.stencilMasksFirst = true;
  (void)test::renderImage(*r, camera(), s, kSize, kSize);
  EXPECT_EQ(r->stats().surfaceBuffers, 1);
  EXPECT_EQ(r->stats().surfaceBufferPasses, 0);
  s.orient.source = OrientSource::None;
  (void)test::renderImage(*r, camera(), s, kSize, kSize);
  EXPECT_EQ(r->stats().surfaceBuffers, 0);
}

TEST_F(Orientation, TurnsResolvedPerPixelDrawTheInPlaceTurnsPicture) {
  // The triangle, vertex, pixel and smooth paths can leave their turned lookups to one pass per pixel
  // (passes/turn_resolve_pass.h): the same frame, with the screen's pattern, a scaled one and an
  // anchored one, the field's angles and the light's.
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth})
    for (PatternSpace pattern : {PatternSpace::Screen, PatternSpace::Anchored})
      for (OrientSource source : {OrientSource::Curvature, OrientSource::Light}) {
        SCOPED_TRACE(std::string(renderPathName(path)) + (pattern == PatternSpace::Anchored ? " anchored" : " screen") +
                     (source == OrientSource::Light ? " light" : " curvature"));
        RenderSettings s;
        s.path = path;
        s.pattern = pattern;
        s.patternScale = pattern == PatternSpace::Anchored ? 1.5f : 1.0f;
        s.orient.source = source;
        s.tuning.turnPlacement = TurnPlacement::InMeshPass;
        r->resetPattern();
        const ImageRGBA8 inPass = test::renderImage(*r, camera(), s, kSize, kSize);
        EXPECT_EQ(r->stats().surfaceBuffers, 0);
        s.tuning.turnPlacement = TurnPlacement::Resolved;
        r->resetPattern();
        const ImageRGBA8 resolved = test::renderImage(*r, camera(), s, kSize, kSize);
        EXPECT_EQ(r->stats().surfaceBuffers, 1);
        // The anchored pattern's coordinate is interpolated over the resolve's full-screen
        // triangle instead of the mesh's: a rounding apart at texel edges.
        EXPECT_LE(test::countDiffering(inPass, resolved), pattern == PatternSpace::Anchored ? kSize * kSize / 500 : 0);
        EXPECT_GT(test::countDiffering(inPass, test::renderImage(*r, camera(), RenderSettings{}, kSize, kSize)), kSize * kSize / 20);
      }
}

TEST_F(Orientation, TurnsAreResolvedPerPixelOnlyWhereTrianglesAreSmall) {
  auto lying = [](int around, int along) {
    Mesh m = cylinder(around, along);
    for (glm::vec3& p : m.positions) p = glm::vec3(-p.y, p.x, p.z);
    finalizeMesh(m);
    return m;
  };
  RenderSettings s;
  s.path = RenderPath::Triangle;
  s.orient.source = OrientSource::Curvature;
  const Mesh coarse = lying(24, 6);  // 288 triangles, about 150 pixels each at 256 x 256
  r->scene().setOnly(&coarse);
  (void)test::renderImage(*r, camera(), s, kSize, kSize);
  EXPECT_EQ(r->stats().surfaceBuffers, 0);
  const Mesh dense = lying(384, 192);  // 147,456, under half a pixel
  r->scene().setOnly(&dense);
  const ImageRGBA8 resolved = test::renderImage(*r, camera(), s, kSize, kSize);
  EXPECT_EQ(r->stats().surfaceBuffers, 1);
  s.tuning.turnPlacement = TurnPlacement::InMeshPass;
  EXPECT_EQ(test::countDiffering(resolved, test::renderImage(*r, camera(), s, kSize, kSize)), 0);
  r->scene().setOnly(&mesh);
}

TEST_F(Orientation, StepsAreStableUnderASmallOrbit) {
  // One degree of orbit moves each surface point's stroke angle a little: its step changes by at
  // most one (no flips between the principal directions).
  RenderSettings s;
  s.orient.source = OrientSource::Curvature;
  OrbitCamera cam(0.0f, 10.0f, 3.0f);
  cam.frame(1.0f);
  const CameraMatrices a = cam.matrices(1.0f);
  cam.orbit(1.0f, 0.0f);
  const CameraMatrices b = cam.matrices(1.0f);
  const ImageRGBA32F anglesA = test::renderStrokeAngles(*r, a, s, kSize, kSize), anglesB = test::renderStrokeAngles(*r, b, s, kSize, kSize);
  const ImageRGBA32F eyeA = test::renderGeometry(*r, a, FrameOutput::EyePosition, kSize, kSize);
  const ImageRGBA32F eyeB = test::renderGeometry(*r, b, FrameOutput::EyePosition, kSize, kSize);
  std::size_t compared = 0;
  EXPECT_LT(test::stepJumpFraction(anglesA, eyeA, a, anglesB, eyeB, b, s.orient.bins, 0.0f, &compared), 0.005);
  EXPECT_GT(compared, 8000u);
  // The measure sees a flip: the same frames with the second turned by a quarter turn.
  ImageRGBA32F flipped = anglesB;
  for (std::size_t i = 0; i < flipped.pixels.size(); i += 4) flipped.pixels[i] += float(M_PI / 2.0);
  EXPECT_GT(test::stepJumpFraction(anglesA, eyeA, a, flipped, eyeB, b, s.orient.bins), 0.95);
}

}  // namespace
}  // namespace npr
