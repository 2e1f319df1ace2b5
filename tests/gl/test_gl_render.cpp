// GL tier: the render paths on the headless context. Stencil equals triangle; pixel agrees
// with the CPU lighting; palettes stay in screen space; golden images; extremes; and
// unchanged state costs nothing.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "renderer/core/image_io.h"
#include "renderer/immediate_api.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/settings/choice_names.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::renderImage;
using test::shippedPalette;
using test::sourcePath;
using test::testCamera;
using test::greyRamp;
using test::expectGolden;


using Fixture = test::RendererFixture;
using test::countDiffering;

int countCovered(Renderer& r, const CameraMatrices& cam, int w, int h) {
  const ImageRGBA32F img = test::renderGeometry(r, cam, FrameOutput::EyeNormal, w, h);
  int n = 0;
  for (size_t i = 3; i < img.pixels.size(); i += 4) n += img.pixels[i] > 0.5f;
  return n;
}

void expectStencilEqualsTriangle(Renderer& r, const std::string& what) {
  const int w = 400, h = 300;
  const CameraMatrices cam = testCamera(float(w) / h);
  const int covered = countCovered(r, cam, w, h);
  ASSERT_GT(covered, 1000) << what;
  for (MatchMode mode : {MatchMode::Colors, MatchMode::Intensity, MatchMode::Order}) {
    RenderSettings s;
    s.match = mode;
    s.path = RenderPath::Stencil;
    const ImageRGBA8 stencil = renderImage(r, cam, s, w, h);
    s.path = RenderPath::Triangle;
    const ImageRGBA8 triangle = renderImage(r, cam, s, w, h);
    const int diff = countDiffering(stencil, triangle);
    EXPECT_LE(diff, covered / 1000) << what << " " << choiceName(mode) << ": " << diff << " of " << covered << " covered pixels differ";
    if (diff > covered / 1000) (void)writeImage(test::outputPath("stencil-vs-triangle-" + std::string(choiceName(mode)) + ".png"), stencil);
  }
}

TEST_F(Fixture, StencilEqualsTriangleOnTheBunny) {
  auto mesh = loadMesh(sourcePath("models/bunny.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  expectStencilEqualsTriangle(*r, "bunny");
}

TEST_F(Fixture, StencilEqualsTriangleOnA500KTriangleMesh) {
  const Mesh mesh = test::torus(500, 500);
  ASSERT_EQ(mesh.triangleCount(), 500000u);
  r->scene().setOnly(&mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  expectStencilEqualsTriangle(*r, "torus");
}

// Back faces are dropped (RenderSettings::cullHiddenBackFaces) only where none can show: a
// closed sphere seen from outside draws the same picture either way in every palette path; from
// inside it, and for an open square, nothing is dropped (inside, the sphere's back faces are
// all there is to see).
TEST_F(Fixture, BackFacesAreDroppedOnlyWhereNoneCanShow) {
  const Mesh sphere = test::icosphere(3);
  const Mesh square = test::square(4);
  ASSERT_TRUE(r->palettes().setMain(greyRamp(8)));
  const int w = 160, h = 120;
  const CameraMatrices outside = OrbitCamera(30.0f, 20.0f, 3.0f).matrices(float(w) / h);
  CameraMatrices inside;
  inside.view = glm::lookAt(glm::vec3(0.1f, 0.0f, 0.2f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0, 1, 0));
  inside.projection = glm::perspective(glm::radians(60.0f), float(w) / h, 0.05f, 10.0f);
  struct Case {
    const Mesh* mesh;
    const CameraMatrices* camera;
    bool culled;
  };
  for (const Case& c : {Case{&sphere, &outside, true}, Case{&sphere, &inside, false}, Case{&square, &outside, false}}) {
    r->scene().setOnly(c.mesh);
    for (RenderPath path : {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth}) {
      RenderSettings s;
      s.path = path;
      const ImageRGBA8 dropped = renderImage(*r, *c.camera, s, w, h);
      EXPECT_EQ(r->stats().backFacesCulled, c.culled) << pathInfo(path).name;
      s.tuning.cullHiddenBackFaces = false;
      const ImageRGBA8 all = renderImage(*r, *c.camera, s, w, h);
      EXPECT_FALSE(r->stats().backFacesCulled);
      EXPECT_EQ(countDiffering(dropped, all), 0) << pathInfo(path).name << (c.culled ? " outside" : " inside or open");
    }
  }
}

TEST_F(Fixture, NaiveStencilDrawsTheSameImage) {
  auto mesh = loadMesh(sourcePath("models/teapot.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("wood")));
  RenderSettings s;
  s.path = RenderPath::Stencil;
  const CameraMatrices cam = testCamera(1.0f);
  const ImageRGBA8 bounded = renderImage(*r, cam, s, 256, 256);
  const int boundedDraws = r->stats().drawCalls;
  s.stencilScissor = s.stencilSkipEmpty = s.stencilMasksFirst = false;
  const ImageRGBA8 naive = renderImage(*r, cam, s, 256, 256);
  EXPECT_EQ(countDiffering(bounded, naive), 0);
  EXPECT_GE(r->stats().drawCalls, boundedDraws);
  // The background, the layer's quad for every bucket (wood's layers are stored over its
  // background: no background quad under them), and a mask for each non-empty one.
  EXPECT_EQ(r->stats().drawCalls, 1 + 30 + r->stats().nonEmptyBuckets);
}

// A framebuffer of the test's own, its depth and stencil in a renderbuffer, a 2D texture, or
// one layer of an array texture (which the stencil path's masks cannot share).
enum class DepthStencilKind { Renderbuffer, Texture, ArrayLayer };

ImageRGBA8 renderWithDepthStencil(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h, DepthStencilKind kind) {
  GLuint fbo = 0, colour = 0, depth = 0;
  glGenFramebuffers(1, &fbo);
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  if (kind == DepthStencilKind::Renderbuffer) {
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);
  } else if (kind == DepthStencilKind::Texture) {
    glGenTextures(1, &depth);
    glBindTexture(GL_TEXTURE_2D, depth);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH24_STENCIL8, w, h);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
  } else {
    glGenTextures(1, &depth);
    glBindTexture(GL_TEXTURE_2D_ARRAY, depth);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH24_STENCIL8, w, h, 2);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, depth, 0, 1);
  }
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_TRUE(r.render(cam, s, {0, 0, w, h}));
  ImageRGBA8 img = readFramebufferRGBA8(0, 0, w, h);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &colour);
  if (kind == DepthStencilKind::Renderbuffer) glDeleteRenderbuffers(1, &depth);
  else glDeleteTextures(1, &depth);
  return img;
}

// Every mask first, the masks writing the surface buffers (object-space pattern, strokes
// along the curvature) as they mark, draws what the original order with a pass per buffer
// draws, with one geometry pass fewer per buffer; where the target's depth-stencil cannot be
// shared, the passes draw the buffers and the picture is the same. A 256-entry palette with
// every bucket drawn needs two runs of stencil marks.
TEST_F(Fixture, StencilMasksFirstWriteTheSurfaceBuffersAndDrawTheSameImage) {
  auto mesh = loadMesh(sourcePath("models/bunny.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  const Palette hatch = shippedPalette("hatch");
  Palette many;
  many.name = "hatch256";
  // Entries 0-199 as bright as white (no lit pixel is nearer to them than to entry 200), the
  // others spread over the model's tones: the two runs' last marks are all on screen.
  for (int i = 0; i < 256; ++i) {
    PaletteEntry e = hatch.entries[std::size_t(i) % hatch.entries.size()];
    e.intensity = i < 200 ? 3.0f : 2.4f - 2.1f * float(i - 200) / 55.0f;
    e.average = glm::vec3(e.intensity / 3.0f);
    many.entries.push_back(std::move(e));
  }
  const int w = 240, h = 200;
  const CameraMatrices cam = testCamera(float(w) / h);
  struct Case {
    const char* name;
    bool object, curvature, everyBucket;
    const Palette* palette;
  };
  for (const Case& c : {Case{"object", true, false, false, &hatch}, Case{"curvature", false, true, false, &hatch},
                        Case{"both", true, true, false, &hatch}, Case{"both, 256 buckets", true, true, true, &many}}) {
    ASSERT_TRUE(r->palettes().setMain(*c.palette));
    RenderSettings s;
    s.path = RenderPath::Stencil;
    if (c.object) s.pattern = PatternSpace::Object;
    if (c.curvature) s.orient.source = OrientSource::Curvature;
    if (c.everyBucket) s.stencilSkipEmpty = false;
    const int buffers = int(c.object) + int(c.curvature);
    if (c.everyBucket) {
      std::set<int> shown;
      const ImageRGBA8 entries = test::renderEntries(*r, cam, s, w, h);
      for (size_t i = 0; i < entries.pixels.size(); i += 4) shown.insert(entries.pixels[i]);
      EXPECT_TRUE(shown.count(254) && shown.count(255)) << "the runs' last buckets are not on screen";
    }
    s.stencilMasksFirst = false;
    const ImageRGBA8 original = renderWithDepthStencil(*r, cam, s, w, h, DepthStencilKind::Renderbuffer);
    const int originalDraws = r->stats().drawCalls;
    s.stencilMasksFirst = true;
    for (DepthStencilKind kind : {DepthStencilKind::Renderbuffer, DepthStencilKind::Texture, DepthStencilKind::ArrayLayer}) {
      const ImageRGBA8 img = renderWithDepthStencil(*r, cam, s, w, h, kind);
      EXPECT_EQ(countDiffering(original, img), 0) << c.name << ", depth-stencil kind " << int(kind);
      const int saved = kind == DepthStencilKind::ArrayLayer ? 0 : buffers;
      EXPECT_EQ(r->stats().drawCalls, originalDraws - saved) << c.name << ", depth-stencil kind " << int(kind);
    }
    EXPECT_GT(countDiffering(original, renderImage(*r, cam, RenderSettings{}, w, h)), 1000) << c.name;  // the settings show
  }
}

// The stencil path keeps its projected vertices while only the light moves and re-bounds the
// new buckets from them: stale rectangles would cut buckets short.
TEST_F(Fixture, StencilBoundsFollowTheLightAndTheView) {
  auto mesh = loadMesh(sourcePath("models/bunny.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  const int w = 320, h = 240;
  RenderSettings s;
  s.path = RenderPath::Stencil;
  CameraMatrices cam = testCamera(float(w) / h);
  (void)renderImage(*r, cam, s, w, h);
  for (int step = 0; step < 3; ++step) {
    if (step == 2) cam = testCamera(float(w) / h, 75.0f, -10.0f);  // then the view
    const float pos[4] = {-3.0f + 2.5f * float(step), 1.0f, 2.0f, 1.0f};
    r->lighting().setModelView(cam.view);
    ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos));
    s.path = RenderPath::Stencil;
    const ImageRGBA8 stencil = renderImage(*r, cam, s, w, h);
    s.path = RenderPath::Triangle;
    const ImageRGBA8 triangle = renderImage(*r, cam, s, w, h);
    const int covered = countCovered(*r, cam, w, h);
    EXPECT_LE(countDiffering(stencil, triangle), covered / 1000) << "step " << step;
  }
}

TEST_F(Fixture, PixelPathAgreesWithTheCpuLightingModel) {
  auto mesh = loadMesh(sourcePath("models/bunny.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  const int w = 320, h = 240;
  const CameraMatrices cam = testCamera(float(w) / h);
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, w, h);
  const ImageRGBA32F nrm = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, w, h);
  for (MatchMode mode : {MatchMode::Intensity, MatchMode::Order, MatchMode::Colors}) {
    RenderSettings s;
    s.path = RenderPath::Pixel;
    s.match = mode;
    const ImageRGBA8 entries = test::renderEntries(*r, cam, s, w, h);
    const PaletteMatcher& m = *r->palettes().matcher();
    const auto prepared = prepareLighting<float>(r->lighting());
    int sampled = 0, exact = 0, nearBoundary = 0;
    for (size_t i = 0; i < size_t(w) * h; i += 7) {
      if (nrm.pixels[i * 4 + 3] < 0.5f) continue;  // background
      const glm::vec3 p(pos.pixels[i * 4], pos.pixels[i * 4 + 1], pos.pixels[i * 4 + 2]);
      const glm::vec3 n(nrm.pixels[i * 4], nrm.pixels[i * 4 + 1], nrm.pixels[i * 4 + 2]);
      const bool back = pos.pixels[i * 4 + 3] < 0.0f;
      const glm::vec3 lit = shade(prepared, p, n, back);
      const int gpu = entries.pixels[i * 4];
      ++sampled;
      if (gpu == m.match(lit)) {
        ++exact;
        continue;
      }
      // Within one step of a tone boundary: a nudge of the lit colour reaches the GPU's choice.
      bool reachable = false;
      for (float d : {-0.01f, 0.01f})
        for (int k = -1; k < 3; ++k) {
          glm::vec3 q = lit;
          if (k < 0) q += glm::vec3(d);
          else q[k] += d;
          reachable = reachable || m.match(q) == gpu;
        }
      EXPECT_TRUE(reachable) << choiceName(mode) << " pixel " << i << ": gpu " << gpu << " cpu " << m.match(lit);
      nearBoundary += reachable;
    }
    EXPECT_GT(sampled, 1000);
    // Colours are matched through a 64^3 lookup table on the GPU, so more pixels sit near a
    // boundary than with the 4096-bin intensity table: with the drawn crosshatch, whose levels
    // are 0.24 apart in intensity against a table cell of 0.016 a channel, 93% are exact
    // (every other one within a nudge of a boundary, checked above).
    EXPECT_GE(exact, sampled * (mode == MatchMode::Colors ? 90 : 99) / 100) << choiceName(mode) << ": " << exact << " of " << sampled << " exact";
    std::printf("%s: %d sampled, %d exact, %d within one step of a boundary\n", choiceName(mode), sampled, exact, nearBoundary);
  }
}

TEST_F(Fixture, PaletteStaysInScreenSpace) {
  // One entry with a distinctive pattern: every covered pixel shows texel (x mod 16, y mod 16)
  // whatever the depth or camera, so the pattern neither moves nor scales with the model.
  Palette p;
  PaletteEntry e;
  e.image = ImageRGBA8{16, 16, std::vector<std::uint8_t>(16 * 16 * 4)};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* px = &e.image.pixels[size_t(y * 16 + x) * 4];
      px[0] = std::uint8_t(x * 16);
      px[1] = std::uint8_t(y * 16);
      px[2] = 77;
      px[3] = 255;
    }
  e.average = glm::vec3(0.5f);
  p.entries.push_back(std::move(e));
  ASSERT_TRUE(r->palettes().setMain(p));
  const Mesh mesh = test::icosphere(4);
  r->scene().setOnly(&mesh);
  const int w = 128, h = 96;
  for (RenderPath path : {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth}) {
    for (float distance : {2.5f, 6.0f}) {
      OrbitCamera c(10.0f + distance * 7.0f, 5.0f, distance);
      RenderSettings s;
      s.path = path;
      const ImageRGBA8 img = renderImage(*r, c.matrices(float(w) / h), s, w, h);
      int checked = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const std::uint8_t* px = &img.pixels[size_t(y * w + x) * 4];
          if (px[2] != 77) continue;  // background
          const int glY = h - 1 - y;  // screen rows count from the bottom in GL
          ASSERT_EQ(px[0], (x % 16) * 16) << renderPathName(path) << " at " << x << "," << y;
          // Images are uploaded top row first, so each tile shows the image upright.
          ASSERT_EQ(px[1], (15 - glY % 16) * 16) << renderPathName(path) << " at " << x << "," << y;
          ++checked;
        }
      EXPECT_GT(checked, 500) << renderPathName(path) << " distance " << distance;
    }
  }
}

TEST_F(Fixture, OneAndTwoHundredFiftySixEntries) {
  const Mesh mesh = test::icosphere(3);
  r->scene().setOnly(&mesh);
  for (int n : {1, 256}) {
    ASSERT_TRUE(r->palettes().setMain(greyRamp(n)));
    for (RenderPath path : userRenderPaths())
      for (MatchMode mode : {MatchMode::Colors, MatchMode::Intensity, MatchMode::Order}) {
        RenderSettings s;
        s.path = path;
        s.match = mode;
        const ImageRGBA8 img = renderImage(*r, testCamera(1.0f), s, 96, 96);
        std::set<int> greys;
        for (size_t i = 0; i < img.pixels.size(); i += 4) {
          ASSERT_EQ(img.pixels[i], img.pixels[i + 1]);  // only greys: nothing broken
          greys.insert(img.pixels[i]);
        }
        if (path == RenderPath::Reference) continue;
        // One entry: the sphere is its grey (128) on the white background. 256 entries: the
        // shading spreads over many of them.
        if (n == 1) {
          EXPECT_EQ(greys, (std::set<int>{128, 255})) << renderPathName(path) << " " << choiceName(mode);
        } else {
          EXPECT_GT(greys.size(), 20u) << renderPathName(path) << " " << choiceName(mode);
        }
      }
  }
}

TEST_F(Fixture, UnchangedStateIsNotRecomputedOrReuploaded) {
  const Mesh mesh = test::icosphere(4);
  r->scene().setOnly(&mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  const CameraMatrices cam = testCamera(1.0f);
  for (RenderPath path : userRenderPaths()) {
    RenderSettings s;
    s.path = path;
    (void)renderImage(*r, cam, s, 64, 64);
    (void)renderImage(*r, cam, s, 64, 64);
    const FrameStats& st = r->stats();
    EXPECT_EQ(st.lightingRecomputes, 0) << renderPathName(path);
    EXPECT_EQ(st.bufferUploads, 0) << renderPathName(path);
    EXPECT_EQ(st.shaderBuilds, 0) << renderPathName(path);
    EXPECT_EQ(st.lutBuilds, 0) << renderPathName(path);
  }
  // A light that stays fixed in the scene while the camera orbits changes what each triangle
  // receives in its own frame only through view-dependent terms: with no specular and a
  // scene-fixed light, orbiting needs no per-triangle recomputation.
  LightingState& l = r->lighting();
  const float black[4] = {0, 0, 0, 1}, world[4] = {2, 2.5f, 3, 1};
  ASSERT_TRUE(l.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black));
  RenderSettings s;
  s.path = RenderPath::Triangle;
  for (float yaw : {10.0f, 40.0f}) {
    const CameraMatrices c = testCamera(1.0f, yaw);
    l.setModelView(c.view);
    ASSERT_TRUE(l.Lightfv(GL_LIGHT0, GL_POSITION, world));
    (void)renderImage(*r, c, s, 64, 64);
  }
  EXPECT_EQ(r->stats().lightingRecomputes, 0);
  // ... while moving the light does.
  const float moved[4] = {-2, 2.5f, 3, 1};
  ASSERT_TRUE(l.Lightfv(GL_LIGHT0, GL_POSITION, moved));
  (void)renderImage(*r, testCamera(1.0f, 40.0f), s, 64, 64);
  EXPECT_EQ(r->stats().lightingRecomputes, 1);
  // Changing the features (a spotlight) compiles a new variant once.
  ASSERT_TRUE(l.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 60.0f));
  s.path = RenderPath::Pixel;
  (void)renderImage(*r, testCamera(1.0f, 40.0f), s, 64, 64);
  EXPECT_EQ(r->stats().shaderBuilds, 1);
  (void)renderImage(*r, testCamera(1.0f, 40.0f), s, 64, 64);
  EXPECT_EQ(r->stats().shaderBuilds, 0);
}

TEST_F(Fixture, ExtremesProduceNoErrorsOrNaN) {
  const Mesh base = test::icosphere(3);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  for (double size : {1e-6, 1.0, 1e6}) {
    Mesh m = test::icosphere(3);
    for (auto& p : m.positions) p *= float(size);
    for (auto& c : m.faceCentroids) c *= float(size);
    r->scene().setOnly(&m);
    OrbitCamera c(30.0f, 20.0f, 3.0f);
    c.frame(float(size));
    for (RenderPath path : userRenderPaths()) {
      RenderSettings s;
      s.path = path;
      (void)renderImage(*r, c.matrices(1.0f), s, 32, 32);
      const ImageRGBA32F n = test::renderGeometry(*r, c.matrices(1.0f), FrameOutput::EyeNormal, 32, 32);
      for (float v : n.pixels) ASSERT_TRUE(std::isfinite(v)) << size;
    }
  }
  r->scene().setOnly(&base);
  // Near/far ratios from 1e-4 to 1e6, and a camera inside the model.
  for (auto [nearP, farP] : {std::pair{1.0f, 1.0001f}, std::pair{1e-3f, 1e3f}, std::pair{1e-4f, 100.0f}}) {
    CameraMatrices cam;
    cam.view = glm::lookAt(glm::vec3(0, 0, 3), glm::vec3(0), glm::vec3(0, 1, 0));
    cam.projection = glm::perspective(glm::radians(40.0f), 1.0f, nearP, farP);
    for (RenderPath path : userRenderPaths()) {
      RenderSettings s;
      s.path = path;
      (void)renderImage(*r, cam, s, 32, 32);
    }
  }
  CameraMatrices inside;
  inside.view = glm::lookAt(glm::vec3(0.1f, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
  inside.projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.01f, 10.0f);
  for (RenderPath path : userRenderPaths()) {
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 img = renderImage(*r, inside, s, 32, 32);
    EXPECT_EQ(img.width, 32);
  }
  // 1x1 and 8192x8192 framebuffers.
  for (int size : {1, 8192})
    for (RenderPath path : {RenderPath::Stencil, RenderPath::Pixel, RenderPath::Smooth}) {
      RenderSettings s;
      s.path = path;
      const ImageRGBA8 img = renderImage(*r, testCamera(1.0f), s, size, size);
      EXPECT_EQ(img.width, size);
    }
}

TEST_F(Fixture, ImmediateBeginRenderTriangleEndDrawsLikeTheRetainedMesh) {
  const Mesh sphere = test::icosphere(3);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  const CameraMatrices cam = testCamera(1.0f);
  RenderSettings s;
  s.path = RenderPath::Stencil;
  r->scene().setOnly(&sphere);
  const ImageRGBA8 retained = renderImage(*r, cam, s, 160, 160);

  PaletteRenderer immediate(*r);
  EXPECT_FALSE(immediate.IntensityRangeScale(-1.0f));
  EXPECT_TRUE(immediate.IntensityRangeScale(1.0f));
  immediate.ColorMatchMode(MatchMode::Intensity);
  const float spec[4] = {0.35f, 0.35f, 0.35f, 1.0f};
  EXPECT_TRUE(immediate.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec));  // same state as the fixture's
  EXPECT_FALSE(immediate.Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, 120.0f));
  auto target = OffscreenTarget::create(160, 160);
  ASSERT_TRUE(target);
  target->bind();
  immediate.Begin();
  for (size_t t = 0; t < sphere.triangleCount(); ++t)
    immediate.RenderTriangle({{sphere.positions[sphere.indices[t * 3]], sphere.positions[sphere.indices[t * 3 + 1]],
                               sphere.positions[sphere.indices[t * 3 + 2]]}});
  ASSERT_TRUE(immediate.End(cam, {0, 0, 160, 160}));
  const ImageRGBA8 drawn = target->readRGBA8();
  EXPECT_LE(countDiffering(retained, drawn), 160 * 160 / 1000);
  EXPECT_GT(r->stats().nonEmptyBuckets, 3);
  EXPECT_FALSE(immediate.End(cam, {0, 0, 160, 160}));  // End without Begin is refused
}

TEST_F(Fixture, CelBandsAreHardWithAntialiasedEdges) {
  const Mesh sphere = test::icosphere(4);
  r->scene().setOnly(&sphere);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("cel")));
  RenderSettings s;
  s.path = RenderPath::Smooth;
  s.bands = {0.9f, 1.6f, 2.3f};
  const ImageRGBA8 img = renderImage(*r, testCamera(1.0f), s, 200, 200);
  std::map<std::uint32_t, int> colours;
  int covered = 0;
  for (size_t i = 0; i < img.pixels.size(); i += 4) {
    const std::uint32_t c = std::uint32_t(img.pixels[i]) << 16 | std::uint32_t(img.pixels[i + 1]) << 8 | img.pixels[i + 2];
    if (c == 0xFFFFFF) continue;  // background
    ++colours[c];
    ++covered;
  }
  // The four flat tones cover almost everything; the rest are blends along the band edges.
  std::vector<int> counts;
  for (const auto& [c, n] : colours) counts.push_back(n);
  std::sort(counts.rbegin(), counts.rend());
  ASSERT_GE(counts.size(), 5u);  // edges are antialiased: some in-between colours exist
  const int flat = counts[0] + counts[1] + counts[2] + (counts.size() > 3 ? counts[3] : 0);
  EXPECT_GT(flat, covered * 9 / 10);
  // Moving a threshold moves the band: the image changes.
  s.bands = {0.6f, 1.6f, 2.3f};
  EXPECT_GT(countDiffering(img, renderImage(*r, testCamera(1.0f), s, 200, 200)), 100);
}

// ---- Golden images -----------------------------------------------------------------------

TEST_F(Fixture, GoldenImagesPerPath) {
  auto mesh = loadMesh(sourcePath("models/teapot.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("crosshatch")));
  const CameraMatrices cam = testCamera(1.0f);
  for (RenderPath path : userRenderPaths()) {
    RenderSettings s;
    s.path = path;
    // llvmpipe is deterministic; a GPU may differ at edges by a texel here and there.
    expectGolden(std::string("teapot-crosshatch-") + renderPathName(path), renderImage(*r, cam, s, 160, 160), 0.005, 0.004);
  }
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("gooch")));
  RenderSettings s;
  s.path = RenderPath::Smooth;
  s.match = MatchMode::Colors;
  expectGolden("teapot-gooch-smooth", renderImage(*r, cam, s, 160, 160), 0.005, 0.004);
  ASSERT_TRUE(r->lighting().setToneModel(ToneModel::Gooch, ToneParameters{}));
  expectGolden("teapot-gooch-tone-smooth", renderImage(*r, cam, s, 160, 160), 0.005, 0.004);
}

TEST_F(Fixture, GoldenImagesOfLinesOverEachPath) {
  auto mesh = loadMesh(sourcePath("models/teapot.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(shippedPalette("cel")));
  const CameraMatrices cam = testCamera(1.0f);
  for (RenderPath path : userRenderPaths()) {
    RenderSettings s;
    s.path = path;
    s.lines.silhouettes = s.lines.creases = s.lines.boundaries = true;
    expectGolden(std::string("teapot-lines-") + renderPathName(path), renderImage(*r, cam, s, 160, 160), 0.005, 0.004);
    EXPECT_GT(r->stats().lines, 50);
  }
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.lines.silhouettes = true;
  s.lines.sketchy = true;
  s.lines.imageSpace = true;
  const ImageRGBA8 a = renderImage(*r, cam, s, 160, 160);
  expectGolden("teapot-lines-sketchy-image-space", a, 0.005, 0.004);
  // Sketchy strokes are stable from frame to frame.
  EXPECT_EQ(countDiffering(a, renderImage(*r, cam, s, 160, 160)), 0);
}

TEST_F(Fixture, HiddenLinesAreRemovedByDepth) {
  // A cube's creases, seen through nothing and then behind an opaque plate: the plate hides them.
  std::vector<Triangle> cube;
  const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  for (const auto& t : f) cube.push_back({{c[t[0]] * 0.4f, c[t[1]] * 0.4f, c[t[2]] * 0.4f}});
  std::vector<Triangle> withPlate = cube;
  withPlate.push_back({{glm::vec3(-0.9f, -0.9f, 0.8f), glm::vec3(0.9f, -0.9f, 0.8f), glm::vec3(0.9f, 0.9f, 0.8f)}});
  withPlate.push_back({{glm::vec3(-0.9f, -0.9f, 0.8f), glm::vec3(0.9f, 0.9f, 0.8f), glm::vec3(-0.9f, 0.9f, 0.8f)}});
  ASSERT_TRUE(r->palettes().setMain(greyRamp(4)));
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.lines.creases = true;
  s.lines.creaseColour = glm::vec3(1, 0, 0);
  auto red = [](const ImageRGBA8& im) {
    int n = 0;
    for (size_t i = 0; i < im.pixels.size(); i += 4) n += im.pixels[i] > 200 && im.pixels[i + 1] < 60;
    return n;
  };
  const CameraMatrices cam = testCamera(1.0f, 20.0f, 15.0f);
  const Mesh open = meshFromTriangles(cube), hidden = meshFromTriangles(withPlate);
  r->scene().setOnly(&open);
  const int visible = red(renderImage(*r, cam, s, 128, 128));
  r->scene().setOnly(&hidden);
  const int behind = red(renderImage(*r, cam, s, 128, 128));
  EXPECT_GT(visible, 200);
  EXPECT_EQ(behind, 0);
}

}  // namespace
}  // namespace npr
