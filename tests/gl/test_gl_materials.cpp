// GL tier: a model's own materials, vertex colours and texture maps in every path. The GPU's
// per-pixel lighting with materials agrees with the CPU model; stencil still equals triangle;
// a texture map's colours reach the reference render; two materials under one light pick
// different entries in MATCH_COLORS; assimp's textured spider renders in colour.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "gl/gl_test_env.h"
#include "renderer/core/image_io.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/immediate_api.h"
#include "renderer/lighting/lighting_model.h"
#include "renderer/materials/mesh_materials.h"
#include "renderer/mesh/mesh_loader.h"
#include "renderer/paths/path_table.h"
#include "renderer/settings/choice_names.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::renderImage;
using test::sourcePath;
using test::testCamera;
using Fixture = test::RendererFixture;

// An icosphere whose faces with x < 0 use material "red" and the others "blue", with a
// glossy red and a dull blue (ambient = diffuse, as exporters write).
Mesh twoMaterialSphere(const test::TempDir& dir,
                       const std::string& mtl = "newmtl red\nKa 0.8 0.1 0.1\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 40\n"
                                                "newmtl blue\nKa 0.1 0.2 0.7\nKd 0.1 0.2 0.7\nKs 0 0 0\nillum 1\n") {
  const Mesh s = test::icosphere(3);
  std::ostringstream obj;
  obj << "mtllib two.mtl\n";
  for (const glm::vec3& p : s.positions) obj << "v " << p.x << " " << p.y << " " << p.z << "\n";
  for (std::size_t t = 0; t < s.triangleCount(); ++t) {
    obj << (s.faceCentroids[t].x < 0.0f ? "usemtl red\n" : "usemtl blue\n");
    obj << "f " << s.indices[t * 3] + 1 << " " << s.indices[t * 3 + 1] + 1 << " " << s.indices[t * 3 + 2] + 1 << "\n";
  }
  dir.write("two.mtl", mtl);
  auto m = loadMesh(dir.write("two.obj", obj.str()));
  EXPECT_TRUE(m) << m.error();
  return m ? std::move(*m) : Mesh{};
}

// Every fifth pixel the mesh covers seen through `cam`, with what the CPU lighting model
// needs to light it with `materials[1]` (red, x < 0) or `materials[2]` (blue), away from the
// band about the seam where faces of both meet (faces are split by their centroids).
struct SurfacePixel {
  std::size_t index;
  int side;  // 0 red, 1 blue
  glm::vec3 lit;
};
std::vector<SurfacePixel> litSurfacePixels(Renderer& r, const CameraMatrices& cam, int w, int h, const std::vector<Material>& materials,
                                           float seam) {
  const ImageRGBA32F pos = test::renderGeometry(r, cam, FrameOutput::EyePosition, w, h);
  const ImageRGBA32F nrm = test::renderGeometry(r, cam, FrameOutput::EyeNormal, w, h);
  const glm::mat4 toObject = glm::inverse(cam.view);
  std::vector<SurfacePixel> out;
  for (std::size_t i = 0; i < std::size_t(w) * h; i += 5) {
    if (nrm.pixels[i * 4 + 3] < 0.5f) continue;
    const glm::vec3 p(pos.pixels[i * 4], pos.pixels[i * 4 + 1], pos.pixels[i * 4 + 2]);
    const glm::vec3 n(nrm.pixels[i * 4], nrm.pixels[i * 4 + 1], nrm.pixels[i * 4 + 2]);
    const float x = glm::vec3(toObject * glm::vec4(p, 1.0f)).x;
    if (std::fabs(x) < seam) continue;
    const int side = x < 0.0f ? 0 : 1;
    const Material& mat = materials[std::size_t(side) + 1];
    out.push_back({i, side, shade(prepareLighting<float>(r.lighting().withMaterial(mat)), p, n, pos.pixels[i * 4 + 3] < 0.0f)});
  }
  return out;
}

TEST_F(Fixture, PixelPathWithMaterialsAgreesWithTheCpuLightingModel) {
  test::TempDir dir;
  const Mesh mesh = twoMaterialSphere(dir);
  ASSERT_EQ(mesh.materials.size(), 3u);  // the default, red, blue
  r->scene().setOnly(&mesh);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  const int w = 320, h = 240;
  const CameraMatrices cam = testCamera(float(w) / h);
  const std::vector<Material> mats = glMaterials(mesh, r->lighting());
  {
    RenderSettings s;
    s.path = RenderPath::Pixel;
    s.match = MatchMode::Colors;
    const ImageRGBA8 entries = test::renderEntries(*r, cam, s, w, h);
    const PaletteMatcher& m = *r->palettes().matcher();
    int sampled = 0, exact = 0, red = 0, blue = 0;
    for (const SurfacePixel& px : litSurfacePixels(*r, cam, w, h, mats, 0.05f)) {
      (px.side == 0 ? red : blue)++;
      ++sampled;
      exact += entries.pixels[px.index * 4] == m.match(px.lit);
    }
    EXPECT_GT(red, 300);
    EXPECT_GT(blue, 300);
    EXPECT_GE(exact, sampled * 95 / 100) << exact << " of " << sampled << " exact";
  }
}

// Each material's every term reaches the per-pixel lighting (the GPU-lit paths draw material
// by material, each from uniforms): ambient, diffuse, specular and emission all different, in
// the reference render, against the CPU model at each sampled pixel.
TEST_F(Fixture, ReferenceLightsEachMaterialWithEachOfItsColours) {
  test::TempDir dir;
  const Mesh mesh = twoMaterialSphere(dir,
                                      "newmtl red\nKa 0.9 0.1 0.1\nKd 0.1 0.7 0.1\nKs 0.4 0.4 0.6\nNs 30\nKe 0.05 0.05 0.3\n"
                                      "newmtl blue\nKa 0.1 0.1 0.9\nKd 0.6 0.2 0.1\nKs 0.5 0.5 0.3\nNs 8\nKe 0.2 0 0\n");
  ASSERT_EQ(mesh.materials.size(), 3u);
  r->scene().setOnly(&mesh);
  const float ambient[4] = {0.3f, 0.3f, 0.3f, 1.0f};
  ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_AMBIENT, ambient));
  const int w = 320, h = 240;
  const CameraMatrices cam = testCamera(float(w) / h);
  const std::vector<Material> mats = glMaterials(mesh, r->lighting());
  RenderSettings s;
  s.path = RenderPath::Reference;
  const ImageRGBA8 img = renderImage(*r, cam, s, w, h);
  int sampled[2] = {0, 0}, close[2] = {0, 0};
  float worst[2] = {0.0f, 0.0f};
  for (const SurfacePixel& px : litSurfacePixels(*r, cam, w, h, mats, 0.2f)) {
    const std::size_t i = px.index;
    const glm::vec3 e = glm::abs(glm::vec3(img.pixels[i * 4], img.pixels[i * 4 + 1], img.pixels[i * 4 + 2]) / 255.0f - glm::clamp(px.lit, 0.0f, 1.0f));
    ++sampled[px.side];
    close[px.side] += glm::all(glm::lessThanEqual(e, glm::vec3(3.0f / 255.0f)));
    worst[px.side] = std::max({worst[px.side], e.r, e.g, e.b});
  }
  for (int k : {0, 1}) {
    EXPECT_GT(sampled[k], 300) << (k ? "blue" : "red");
    EXPECT_GE(close[k], sampled[k] * 97 / 100) << (k ? "blue" : "red") << ": " << close[k] << " of " << sampled[k] << " within 3/255";
    EXPECT_LE(worst[k] * 255.0f, 8.0f) << (k ? "blue" : "red");  // a highlight of the wrong size misses by more
  }
}

TEST_F(Fixture, StencilEqualsTriangleWithMaterials) {
  test::TempDir dir;
  const Mesh mesh = twoMaterialSphere(dir);
  r->scene().setOnly(&mesh);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  const int w = 320, h = 240;
  const CameraMatrices cam = testCamera(float(w) / h);
  for (MatchMode mode : {MatchMode::Colors, MatchMode::Intensity}) {
    RenderSettings s;
    s.match = mode;
    s.path = RenderPath::Stencil;
    const ImageRGBA8 stencil = renderImage(*r, cam, s, w, h);
    s.path = RenderPath::Triangle;
    const ImageRGBA8 triangle = renderImage(*r, cam, s, w, h);
    EXPECT_LE(test::countDiffering(stencil, triangle), w * h / 1000) << choiceName(mode);
    // And the materials change the picture: off, the sphere is one grey material.
    s.materials = false;
    EXPECT_GT(test::countDiffering(triangle, renderImage(*r, cam, s, w, h)), w * h / 20) << choiceName(mode);
  }
}

// A camera-facing square of side 1.2 at z = `z` with one material, texture coordinates over
// it and, when `cutLeft`, a map whose left half is transparent (alpha 0) and right half opaque.
Mesh seeThroughSquare(MeshMaterial::Alpha alpha, float opacity, bool cutLeft, float z) {
  Mesh m = test::square(4);
  for (glm::vec3& p : m.positions) p = glm::vec3(p.x * 0.6f, p.y * 0.6f, z);
  for (const glm::vec3& p : m.positions) m.texcoords.push_back(glm::vec2(p.x / 1.2f + 0.5f, p.y / 1.2f + 0.5f));
  MeshMaterial mat;
  mat.name = "glass";
  mat.ambient = mat.diffuse = glm::vec3(0.9f, 0.3f, 0.1f);
  mat.alpha = alpha;
  mat.opacity = opacity;
  if (cutLeft) {
    ImageRGBA8 map{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 255)};
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 8; ++x) map.pixels[(std::size_t(y) * 16 + x) * 4 + 3] = 0;
    m.textures.push_back({"cut.png", std::move(map)});
    mat.diffuseMap = 0;
  }
  m.materials.push_back(mat);
  m.faceMaterials.assign(m.triangleCount(), 0);
  finalizeMesh(m);
  return m;
}

// One frame with `mesh` in the scene for it alone.
ImageRGBA8 renderWithModel(Renderer& r, const Mesh& mesh, const CameraMatrices& cam, const RenderSettings& s, int side) {
  const ModelId id = r.scene().add(mesh);
  ImageRGBA8 img = renderImage(r, cam, s, side, side);
  r.scene().remove(id);
  return img;
}

// glTF's MASK: a square whose map's left half is transparent, in front of a sphere. In every
// path the left half shows what is behind it (the sphere and background, exactly as without the
// square) and the right half the square (exactly as an opaque square); a band about the cut,
// where the map's bilinear filter mixes the halves, is not counted.
TEST_F(Fixture, AMaskedMaterialIsCutOutInEveryPath) {
  const Mesh sphere = test::icosphere(3);
  const glm::mat4 behind = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -0.4f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  const Mesh opaque = seeThroughSquare(MeshMaterial::Alpha::Opaque, 1.0f, true, 0.3f);
  const Mesh masked = seeThroughSquare(MeshMaterial::Alpha::Mask, 1.0f, true, 0.3f);
  EXPECT_FALSE(opaque.seeThrough);
  EXPECT_TRUE(masked.seeThrough);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  constexpr int kSide = 120;
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  const CameraMatrices cam = c.matrices(1.0f);
  r->scene().add(sphere, behind);
  for (RenderPath path : userRenderPaths()) {
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 back = renderImage(*r, cam, s, kSide, kSide);
    const ImageRGBA8 front = renderWithModel(*r, opaque, cam, s, kSide);
    const ImageRGBA8 cut = renderWithModel(*r, masked, cam, s, kSide);
    int counted[2] = {0, 0}, wrong[2] = {0, 0};
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        const std::size_t i = (std::size_t(y) * kSide + x) * 4;
        auto same = [&](const ImageRGBA8& a, const ImageRGBA8& b) { return std::equal(&a.pixels[i], &a.pixels[i] + 3, &b.pixels[i]); };
        if (same(back, front) || std::abs(x - kSide / 2) < 4) continue;  // the square not seen here, or the cut's band
        const int side = x < kSide / 2 ? 0 : 1;
        ++counted[side];
        wrong[side] += !same(cut, side == 0 ? back : front);
      }
    for (int side : {0, 1}) {
      EXPECT_GT(counted[side], kSide * kSide / 10) << renderPathName(path) << ": the square is not on screen";
      EXPECT_LE(wrong[side], counted[side] / 100) << renderPathName(path) << (side ? ": the kept half" : ": the cut half") << ", " << wrong[side]
                                                  << " of " << counted[side] << " pixels differ";
    }
  }
}

// The stencil path marks a scene's objects together: each see-through object's masks keep its
// own cut (its coverage bound for each of its masks), as when the objects are drawn one by one.
TEST_F(Fixture, SeeThroughObjectsMarkedTogetherKeepTheirOwnCuts) {
  const Mesh cutLeft = seeThroughSquare(MeshMaterial::Alpha::Mask, 1.0f, true, 0.0f);
  Mesh cutRight = cutLeft;  // the same square, its map's other half transparent
  for (std::size_t i = 3; i < cutRight.textures[0].image.pixels.size(); i += 4) cutRight.textures[0].image.pixels[i] = 255 - cutRight.textures[0].image.pixels[i];
  const Palette hatch = test::shippedPalette("hatch");
  ASSERT_TRUE(r->palettes().setMain(hatch));
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  const CameraMatrices cam = c.matrices(1.0f);
  // A light close to the squares: their triangles fall in several buckets.
  const float pos[4] = {0.0f, 0.2f, 0.5f, 1.0f};
  r->lighting().setModelView(cam.view);
  ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos));
  const ModelId a = r->scene().add(cutLeft, glm::translate(glm::mat4(1.0f), glm::vec3(-0.35f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)));
  const ModelId b = r->scene().add(cutRight, glm::translate(glm::mat4(1.0f), glm::vec3(0.35f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)));
  RenderSettings s;
  s.path = RenderPath::Stencil;
  constexpr int kSide = 120;
  const ImageRGBA8 together = renderImage(*r, cam, s, kSide, kSide);
  EXPECT_GT(r->stats().drawCalls, 4);
  // Palettes of their own (named apart, so not shared: Scene::setPalette): drawn alone.
  Palette ownA = hatch, ownB = hatch;
  ownA.name += " a", ownB.name += " b";
  ASSERT_TRUE(r->scene().setPalette(a, ownA));
  ASSERT_TRUE(r->scene().setPalette(b, ownB));
  const int drawsTogether = r->stats().drawCalls;
  const ImageRGBA8 oneByOne = renderImage(*r, cam, s, kSide, kSide);
  EXPECT_LT(drawsTogether, r->stats().drawCalls);  // the quads drawn once for both
  int differ = 0;
  for (std::size_t i = 0; i < together.pixels.size(); i += 4) differ += !std::equal(&together.pixels[i], &together.pixels[i] + 3, &oneByOne.pixels[i]);
  EXPECT_EQ(differ, 0);
}

// The geometry pass (image-space edges, screen-space occlusion, the tests' eye positions) leaves
// out what the cut leaves out, from the first frame on: a masked square's geometry has its
// right half only.
TEST_F(Fixture, TheGeometryPassLeavesOutWhatAMaskCuts) {
  const Mesh masked = seeThroughSquare(MeshMaterial::Alpha::Mask, 1.0f, true, 0.0f);
  constexpr int kSide = 96;
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  r->scene().add(masked);
  const ImageRGBA32F pos = test::renderGeometry(*r, c.matrices(1.0f), FrameOutput::EyePosition, kSide, kSide);
  int half[2] = {0, 0};
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x)
      if (std::abs(x - kSide / 2) >= 3 && pos.pixels[(std::size_t(y) * kSide + x) * 4 + 2] != 0.0f) ++half[x < kSide / 2 ? 0 : 1];
  EXPECT_EQ(half[0], 0);
  EXPECT_GT(half[1], kSide * kSide / 8);
}

// glTF's BLEND, drawn as screen-door transparency: a square of opacity 0.25 covers a quarter of
// its pixels (4 of every 4x4 block) in every path, the same ones every frame; 0.75 three quarters.
TEST_F(Fixture, ABlendedMaterialCoversItsOpacitysShareOfPixelsInEveryPath) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  constexpr int kSide = 96;
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  const CameraMatrices cam = c.matrices(1.0f);
  const Mesh opaque = seeThroughSquare(MeshMaterial::Alpha::Opaque, 1.0f, false, 0.0f);
  for (float opacity : {0.25f, 0.75f}) {
    const Mesh blended = seeThroughSquare(MeshMaterial::Alpha::Blend, opacity, false, 0.0f);
    ASSERT_TRUE(blended.seeThrough);
    for (RenderPath path : userRenderPaths()) {
      RenderSettings s;
      s.path = path;
      const ImageRGBA8 empty = renderImage(*r, cam, s, kSide, kSide);
      const ImageRGBA8 full = renderWithModel(*r, opaque, cam, s, kSide);
      const ModelId b = r->scene().add(blended);
      const ImageRGBA8 part = renderImage(*r, cam, s, kSide, kSide);
      const ImageRGBA8 again = renderImage(*r, cam, s, kSide, kSide);
      r->scene().remove(b);
      int square = 0, drawn = 0;
      for (std::size_t i = 0; i < std::size_t(kSide * kSide) * 4; i += 4) {
        if (std::equal(&empty.pixels[i], &empty.pixels[i] + 3, &full.pixels[i])) continue;
        ++square;
        drawn += std::equal(&part.pixels[i], &part.pixels[i] + 3, &full.pixels[i]);
      }
      ASSERT_GT(square, kSide * kSide / 8) << renderPathName(path);
      EXPECT_NEAR(double(drawn) / square, opacity, 0.04) << renderPathName(path) << ": " << drawn << " of " << square;
      EXPECT_EQ(test::countDiffering(part, again), 0) << renderPathName(path) << ": the screen door moved in a still view";
    }
  }
}

// A see-through caster lets light through where it lets the eye: a square held flat above a
// slab, lit from straight above, shadows the slab; with its map's left half cut away, about half
// as much of the slab (the pixels where the square itself is not in view).
TEST_F(Fixture, AMaskedCasterCastsTheShadowOfWhatIsLeft) {
  const glm::mat4 faceUp = glm::rotate(glm::mat4(1.0f), glm::radians(-90.0f), glm::vec3(1, 0, 0));
  const Mesh slab = test::square(8);
  const glm::mat4 slabPlace = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.5f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(1.2f)) * faceUp;
  const glm::mat4 squarePlace = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.2f, 0.0f)) * faceUp;
  const Mesh opaque = seeThroughSquare(MeshMaterial::Alpha::Opaque, 1.0f, true, 0.0f);
  const Mesh masked = seeThroughSquare(MeshMaterial::Alpha::Mask, 1.0f, true, 0.0f);
  constexpr int kSide = 160;
  const CameraMatrices cam = testCamera(1.0f, 30.0f, 50.0f);
  const float above[4] = {0.0f, 1.0f, 0.0f, 0.0f};
  r->lighting().setModelView(cam.view);
  ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, above));
  RenderSettings s;
  s.path = RenderPath::Reference;
  r->scene().add(slab, slabPlace);
  const ImageRGBA32F slabAlone = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSide, kSide);
  const ImageRGBA8 lit = renderImage(*r, cam, s, kSide, kSide);
  int shadowed[2] = {0, 0}, slabPixels = 0;
  for (int k : {0, 1}) {
    const ModelId id = r->scene().add(k == 0 ? opaque : masked, squarePlace);
    const ImageRGBA32F both = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSide, kSide);
    s.shadows = true;
    const ImageRGBA8 shade = renderImage(*r, cam, s, kSide, kSide);
    s.shadows = false;
    r->scene().remove(id);
    auto luminance = [](const ImageRGBA8& img, std::size_t i) { return (int(img.pixels[4 * i]) + img.pixels[4 * i + 1] + img.pixels[4 * i + 2]) / 765.0f; };
    for (std::size_t i = 0; i < std::size_t(kSide * kSide); ++i) {
      if (slabAlone.pixels[4 * i + 2] == 0.0f || std::fabs(both.pixels[4 * i + 2] - slabAlone.pixels[4 * i + 2]) > 1e-4f) continue;
      slabPixels += k == 0;
      shadowed[k] += luminance(shade, i) < luminance(lit, i) - 0.1f;
    }
  }
  EXPECT_GT(slabPixels, kSide * kSide / 5);
  ASSERT_GT(shadowed[0], 1000) << "the opaque square casts no shadow: the test tests nothing";
  EXPECT_GT(shadowed[1], shadowed[0] * 35 / 100) << shadowed[1] << " of " << shadowed[0];
  EXPECT_LT(shadowed[1], shadowed[0] * 65 / 100) << shadowed[1] << " of " << shadowed[0] << ": the cut half still casts";
}

// A camera-facing square split into two triangles: the left one red, the right one blue.
TEST_F(Fixture, TwoMaterialsUnderOneLightPickDifferentEntriesInColorsMode) {
  test::TempDir dir;
  dir.write("m.mtl", "newmtl red\nKa 0.9 0.2 0.1\nKd 0.9 0.2 0.1\nnewmtl blue\nKa 0.1 0.3 0.9\nKd 0.1 0.3 0.9\n");
  auto mesh = loadMesh(dir.write("sq.obj",
                                 "mtllib m.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                 "usemtl red\nf 1 3 4\nusemtl blue\nf 1 2 3\n"));
  ASSERT_TRUE(mesh) << mesh.error();
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  const CameraMatrices cam = c.matrices(1.0f);
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel}) {
    RenderSettings s;
    s.path = path;
    s.match = MatchMode::Colors;
    const ImageRGBA8 e = test::renderEntries(*r, cam, s, 100, 100);
    auto at = [&](int x, int y) { return e.pixels[(std::size_t(y) * 100 + x) * 4]; };
    // Upper left is in the red triangle, lower right in the blue one.
    EXPECT_NE(at(30, 30), at(70, 70)) << renderPathName(path);
    s.materials = false;
    const ImageRGBA8 off = test::renderEntries(*r, cam, s, 100, 100);
    EXPECT_EQ(off.pixels[(30 * 100 + 30) * 4], off.pixels[(70 * 100 + 70) * 4]) << renderPathName(path) << " with materials off";
  }
}

// A textured square: a map in four quadrants (red, green / blue, white) over it, light from
// the eye.
TEST_F(Fixture, TextureMapColoursReachTheReferenceRender) {
  test::TempDir dir;
  ImageRGBA8 map{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, 255)};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* p = &map.pixels[(std::size_t(y) * 16 + x) * 4];
      const glm::ivec3 c = y < 8 ? (x < 8 ? glm::ivec3(255, 0, 0) : glm::ivec3(0, 255, 0)) : (x < 8 ? glm::ivec3(0, 0, 255) : glm::ivec3(255));
      p[0] = std::uint8_t(c.r), p[1] = std::uint8_t(c.g), p[2] = std::uint8_t(c.b);
    }
  ASSERT_TRUE(writeImage((dir.path() / "map 1.png").string(), map));
  dir.write("t.mtl", "newmtl tex\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nmap_Kd -s 1 1 1 .\\map 1.png\n");
  auto mesh = loadMesh(dir.write("t.obj",
                                 "mtllib t.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                 "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl tex\nf 1/1 2/2 3/3 4/4\n"));
  ASSERT_TRUE(mesh) << mesh.error();
  ASSERT_EQ(mesh->report.textures_loaded.size(), 1u) << mesh->report.toJson();
  r->scene().setOnly(&*mesh);
  const float dir4[4] = {0, 0, 1, 0};
  r->lighting().setModelView(glm::mat4(1.0f));
  ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, dir4));
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  RenderSettings s;
  s.path = RenderPath::Reference;
  const ImageRGBA8 img = renderImage(*r, c.matrices(1.0f), s, 200, 200);
  auto px = [&](int x, int y) {  // image rows are top first
    const std::uint8_t* p = &img.pixels[(std::size_t(y) * 200 + x) * 4];
    return glm::ivec3(p[0], p[1], p[2]);
  };
  // Lit head-on with Kd = 1 and a white light: the texel's own colour, away from the
  // quadrants' borders (the map is filtered). v counts up: the top rows of the image file
  // (red, green) are at the top of the square.
  const int lo = 80, hi = 120;
  EXPECT_NEAR(px(lo, lo).r, 255, 3);
  EXPECT_LE(px(lo, lo).g, 3);
  EXPECT_NEAR(px(hi, lo).g, 255, 3);
  EXPECT_NEAR(px(lo, hi).b, 255, 3);
  EXPECT_LE(px(lo, hi).r, 3);
  EXPECT_GE(px(hi, hi).r, 252);
  EXPECT_GE(px(hi, hi).b, 252);
}

TEST_F(Fixture, AssimpSpiderRendersWithItsTextures) {
  const std::string path = "/usr/share/assimp/models/OBJ/spider.obj";  // Debian's assimp-testmodels (.ci/setup installs it)
  auto mesh = loadMesh(path);
  ASSERT_TRUE(mesh) << mesh.error() << " (install assimp-testmodels)";
  EXPECT_EQ(mesh->report.materials, 4u);
  EXPECT_EQ(mesh->report.textures_loaded.size(), 4u) << mesh->report.toJson();
  EXPECT_TRUE(mesh->report.textures_missing.empty());
  r->scene().setOnly(&*mesh);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  const CameraMatrices cam = testCamera(4.0f / 3.0f);
  RenderSettings s;
  s.path = RenderPath::Reference;
  auto colourful = [](const ImageRGBA8& img) {
    int n = 0;
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) {
      const int r = img.pixels[i], g = img.pixels[i + 1], b = img.pixels[i + 2];
      n += std::max({r, g, b}) - std::min({r, g, b}) > 24;
    }
    return n;
  };
  const int on = colourful(renderImage(*r, cam, s, 320, 240));
  s.materials = false;
  const int off = colourful(renderImage(*r, cam, s, 320, 240));
  std::printf("spider: %d coloured pixels with its materials, %d without\n", on, off);
  EXPECT_GT(on, 1500) << "textured spider: coloured pixels";
  EXPECT_LT(off, 100) << "grey spider with materials off";
}

// A palette of n solid entries from `colour` (light) to a tenth of it.
Palette solidRamp(int n, glm::vec3 colour, const std::string& name) {
  Palette p;
  p.name = name;
  for (int i = 0; i < n; ++i) {
    PaletteEntry e;
    const glm::vec3 c = colour * (1.0f - 0.9f * float(i) / float(n - 1));
    e.image = ImageRGBA8{4, 4, std::vector<std::uint8_t>(64, 255)};
    for (std::size_t k = 0; k < 64; k += 4)
      for (int ch = 0; ch < 3; ++ch) e.image.pixels[k + std::size_t(ch)] = std::uint8_t(std::lround(c[ch] * 255.0f));
    e.average = c;
    e.intensity = c.r + c.g + c.b;
    p.entries.push_back(std::move(e));
  }
  return p;
}

// Per-material palettes: the sphere's "red" material is drawn with a blue palette, the rest
// with the main, red one, in every path.
TEST_F(Fixture, PerMaterialPalettesDrawEachMaterialsOwnTextures) {
  test::TempDir dir;
  const Mesh mesh = twoMaterialSphere(dir);
  r->scene().setOnly(&mesh);
  ASSERT_TRUE(r->palettes().setMain(solidRamp(8, glm::vec3(1.0f, 0.2f, 0.1f), "reds")));
  ASSERT_TRUE(r->palettes().setMaterial("red", solidRamp(8, glm::vec3(0.1f, 0.3f, 1.0f), "blues")));
  const int w = 200, h = 160;
  const CameraMatrices cam = testCamera(float(w) / h, 0.0f, 0.0f);  // looking down -z: x < 0 on the left
  const ImageRGBA32F pos = test::renderGeometry(*r, cam, FrameOutput::EyePosition, w, h);
  const glm::mat4 toObject = glm::inverse(cam.view);
  for (const PathInfo& info : renderPaths()) {
    if (!info.userSelectable || !info.usesPalette) continue;
    RenderSettings s;
    s.path = info.id;
    s.match = MatchMode::Intensity;
    const ImageRGBA8 img = renderImage(*r, cam, s, w, h);
    int blueOnRed = 0, redOnBlue = 0, right = 0, wrong = 0;
    for (int y = 0; y < h; y += 2)
      for (int x = 0; x < w; x += 2) {
        const std::size_t g = (std::size_t(y) * w + x) * 4;
        if (pos.pixels[g + 3] == 0.0f) continue;
        const float ox = glm::vec3(toObject * glm::vec4(pos.pixels[g], pos.pixels[g + 1], pos.pixels[g + 2], 1.0f)).x;
        if (std::fabs(ox) < 0.05f) continue;
        const std::uint8_t* p = &img.pixels[(std::size_t(y) * w + x) * 4];
        const bool blue = p[2] > p[0];
        if (ox < 0.0f) (blue ? right : wrong)++, blueOnRed += blue;
        else (blue ? wrong : right)++, redOnBlue += !blue;
      }
    EXPECT_GT(blueOnRed, 200) << info.name;
    EXPECT_GT(redOnBlue, 200) << info.name;
    EXPECT_LE(wrong, (right + wrong) / 100) << info.name << ": " << wrong << " pixels show the other material's palette";
  }
  // Without it, the whole sphere is red.
  r->palettes().clearMaterial("red");
  RenderSettings s;
  s.path = RenderPath::Pixel;
  const ImageRGBA8 img = renderImage(*r, cam, s, w, h);
  int blue = 0;
  for (std::size_t i = 0; i < img.pixels.size(); i += 4) blue += img.pixels[i + 2] > img.pixels[i] + 20;
  EXPECT_EQ(blue, 0);
}

// A material's part draws through the model's own vertex streams (only its index buffer is
// its own): given the main palette again, the split model shows the same picture as the whole
// one, the hatching direction field and the occlusion bake included, in every path.
TEST_F(Fixture, PerMaterialPartsDrawThroughTheModelsVertexStreams) {
  test::TempDir dir;
  const Mesh mesh = twoMaterialSphere(dir);
  r->scene().setOnly(&mesh);
  const Palette hatch = test::shippedPalette("hatch");
  ASSERT_TRUE(r->palettes().setMain(hatch));
  const CameraMatrices cam = testCamera(1.0f);
  for (const PathInfo& info : renderPaths()) {
    if (!info.userSelectable || !info.usesPalette) continue;
    RenderSettings s;
    s.path = info.id;
    s.orient.source = OrientSource::Curvature;
    s.occlusion = true;
    r->palettes().clearMaterial("red");
    const ImageRGBA8 whole = renderImage(*r, cam, s, 160, 160);
    ASSERT_TRUE(r->palettes().setMaterial("red", hatch));
    const ImageRGBA8 split = renderImage(*r, cam, s, 160, 160);
    EXPECT_EQ(test::countDiffering(whole, split), 0) << info.name;
  }
  r->palettes().clearMaterial("red");
}

// The original interface: a Materialfv between RenderTriangle calls applies to the triangles
// that follow, as in OpenGL. Two camera-facing triangles, red then blue.
TEST_F(Fixture, ImmediateMaterialfvAppliesToTheTrianglesThatFollow) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("gooch")));
  OrbitCamera c(0.0f, 0.0f, 3.0f);
  c.frame(1.0f);
  const CameraMatrices cam = c.matrices(1.0f);
  auto target = OffscreenTarget::create(100, 100);
  ASSERT_TRUE(target);
  PaletteRenderer immediate(*r);
  const float head[4] = {0, 0, 1, 0};  // a directional light: equal normals light equally
  r->lighting().setModelView(glm::mat4(1.0f));
  ASSERT_TRUE(immediate.Lightfv(GL_LIGHT0, GL_POSITION, head));
  immediate.ColorMatchMode(MatchMode::Colors);
  immediate.RenderPathMode(RenderPath::Triangle);
  const float red[4] = {0.9f, 0.2f, 0.1f, 1.0f}, blue[4] = {0.1f, 0.3f, 0.9f, 1.0f};
  auto draw = [&](bool switchMaterial) {
    target->bind();
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT_TRUE(immediate.Materialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red));
    immediate.Begin();
    immediate.RenderTriangle({{glm::vec3(-1, -1, 0), glm::vec3(1, 1, 0), glm::vec3(-1, 1, 0)}});
    if (switchMaterial) {
      EXPECT_TRUE(immediate.Materialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue));
    }
    immediate.RenderTriangle({{glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(1, 1, 0)}});
    EXPECT_TRUE(immediate.End(cam, {0, 0, 100, 100}));
    return target->readRGBA8();
  };
  auto px = [](const ImageRGBA8& img, int x, int y) { return glm::ivec3(img.pixels[(std::size_t(y) * 100 + x) * 4], img.pixels[(std::size_t(y) * 100 + x) * 4 + 1], img.pixels[(std::size_t(y) * 100 + x) * 4 + 2]); };
  const ImageRGBA8 one = draw(false), two = draw(true);
  EXPECT_EQ(px(one, 30, 30), px(one, 70, 70)) << "one material: one entry";
  EXPECT_NE(px(two, 30, 30), px(two, 70, 70)) << "the second triangle is drawn with the material set after the first";
  EXPECT_EQ(px(two, 30, 30), px(one, 30, 30)) << "the first keeps the material current when it was given";
}

}  // namespace
}  // namespace npr
