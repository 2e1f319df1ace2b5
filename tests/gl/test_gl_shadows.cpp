// GL tier: the ground plane and cast shadows. A unit cube standing on the ground plane, lit
// from one side: the ground where the cube's shadow falls gets a darker palette entry than the
// lit ground, in every path and for directional, spot and point lights; without shadows the
// two are the same (the per-triangle paths get shadows from the GPU per-triangle lighting,
// whose entries agree with the CPU's). A flat plate lit at grazing angles shows no acne at any
// zoom. Maps are redrawn only when a light moves relative to the model. Baked ambient occlusion is
// lower in a concave corner than on convex ones, and darkens the frame there. Control-image
// palettes (seed 003) fall where the ray-cast reference says the light is blocked, weigh the
// three palettes as a partition of unity in every path, and light their pixels as the path does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "renderer/immediate_api.h"
#include "renderer/mesh/mesh_builder.h"
#include "renderer/mesh/mesh_loader.h"
#include "support/shadow_reference.h"
#include "support/test_util.h"

namespace npr {
namespace {

using Fixture = test::RendererFixture;
constexpr int kSize = 256;

Mesh unitCube() {
  const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const int f[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  std::vector<Triangle> tris;
  for (const auto& t : f) tris.push_back({{c[t[0]] * 0.5f, c[t[1]] * 0.5f, c[t[2]] * 0.5f}});
  return meshFromTriangles(tris);
}

// Window pixel (x, y from the top) of a model-space point.
glm::ivec2 pixelOf(const CameraMatrices& cam, const glm::vec3& p, int w, int h) {
  const glm::vec4 c = cam.projection * cam.view * glm::vec4(p, 1.0f);
  const glm::vec2 win = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(w, h);
  return {int(win.x), h - 1 - int(win.y)};
}

int entryAt(const ImageRGBA8& entries, glm::ivec2 p) {
  EXPECT_TRUE(p.x >= 0 && p.y >= 0 && p.x < entries.width && p.y < entries.height) << p.x << ", " << p.y;
  if (p.x < 0 || p.y < 0 || p.x >= entries.width || p.y >= entries.height) return -1;
  return entries.pixels[(size_t(p.y) * entries.width + size_t(p.x)) * 4];
}

// `m` moved by `place` over a square plate at y = -0.6, both in one model.
template <class Place>
Mesh overPlate(const Mesh& m, Place place) {
  std::vector<Triangle> scene;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    Triangle tri;
    for (int k = 0; k < 3; ++k) tri.v[size_t(k)] = place(m.positions[m.indices[t * 3 + size_t(k)]]);
    scene.push_back(tri);
  }
  Triangle a, b;
  a.v = {glm::vec3(-1.5f, -0.6f, -1.5f), glm::vec3(-1.5f, -0.6f, 1.5f), glm::vec3(1.5f, -0.6f, 1.5f)};
  b.v = {glm::vec3(-1.5f, -0.6f, -1.5f), glm::vec3(1.5f, -0.6f, 1.5f), glm::vec3(1.5f, -0.6f, -1.5f)};
  scene.push_back(a);
  scene.push_back(b);
  return meshFromTriangles(scene);
}

// A cube floating above the plate.
Mesh floatingCubeOverPlate() {
  return overPlate(unitCube(), [](const glm::vec3& p) { return p * 0.6f + glm::vec3(0.0f, 0.2f, 0.0f); });
}

// A torus tilted 30 degrees over the plate: it shadows the plate and, where the light is low,
// its own far side.
Mesh tiltedTorusOverPlate() {
  const glm::mat3 tilt = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(1.0f, 0.0f, 0.0f)));
  return overPlate(torus(96, 32), [&](const glm::vec3& p) { return tilt * (p * 0.7f) + glm::vec3(0.0f, 0.15f, 0.0f); });
}

// One solid entry of `colour` (8-bit values): every lit colour matches it.
Palette solidPalette(const std::string& name, glm::u8vec3 colour) {
  Palette p;
  p.name = name;
  PaletteEntry e;
  e.image = ImageRGBA8{4, 4, std::vector<std::uint8_t>(64, 255)};
  for (std::size_t k = 0; k < 64; k += 4)
    for (int ch = 0; ch < 3; ++ch) e.image.pixels[k + std::size_t(ch)] = colour[ch];
  e.average = glm::vec3(colour) / 255.0f;
  e.intensity = e.average.r + e.average.g + e.average.b;
  p.entries.push_back(std::move(e));
  return p;
}

CameraMatrices sceneCamera() {
  OrbitCamera c(0.0f, 35.0f, 3.0f);
  c.frame(2.2f);  // the cube and the ground around it
  return c.matrices(1.0f);
}

struct Shadows : Fixture {
  Mesh cube = unitCube();
  CameraMatrices cam = sceneCamera();
  void SetUp() override {
    Fixture::SetUp();
    ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
    r->scene().setOnly(&cube);
  }
  // Light 0 at `position` (model space, w = 0: a direction), set through the camera's view as
  // the viewer does.
  void light(const glm::vec4& position, float spotCutoff = 180.0f, const glm::vec3& spotDirection = {0, -1, 0}) {
    r->lighting().setModelView(cam.view);
    const float pos[4] = {position.x, position.y, position.z, position.w};
    ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos));
    const float dir[3] = {spotDirection.x, spotDirection.y, spotDirection.z};
    ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_SPOT_DIRECTION, dir));
    ASSERT_TRUE(r->lighting().Lightf(GL_LIGHT0, GL_SPOT_CUTOFF, spotCutoff));
  }
  // The entries at a ground point in the cube's shadow (x = -1) and a lit one (x = +1.3).
  std::pair<int, int> shadowedAndLit(const RenderSettings& s) {
    const ImageRGBA8 e = test::renderEntries(*r, cam, s, kSize, kSize);
    const float y = -0.5f;
    return {entryAt(e, pixelOf(cam, {-1.0f, y, 0.0f}, kSize, kSize)), entryAt(e, pixelOf(cam, {1.3f, y, 0.0f}, kSize, kSize))};
  }
};

TEST_F(Shadows, CubeShadowOnTheGroundIsDarkerInEveryPath) {
  light({1.0f, 1.0f, 0.0f, 0.0f});  // from +x, 45 degrees up: the shadow reaches x = -1.5
  // (entries: the smooth path's selection is a blend, read as floats elsewhere; the
  // per-triangle paths light on the GPU with shadows, shading/gpu_triangle_lighting.h)
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Triangle, RenderPath::Stencil}) {
    SCOPED_TRACE(pathInfo(path).name);
    RenderSettings s;
    s.path = path;
    s.ground = true;
    const auto [offShadow, offLit] = shadowedAndLit(s);
    EXPECT_EQ(offShadow, offLit);  // without shadows the flat ground has one tone
    s.shadows = true;
    const auto [shadow, lit] = shadowedAndLit(s);
    EXPECT_EQ(lit, offLit);
    EXPECT_GE(shadow, lit + 1) << "the crosshatch palette's entries darken with the index";
  }
}

TEST_F(Shadows, GroundShadowTextureAgreesWithPerPixelLookups) {
  // The ground's shadows read from its texture choose the entries the per-pixel lookups choose,
  // but along the shadow's soft edge, for each kind of light. Somewhere along those edges the
  // two differ: the ground does read its texture (on this machine 6, 11, 0 and 8 pixels).
  int edgeDifferences = 0;
  for (const glm::vec4 position : {glm::vec4(1.0f, 1.0f, 0.3f, 0.0f), glm::vec4(2.0f, 2.0f, 0.5f, 1.0f)}) {
    light(position);
    for (RenderPath path : {RenderPath::Pixel, RenderPath::Smooth}) {
      SCOPED_TRACE(pathInfo(path).name);
      RenderSettings s;
      s.path = path;
      s.ground = s.shadows = true;
      s.tuning.groundShadowTexture = false;
      const ImageRGBA8 perPixel = test::renderImage(*r, cam, s, kSize, kSize);
      s.tuning.groundShadowTexture = true;
      const ImageRGBA8 textured = test::renderImage(*r, cam, s, kSize, kSize);
      s.shadows = false;
      const ImageRGBA8 unshadowed = test::renderImage(*r, cam, s, kSize, kSize);
      const int shadowPixels = test::countDiffering(perPixel, unshadowed);
      EXPECT_GT(shadowPixels, 1500) << "the scene must show a shadow";
      EXPECT_LT(test::countDiffering(perPixel, textured), shadowPixels / 20) << "w " << position.w;
      edgeDifferences += test::countDiffering(perPixel, textured);
    }
  }
  EXPECT_GT(edgeDifferences, 0) << "the ground's shadow texture is not read";
}

TEST_F(Shadows, GoochToneCoolsInCastShadow) {
  // The cool-to-warm tone takes the first light's shadow: the ground in the cube's shadow gets
  // the terminator's (cooler) tone, the lit ground keeps its warm one.
  light({1.0f, 1.0f, 0.0f, 0.0f});
  ASSERT_TRUE(r->lighting().setToneModel(ToneModel::Gooch, r->lighting().toneParameters()));
  RenderSettings s;
  s.path = RenderPath::Reference;
  s.ground = true;
  auto at = [&](const ImageRGBA8& img, glm::vec3 p) {
    const glm::ivec2 q = pixelOf(cam, p, kSize, kSize);
    const std::uint8_t* c = &img.pixels[(size_t(q.y) * kSize + size_t(q.x)) * 4];
    return glm::ivec3(c[0], c[1], c[2]);
  };
  const ImageRGBA8 plain = test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_EQ(at(plain, {-1.0f, -0.5f, 0.0f}), at(plain, {1.3f, -0.5f, 0.0f}));
  s.shadows = true;
  const ImageRGBA8 shadowed = test::renderImage(*r, cam, s, kSize, kSize);
  const glm::ivec3 inShadow = at(shadowed, {-1.0f, -0.5f, 0.0f}), lit = at(shadowed, {1.3f, -0.5f, 0.0f});
  EXPECT_EQ(lit, at(plain, {1.3f, -0.5f, 0.0f}));
  EXPECT_GT(inShadow.b - inShadow.r, lit.b - lit.r + 20) << "shadow " << inShadow.r << "," << inShadow.b << " lit " << lit.r << "," << lit.b;
  ASSERT_TRUE(r->lighting().setToneModel(ToneModel::OpenGL, r->lighting().toneParameters()));
}

TEST_F(Shadows, SpotAndPointLightsCastShadowsToo) {
  RenderSettings s;
  s.ground = true;
  s.shadows = true;
  light({2.0f, 2.0f, 0.0f, 1.0f}, 60.0f, glm::normalize(glm::vec3(-1.0f, -1.0f, 0.0f)));  // spot
  auto [shadow, lit] = shadowedAndLit(s);
  EXPECT_GE(shadow, lit + 1) << "spot";
  light({2.0f, 2.0f, 0.0f, 1.0f});  // point, outside the casters: one map toward them
  std::tie(shadow, lit) = shadowedAndLit(s);
  EXPECT_GE(shadow, lit + 1) << "point";
  EXPECT_EQ(r->stats().shadowLayers, 1);
  light({0.55f, 0.55f, 0.3f, 1.0f});  // point among the casters (inside their bounding sphere): six maps
  std::tie(shadow, lit) = shadowedAndLit(s);
  EXPECT_GE(shadow, lit + 1) << "point among the casters";
  EXPECT_EQ(r->stats().shadowLayers, 6);
}

TEST_F(Shadows, NoAcneOnAPlateAtGrazingLight) {
  // A large flat plate (the model) over the ground, lit at a few degrees above its plane, seen
  // from near and far: with shadows it must show what it shows without (nothing shadows it).
  std::vector<Triangle> plate(2);
  plate[0].v = {glm::vec3(-1, 0, -1), glm::vec3(-1, 0, 1), glm::vec3(1, 0, 1)};
  plate[1].v = {glm::vec3(-1, 0, -1), glm::vec3(1, 0, 1), glm::vec3(1, 0, -1)};
  const Mesh m = meshFromTriangles(plate);
  r->scene().setOnly(&m);
  for (float elevation : {3.0f, 10.0f, 30.0f})
    for (float distance : {1.5f, 3.0f, 8.0f}) {
      OrbitCamera c(20.0f, 40.0f, distance);
      cam = c.matrices(1.0f);
      const float e = glm::radians(elevation);
      light({std::cos(e), std::sin(e), 0.3f, 0.0f});
      RenderSettings s;
      s.ground = true;
      const ImageRGBA8 plain = test::renderEntries(*r, cam, s, kSize, kSize);
      s.shadows = true;
      const ImageRGBA8 shadowed = test::renderEntries(*r, cam, s, kSize, kSize);
      const ImageRGBA32F cover = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, kSize, kSize);
      int covered = 0, differ = 0;
      for (std::size_t i = 0; i < cover.pixels.size() / 4; ++i) {
        if (cover.pixels[i * 4 + 3] == 0.0f) continue;  // the plate only
        ++covered;
        differ += plain.pixels[i * 4] != shadowed.pixels[i * 4];
      }
      EXPECT_GT(covered, 500) << elevation << " deg, distance " << distance;
      EXPECT_EQ(differ, 0) << elevation << " deg, distance " << distance << ": acne on " << differ << " of " << covered;
    }
  r->scene().setOnly(&cube);
}

TEST_F(Shadows, AgreeWithARayCastReference) {
  // A cube floating above a plate, and a tilted torus over it (both in the model), directional
  // lights from the side: the pixels the reference path draws darker with shadows are those a
  // ray toward the light from their surface point cannot leave (away from a 2-pixel band along
  // the shadows' edges).
  const std::pair<const char*, Mesh> scenes[] = {{"cube over a plate", floatingCubeOverPlate()}, {"tilted torus over a plate", tiltedTorusOverPlate()}};
  for (const auto& [name, m] : scenes) {
    r->scene().setOnly(&m);
    for (const glm::vec3 dir : {glm::vec3(1.0f, 1.5f, 0.4f), glm::vec3(-0.6f, 1.0f, -0.8f), glm::vec3(0.2f, 1.0f, 0.1f), glm::vec3(1.0f, 0.35f, 0.2f)}) {
      const glm::vec3 toLight = glm::normalize(dir);
      light(glm::vec4(toLight, 0.0f));
      RenderSettings s;
      s.path = RenderPath::Reference;
      const ImageRGBA8 plain = test::renderImage(*r, cam, s, kSize, kSize);
      s.shadows = true;
      const ImageRGBA8 shadowed = test::renderImage(*r, cam, s, kSize, kSize);
      const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
      const ImageRGBA32F nrm = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, kSize, kSize);
      const test::ShadowAgreement a = test::compareShadows(m, toLight, cam, pos, nrm, plain, shadowed);
      EXPECT_GT(a.compared, 8000u);
      EXPECT_GT(a.shadowed, 200u) << "the scene must have shadows to compare";
      EXPECT_GE(a.agreement, 0.99) << name << ", light " << dir.x << ", " << dir.y << ", " << dir.z << ": " << a.shadowed
                                   << " shadowed of " << a.compared;
      std::printf("%s, light (%.1f, %.2f, %.1f): %.2f%% of %zu lit-side pixels agree, %zu shadowed\n", name, dir.x, dir.y,
                  dir.z, 100.0 * a.agreement, std::size_t(a.compared), std::size_t(a.shadowed));
    }
  }
  r->scene().setOnly(&cube);
}

TEST_F(Shadows, GpuAndCpuPerTriangleEntriesAgree) {
  // Without shadows the two lightings compute the same equation in float: entries differ only
  // where a triangle's tone sits on a boundary between two entries.
  auto bunny = loadMesh(test::sourcePath("models/bunny.obj"));
  ASSERT_TRUE(bunny) << bunny.error();
  r->scene().setOnly(&*bunny);
  const CameraMatrices view = test::testCamera(1.0f);
  for (bool twoSided : {false, true}) {
    ASSERT_TRUE(r->lighting().LightModeli(GL_LIGHT_MODEL_TWO_SIDE, twoSided ? 1 : 0));
    RenderSettings cpu, gpu;
    cpu.path = gpu.path = RenderPath::Triangle;
    cpu.triangleLighting = TriangleLighting::Cpu;
    gpu.triangleLighting = TriangleLighting::Gpu;
    (void)test::renderImage(*r, view, cpu, 64, 64);
    const std::vector<std::uint8_t> onCpu = r->scene().first()->triangles().shading().entry;
    (void)test::renderImage(*r, view, gpu, 64, 64);
    const std::vector<std::uint8_t> onGpu = r->scene().first()->triangles().shading().entry;
    ASSERT_EQ(onCpu.size(), bunny->triangleCount());
    ASSERT_EQ(onGpu.size(), onCpu.size());
    std::size_t differ = 0, far = 0;
    for (std::size_t t = 0; t < onCpu.size(); ++t) {
      differ += onCpu[t] != onGpu[t];
      far += std::abs(int(onCpu[t]) - int(onGpu[t])) > 1;
    }
    EXPECT_LE(double(differ), 0.005 * double(onCpu.size())) << (twoSided ? "two-sided" : "one-sided");
    EXPECT_EQ(far, 0u);  // never more than the neighbouring entry
  }
  r->scene().setOnly(&cube);
}

TEST_F(Shadows, MapsAreRedrawnOnlyWhenTheLightMovesRelativeToTheModel) {
  light({1.0f, 1.0f, 0.0f, 0.0f});
  RenderSettings s;
  s.shadows = true;
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_EQ(r->stats().shadowMapRenders, 1);
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_EQ(r->stats().shadowMapRenders, 0);
  light({1.0f, 2.0f, 0.0f, 0.0f});
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_EQ(r->stats().shadowMapRenders, 1);
  s.ground = true;  // the scene changed
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_EQ(r->stats().shadowMapRenders, 1);
}

// A floor and a wall meeting at a right angle (a concave corner along x at y = 0, z = 0), as
// grids so there are vertices near and far from the corner.
Mesh innerCorner() {
  std::vector<glm::vec3> v;
  std::vector<std::array<int, 3>> t;
  const int n = 8;
  auto grid = [&](auto at) {
    const int base = int(v.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) v.push_back(at(float(i) / n, float(j) / n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = base + j * (n + 1) + i;
        t.push_back({a, a + n + 1, a + n + 2});
        t.push_back({a, a + n + 2, a + 1});
      }
  };
  grid([](float u, float w) { return glm::vec3(u * 2.0f - 1.0f, 0.0f, w); });  // floor, facing +y
  grid([](float u, float w) { return glm::vec3(u * 2.0f - 1.0f, w, 0.0f); });  // wall, facing +z
  Mesh m;
  buildTriMesh(v, t, m);
  finalizeMesh(m);
  return m;
}

TEST_F(Shadows, OcclusionIsLowerInAConcaveCornerThanOnAConvexOne) {
  const Mesh corner = innerCorner();
  r->scene().setOnly(&corner);
  RenderSettings s;
  s.occlusion = true;
  (void)test::renderImage(*r, cam, s, 64, 64);
  ASSERT_NE(r->scene().first()->occlusionBake(), nullptr);
  ASSERT_TRUE(r->scene().first()->occlusionBake()->done());
  const std::vector<float>& ao = r->scene().first()->occlusionBake()->values();
  ASSERT_EQ(ao.size(), corner.positions.size());
  float inCorner = 1.0f, open = 0.0f;
  for (std::size_t i = 0; i < ao.size(); ++i) {
    const glm::vec3 p = corner.positions[i];
    if (std::fabs(p.x) > 0.5f) continue;  // away from the sheets' side edges
    if (p.y < 0.01f && p.z > 0.1f && p.z < 0.2f) inCorner = std::min(inCorner, ao[i]);  // floor next to the wall
    if (p.y < 0.01f && p.z > 0.99f) open = std::max(open, ao[i]);                        // floor's far edge
  }
  EXPECT_LT(inCorner, 0.75f);
  EXPECT_GT(open, inCorner + 0.1f);
  // A cube's corners and faces are convex: open to their whole hemisphere.
  r->scene().setOnly(&cube);
  (void)test::renderImage(*r, cam, s, 64, 64);
  ASSERT_TRUE(r->scene().first()->occlusionBake() && r->scene().first()->occlusionBake()->done());
  for (float a : r->scene().first()->occlusionBake()->values()) EXPECT_GT(a, 0.95f);
  // And the frame gets darker where it is occluded, in every path (the per-triangle paths scale
  // each face by its vertices' mean occlusion).
  // (Measured in tone alone: a grey ramp, no pattern to add noise to the sums.)
  r->scene().setOnly(&corner);
  ASSERT_TRUE(r->palettes().setMain(test::greyRamp(16)));
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Smooth, RenderPath::Triangle, RenderPath::Stencil}) {
    RenderSettings off, on = s;
    off.path = on.path = path;
    const ImageRGBA8 plain = test::renderImage(*r, cam, off, 96, 96), dark = test::renderImage(*r, cam, on, 96, 96);
    // Ink (255 - grey) over the frame: the background adds none, so the model's share counts.
    double inkPlain = 0.0, inkDark = 0.0;
    for (std::size_t i = 0; i < plain.pixels.size(); i += 4) {
      inkPlain += 255 - plain.pixels[i + 1];
      inkDark += 255 - dark.pixels[i + 1];
    }
    EXPECT_GT(inkDark, (path == RenderPath::Smooth ? 1.003 : 1.03) * inkPlain) << pathInfo(path).name;  // smooth: the blend softens it
  }
  r->scene().setOnly(&cube);
}

TEST_F(Shadows, ControlPalettesFallWhereRaysAreBlocked) {
  // Seed 003's control images: a shadow palette drawn where the light is blocked. White main
  // palette, black shadow palette: the frame darkens exactly where a ray toward the light from
  // the surface hits the scene (the ray-cast reference of AgreeWithARayCastReference).
  const Mesh m = floatingCubeOverPlate();
  r->scene().setOnly(&m);
  ASSERT_TRUE(r->palettes().setMain(solidPalette("white", {255, 255, 255})));
  for (const glm::vec3 dir : {glm::vec3(1.0f, 1.5f, 0.4f), glm::vec3(-0.6f, 1.0f, -0.8f)}) {
    const glm::vec3 toLight = glm::normalize(dir);
    light(glm::vec4(toLight, 0.0f));
    RenderSettings s;
    s.shadows = true;
    r->palettes().clearControl(ControlParameter::Shadow);
    const ImageRGBA8 plain = test::renderImage(*r, cam, s, kSize, kSize);
    ASSERT_TRUE(r->palettes().setControl(ControlParameter::Shadow, solidPalette("black", {0, 0, 0})));
    const ImageRGBA8 drawn = test::renderImage(*r, cam, s, kSize, kSize);
    const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
    const ImageRGBA32F nrm = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, kSize, kSize);
    const test::ShadowAgreement a = test::compareShadows(m, toLight, cam, pos, nrm, plain, drawn);
    EXPECT_GT(a.shadowed, 200u);
    EXPECT_GE(a.agreement, 0.99) << "light " << dir.x << ", " << dir.y << ", " << dir.z;
  }
  r->palettes().clearControl(ControlParameter::Shadow);
  r->scene().setOnly(&cube);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
}

TEST_F(Shadows, ControlPalettesWeighAsAPartitionOfUnityInEveryPath) {
  // Main blue, occlusion green, shadow red, one solid entry each: every covered pixel's
  // channels are the three weights, which must sum to 1 (within the 8-bit blends' rounding),
  // in every palette path. The per-pixel paths show both parameters.
  const Mesh m = floatingCubeOverPlate();
  r->scene().setOnly(&m);
  ASSERT_TRUE(r->palettes().setMain(solidPalette("blue", {0, 0, 255})));
  ASSERT_TRUE(r->palettes().setControl(ControlParameter::Shadow, solidPalette("red", {255, 0, 0})));
  ASSERT_TRUE(r->palettes().setControl(ControlParameter::Occlusion, solidPalette("green", {0, 255, 0})));
  light(glm::vec4(glm::normalize(glm::vec3(1.0f, 1.5f, 0.4f)), 0.0f));
  const ImageRGBA32F cover = test::renderGeometry(*r, cam, FrameOutput::EyeNormal, kSize, kSize);
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Smooth, RenderPath::Vertex, RenderPath::Triangle, RenderPath::Stencil}) {
    SCOPED_TRACE(pathInfo(path).name);
    RenderSettings s;
    s.path = path;
    s.shadows = s.occlusion = true;
    const ImageRGBA8 img = test::renderImage(*r, cam, s, kSize, kSize);
    int covered = 0, off = 0, shadowed = 0, occluded = 0;
    for (std::size_t i = 0; i < cover.pixels.size() / 4; ++i) {
      if (cover.pixels[i * 4 + 3] == 0.0f) continue;
      ++covered;
      const int r8 = img.pixels[i * 4], g8 = img.pixels[i * 4 + 1], b8 = img.pixels[i * 4 + 2];
      off += std::abs(r8 + g8 + b8 - 255) > 3;
      shadowed += r8 > 230;
      occluded += g8 > 25;
    }
    EXPECT_GT(covered, 8000);
    EXPECT_EQ(off, 0) << "pixels whose weights do not sum to 1";
    if (path != RenderPath::Vertex) {  // per vertex, the plate's four corners are all lit and open
      EXPECT_GT(shadowed, 200);
      EXPECT_GT(occluded, 100);
    }
  }
  r->palettes().clearControl(ControlParameter::Shadow);
  r->palettes().clearControl(ControlParameter::Occlusion);
  r->scene().setOnly(&cube);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
}

TEST_F(Shadows, AControlPaletteLikeTheMainOneChangesNothing) {
  // Each control layer lights its pixels as the path does: a shadow palette equal to the main
  // one, blended over it, leaves the frame as it was (within the blend's rounding), two-sided
  // lighting included (the per-vertex path lights both sides). The ground's grid gives the
  // per-vertex path vertices in the shadow.
  ASSERT_TRUE(r->palettes().setMain(test::greyRamp(16)));
  light({1.0f, 1.0f, 0.3f, 0.0f});  // the cube's shadow across the ground's grid
  for (int twoSided : {0, 1}) {
    ASSERT_TRUE(r->lighting().LightModeli(GL_LIGHT_MODEL_TWO_SIDE, twoSided));
    for (RenderPath path : {RenderPath::Pixel, RenderPath::Vertex, RenderPath::Smooth}) {
      SCOPED_TRACE(testing::Message() << pathInfo(path).name << (twoSided ? ", two-sided" : ""));
      RenderSettings s;
      s.path = path;
      s.shadows = s.ground = true;
      r->palettes().clearControl(ControlParameter::Shadow);
      const ImageRGBA8 plain = test::renderImage(*r, cam, s, kSize, kSize);
      ASSERT_TRUE(r->palettes().setControl(ControlParameter::Shadow, test::greyRamp(16)));
      const ImageRGBA8 layered = test::renderImage(*r, cam, s, kSize, kSize);
      int off = 0;
      for (std::size_t i = 0; i < plain.pixels.size(); ++i) off += std::abs(int(plain.pixels[i]) - int(layered.pixels[i])) > 2;
      EXPECT_EQ(off, 0) << "channels changed by the layer";
    }
  }
  ASSERT_TRUE(r->lighting().LightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0));
  r->palettes().clearControl(ControlParameter::Shadow);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
}

TEST_F(Shadows, ScreenOcclusionDarkensConcaveCornersAndLeavesConvexShapesAlone) {
  // Per pixel, every frame, from what the frame shows (measured in tone: a grey ramp): in the
  // per-pixel paths the inner corner's floor next to the wall gets a darker entry than its far
  // edge, which it does not without occlusion; a cube, convex everywhere, is left as it was;
  // and the ground just in front of a cube standing on it darkens.
  ASSERT_TRUE(r->palettes().setMain(test::greyRamp(16)));
  const Mesh corner = innerCorner();
  RenderSettings on;
  on.occlusion = true;
  on.occlusionMethod = OcclusionMethod::Screen;
  light({0.0f, 1.0f, 1.0f, 0.0f});  // the floor and the wall lit alike
  auto nearAndFar = [&](const RenderSettings& s, glm::vec3 nearPoint, glm::vec3 farPoint) {
    const ImageRGBA8 e = test::renderEntries(*r, cam, s, kSize, kSize);
    return std::pair{entryAt(e, pixelOf(cam, nearPoint, kSize, kSize)), entryAt(e, pixelOf(cam, farPoint, kSize, kSize))};
  };
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Smooth}) {
    SCOPED_TRACE(pathInfo(path).name);
    RenderSettings off;
    off.path = on.path = path;
    if (path == RenderPath::Pixel) {  // entries (the smooth path's selection is a blend)
      r->scene().setOnly(&corner);
      const auto [plainNear, plainFar] = nearAndFar(off, {0.0f, 0.0f, 0.04f}, {0.0f, 0.0f, 0.9f});
      EXPECT_EQ(plainNear, plainFar);
      const auto [near, far] = nearAndFar(on, {0.0f, 0.0f, 0.04f}, {0.0f, 0.0f, 0.9f});
      EXPECT_GE(near, far + 2) << "floor by the wall " << near << ", at its far edge " << far;
    }
    r->scene().setOnly(&cube);
    const ImageRGBA8 plain = test::renderImage(*r, cam, off, 128, 128), screen = test::renderImage(*r, cam, on, 128, 128);
    EXPECT_LT(test::countDiffering(plain, screen), 128 * 128 / 100) << "a convex cube is occluded";
  }
  RenderSettings s = on;
  s.path = RenderPath::Pixel;
  s.ground = true;
  const auto [near, far] = nearAndFar(s, {0.0f, -0.5f, 0.6f}, {0.0f, -0.5f, 1.6f});
  EXPECT_GE(near, far + 1) << "ground in front of the cube " << near << ", further out " << far;
  s.occlusion = false;
  const auto [flatNear, flatFar] = nearAndFar(s, {0.0f, -0.5f, 0.6f}, {0.0f, -0.5f, 1.6f});
  EXPECT_EQ(flatNear, flatFar);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
}

TEST_F(Shadows, OcclusionBakesInStepsWithABudget) {
  r->setOcclusionBudget(1e-6);  // one direction per frame
  RenderSettings s;
  s.occlusion = true;
  (void)test::renderImage(*r, cam, s, 32, 32);
  ASSERT_NE(r->scene().first()->occlusionBake(), nullptr);
  EXPECT_EQ(r->scene().first()->occlusionBake()->directionsDone(), 1);
  EXPECT_TRUE(r->scene().first()->occlusionBake()->values().empty());
  for (int f = 1; f < r->scene().first()->occlusionBake()->directions(); ++f) (void)test::renderImage(*r, cam, s, 32, 32);
  EXPECT_TRUE(r->scene().first()->occlusionBake()->done());
  EXPECT_EQ(r->scene().first()->occlusionBake()->values().size(), cube.positions.size());
  r->setOcclusionBudget(0.0);
}

}  // namespace
}  // namespace npr
