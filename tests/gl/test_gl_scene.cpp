// GL tier: a scene of several models (renderer/scene/). Each model is drawn where its transform
// puts it (the same picture as its mesh moved there), the nearest surface wins across models,
// one model casts shadows and screen-space occlusion on another, each keeps its own caches
// (a removed model takes only its own with it; unchanged frames do no work), and the anchored
// pattern follows each model alone. A deforming model draws its pose in every path exactly as a
// static copy of that pose, without computing a per-mesh cache again.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_env.h"
#include "renderer/animation/deformation.h"
#include "renderer/mesh/mesh_builder.h"
#include "renderer/settings/choice_names.h"
#include "support/analytic_surfaces.h"
#include "support/skinned_cylinder.h"
#include "support/test_util.h"

namespace npr {
namespace {

using SceneFixture = test::RendererFixture;

constexpr int kSize = 160;

float luminance(const ImageRGBA8& img, std::size_t i) {
  return (0.2126f * img.pixels[4 * i] + 0.7152f * img.pixels[4 * i + 1] + 0.0722f * img.pixels[4 * i + 2]) / 255.0f;
}
bool covered(const ImageRGBA32F& g, std::size_t i) { return g.pixels[4 * i + 2] != 0.0f; }

// A slab facing up (the square turned to face +y), scaled and lowered under a sphere.
Mesh slab() { return test::rotatedMesh(test::square(8), glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(-90.0f), glm::vec3(1, 0, 0)))); }
const glm::mat4 kSlabPlace = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.5f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(1.2f));
const glm::mat4 kSpherePlace = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0.0f, 0.1f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.35f));

void lightFromAbove(Renderer& r, const CameraMatrices& cam) {
  const float pos[4] = {0.2f, 1.0f, 0.3f, 0.0f};
  r.lighting().setModelView(cam.view);
  ASSERT_TRUE(r.lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos));
}

TEST_F(SceneFixture, AModelIsDrawnWhereItsTransformPutsIt) {
  const Mesh sphere = icosphere(3);
  const glm::mat4 place = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 0.1f)) *
                          glm::rotate(glm::mat4(1.0f), glm::radians(35.0f), glm::vec3(0, 1, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  Mesh moved = sphere;
  for (glm::vec3& p : moved.positions) p = glm::vec3(place * glm::vec4(p, 1.0f));
  finalizeMesh(moved);
  RenderSettings s;
  s.path = RenderPath::Reference;
  const CameraMatrices cam = test::testCamera(1.0f);
  r->scene().setOnly(&moved);
  const ImageRGBA8 baked = test::renderImage(*r, cam, s, kSize, kSize);
  r->scene().setOnly(nullptr);
  const ModelId id = r->scene().add(sphere, place);
  EXPECT_EQ(r->scene().size(), 1u);
  const ImageRGBA8 placed = test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_LE(test::countDiffering(baked, placed), kSize * kSize / 200);
  // Moved back to the origin, it is another picture.
  ASSERT_TRUE(r->scene().setTransform(id, glm::mat4(1.0f)));
  EXPECT_GT(test::countDiffering(baked, test::renderImage(*r, cam, s, kSize, kSize)), kSize * kSize / 20);
  EXPECT_FALSE(r->scene().setTransform(id + 100, glm::mat4(1.0f)));
}

TEST_F(SceneFixture, TheNearestSurfaceWinsAcrossModels) {
  const Mesh a = icosphere(3), b = torus(48, 24);
  const glm::mat4 pa = glm::translate(glm::mat4(1.0f), glm::vec3(-0.25f, 0.0f, 0.2f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
  const glm::mat4 pb = glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, 0.1f, -0.1f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.7f));
  const CameraMatrices cam = test::testCamera(1.0f);
  const ModelId ia = r->scene().add(a, pa);
  const ImageRGBA32F onlyA = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  r->scene().remove(ia);
  r->scene().add(b, pb);
  const ImageRGBA32F onlyB = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  r->scene().add(a, pa);
  EXPECT_EQ(r->scene().size(), 2u);
  const ImageRGBA32F both = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  int overlap = 0, wrong = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
    const bool inA = covered(onlyA, i), inB = covered(onlyB, i);
    if (!inA && !inB) {
      wrong += covered(both, i);
      continue;
    }
    overlap += inA && inB;
    const float nearest = inA && inB ? std::max(onlyA.pixels[4 * i + 2], onlyB.pixels[4 * i + 2]) : inA ? onlyA.pixels[4 * i + 2] : onlyB.pixels[4 * i + 2];
    wrong += std::fabs(both.pixels[4 * i + 2] - nearest) > 1e-4f;
  }
  EXPECT_GT(overlap, 500) << "the models do not overlap on screen: the test tests nothing";
  EXPECT_LE(wrong, kSize * kSize / 1000);
}

TEST_F(SceneFixture, OneModelShadowsAndOccludesAnother) {
  const Mesh sphere = icosphere(3), ground = slab();
  const CameraMatrices cam = test::testCamera(1.0f, 30.0f, 50.0f);
  lightFromAbove(*r, cam);
  r->scene().add(ground, kSlabPlace);
  const ImageRGBA32F slabAlone = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  r->scene().add(sphere, kSpherePlace);
  const ImageRGBA32F withSphere = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  RenderSettings s;
  s.path = RenderPath::Reference;
  const ImageRGBA8 lit = test::renderImage(*r, cam, s, kSize, kSize);
  s.shadows = true;
  const ImageRGBA8 shadowed = test::renderImage(*r, cam, s, kSize, kSize);
  s.shadows = false;
  s.occlusion = true;
  s.occlusionMethod = OcclusionMethod::Screen;
  const ImageRGBA8 occluded = test::renderImage(*r, cam, s, kSize, kSize);
  // The slab's own pixels (seen past the sphere): a flat slab lit from above neither shadows
  // nor occludes itself, so what darkens there comes from the sphere.
  int slabPixels = 0, inShadow = 0, inCrevice = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) {
    if (!covered(slabAlone, i) || std::fabs(withSphere.pixels[4 * i + 2] - slabAlone.pixels[4 * i + 2]) > 1e-4f) continue;
    ++slabPixels;
    inShadow += luminance(shadowed, i) < luminance(lit, i) - 0.1f;
    inCrevice += luminance(occluded, i) < luminance(lit, i) - 0.05f;
  }
  EXPECT_GT(slabPixels, kSize * kSize / 4);
  EXPECT_GT(inShadow, 200) << "the sphere casts no shadow on the slab";
  EXPECT_GT(inCrevice, 50) << "the sphere occludes nothing of the slab";
  // The slab alone: nothing darkens it.
  r->scene().setOnly(nullptr);
  r->scene().add(ground, kSlabPlace);
  s.occlusion = false;
  const ImageRGBA8 aloneLit = test::renderImage(*r, cam, s, kSize, kSize);
  s.shadows = true;
  const ImageRGBA8 aloneShadowed = test::renderImage(*r, cam, s, kSize, kSize);
  int darkened = 0;
  for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i) darkened += luminance(aloneShadowed, i) < luminance(aloneLit, i) - 0.1f;
  EXPECT_LE(darkened, kSize * kSize / 1000);
}

TEST_F(SceneFixture, EachModelKeepsItsOwnCaches) {
  const Mesh a = test::rotatedMesh(torus(48, 24), test::obliqueRotation()), b = test::rotatedMesh(icosphere(3), test::obliqueRotation());
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  // Rigid placements: the per-triangle lighting is kept in model space across frames for those
  // (a scaled model is relit every frame, as a scaled modelview always was).
  const ModelId ia = r->scene().add(a, glm::translate(glm::mat4(1.0f), glm::vec3(-0.9f, 0.0f, 0.0f)));
  const ModelId ib = r->scene().add(b, glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, 0.0f, 0.0f)));
  RenderSettings s;
  s.path = RenderPath::Triangle;
  s.orient.source = OrientSource::Curvature;
  s.lines.silhouettes = true;
  const CameraMatrices cam = test::testCamera(1.0f);
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  const DirectionField* fieldA = r->scene().find(ia)->directionFieldIfComputed();
  const DirectionField* fieldB = r->scene().find(ib)->directionFieldIfComputed();
  ASSERT_NE(fieldA, nullptr);
  ASSERT_NE(fieldB, nullptr);
  EXPECT_EQ(fieldA->directions.size(), a.positions.size());
  EXPECT_EQ(fieldB->directions.size(), b.positions.size());
  // Unchanged frames do no work; removing one model leaves the other's caches as they were.
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_EQ(r->stats().bufferUploads, 0);
  EXPECT_EQ(r->stats().lightingRecomputes, 0);
  r->scene().remove(ib);
  EXPECT_EQ(r->scene().find(ib), nullptr);
  EXPECT_EQ(r->scene().find(ia)->directionFieldIfComputed(), fieldA);
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_EQ(r->stats().bufferUploads, 0);
  EXPECT_EQ(r->stats().lightingRecomputes, 0);
  EXPECT_EQ(r->scene().find(ia)->directionFieldIfComputed(), fieldA);
}

// The per-triangle paths light a scene's models side by side before the frame draws them
// (Renderer::prepareTriangleShading): each model is lit once a frame, ahead, and not again when
// it draws (a key that differed would light it twice), and the picture is the one each model
// gives alone in the same place.
TEST_F(SceneFixture, AScenesModelsAreLitSideBySideOncePerFrame) {
  const Mesh sphere = icosphere(3);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  std::vector<glm::mat4> places;
  for (int i = 0; i < 4; ++i)
    places.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(-0.6f + 0.4f * float(i), 0.1f * float(i % 2), 0.0f)) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(0.18f)));
  const CameraMatrices cam = test::testCamera(1.0f);
  auto light = [&](int frame) {
    const float pos[4] = {std::cos(float(frame)), 1.0f, std::sin(float(frame)), 0.0f};
    r->lighting().setModelView(cam.view);
    return r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos);
  };
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Stencil}) {
    RenderSettings s;
    s.path = path;
    ASSERT_TRUE(light(0));
    // Each model alone (one model: not lit ahead), and nothing: the reference pictures.
    const ImageRGBA8 empty = test::renderImage(*r, cam, s, kSize, kSize);
    std::vector<ImageRGBA8> each;
    for (const glm::mat4& place : places) {
      const ModelId id = r->scene().add(sphere, place);
      each.push_back(test::renderImage(*r, cam, s, kSize, kSize));
      r->scene().remove(id);
    }
    std::vector<ModelId> ids;
    for (const glm::mat4& place : places) ids.push_back(r->scene().add(sphere, place));
    for (int frame = 0; frame < 3; ++frame) {
      ASSERT_TRUE(light(frame));  // the light moves every frame: every model is lit again, once
      const ImageRGBA8 all = test::renderImage(*r, cam, s, kSize, kSize);
      EXPECT_EQ(r->stats().lightingRecomputes, 4) << renderPathName(path) << ", frame " << frame;
      EXPECT_EQ(r->stats().modelsLitAhead, 4) << renderPathName(path) << ", frame " << frame;
      if (frame > 0) continue;
      // Every model's pixels as it drew them alone (the spheres do not overlap on screen).
      int differ = 0, counted = 0;
      for (std::size_t i = 0; i < std::size_t(kSize * kSize) * 4; i += 4)
        for (const ImageRGBA8& one : each) {
          if (std::equal(&one.pixels[i], &one.pixels[i] + 3, &empty.pixels[i])) continue;
          ++counted;
          differ += !std::equal(&one.pixels[i], &one.pixels[i] + 3, &all.pixels[i]);
        }
      EXPECT_GT(counted, kSize * kSize / 20) << renderPathName(path);
      // (Within 1%: the scene's automatic tone range is fitted to four spheres, not one.)
      EXPECT_LE(differ, counted / 100) << renderPathName(path) << ": " << differ << " of " << counted;
    }
    for (ModelId id : ids) r->scene().remove(id);
  }
}

// The stencil path marks a scene's objects together and draws each bucket's quads once for all
// of them: the same picture as drawing them one by one (objects that overlap on screen, in
// front of and behind each other), with fewer draws.
TEST_F(SceneFixture, TheStencilPathDrawsAScenesObjectsTogetherAsItDrawsThemOneByOne) {
  const Palette hatch = test::shippedPalette("hatch");
  ASSERT_TRUE(r->palettes().setMain(hatch));
  const Mesh sphere = icosphere(3);
  std::vector<ModelId> ids;
  for (int i = 0; i < 6; ++i)
    ids.push_back(r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f + 0.2f * float(i), 0.08f * float(i % 3), 0.15f * float(i % 2))) *
                                          glm::scale(glm::mat4(1.0f), glm::vec3(0.3f))));
  const CameraMatrices cam = test::testCamera(1.0f);
  lightFromAbove(*r, cam);
  for (bool masksFirst : {true, false}) {
    SCOPED_TRACE(masksFirst ? "masks first" : "mask and quads per bucket");
    RenderSettings s;
    s.path = RenderPath::Stencil;
    s.stencilMasksFirst = masksFirst;
    const ImageRGBA8 together = test::renderImage(*r, cam, s, kSize, kSize);
    const int drawsTogether = r->stats().drawCalls;
    // The same textures given to each object as a palette of its own (named apart, so each is
    // its own upload: Scene::setPalette shares only the same palette): objects of different
    // palettes are drawn one by one.
    for (ModelId id : ids) {
      Palette own = hatch;
      own.name += " " + std::to_string(id);
      ASSERT_TRUE(r->scene().setPalette(id, own));
    }
    const ImageRGBA8 oneByOne = test::renderImage(*r, cam, s, kSize, kSize);
    const int drawsOneByOne = r->stats().drawCalls;
    for (ModelId id : ids) r->scene().clearPalette(id);
    std::size_t differ = 0, covered = 0;
    const ImageRGBA8 empty = [&] {
      for (ModelId id : ids) r->scene().setVisible(id, false);
      ImageRGBA8 e = test::renderImage(*r, cam, s, kSize, kSize);
      for (ModelId id : ids) r->scene().setVisible(id, true);
      return e;
    }();
    for (std::size_t i = 0; i < together.pixels.size(); i += 4) {
      covered += !std::equal(&together.pixels[i], &together.pixels[i] + 3, &empty.pixels[i]);
      differ += !std::equal(&together.pixels[i], &together.pixels[i] + 3, &oneByOne.pixels[i]);
    }
    EXPECT_GT(covered, std::size_t(kSize * kSize / 10));
    EXPECT_EQ(differ, 0u);
    // Per bucket, a mask per object and one quad against a mask and a quad per object.
    EXPECT_LT(drawsTogether, drawsOneByOne * 3 / 4) << drawsTogether << " against " << drawsOneByOne;
  }
}

// 64 small objects (half instances of four spheres, half spheres of their own, in four
// materials) are merged into batches (scene/scene_batches.h): every path draws them as it draws
// each object alone, within the rounding of the merged vertices (at most 0.3% of the pixels
// differ, none by more than a step of the palette), in a tenth of the draws; the stencil path
// stays equal to the triangle path. Objects wholly outside the view are not drawn, and the
// frame is the one without them.
TEST_F(SceneFixture, ManySmallObjectsAreDrawnInBatchesAsEachAlone) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  std::deque<Mesh> meshes;
  const glm::vec3 diffuse[4] = {{0.8f, 0.3f, 0.2f}, {0.3f, 0.7f, 0.3f}, {0.3f, 0.4f, 0.9f}, {0.7f, 0.7f, 0.7f}};
  for (int k = 0; k < 4; ++k) meshes.push_back(test::sphereInMaterial(2, "m" + std::to_string(k), diffuse[k]));
  std::vector<ModelId> ids;
  for (int i = 0; i < 64; ++i) {
    const Mesh* mesh = &meshes[std::size_t(i / 2) % 4];
    if (i % 2) {
      Mesh own = *mesh;
      for (glm::vec3& v : own.positions) v.y *= 0.7f + 0.01f * float(i);
      finalizeMesh(own);
      meshes.push_back(std::move(own));
      mesh = &meshes.back();
    }
    const glm::vec3 at(-0.7f + 0.2f * float(i % 8), -0.7f + 0.2f * float(i / 8), 0.1f * float(i % 3));
    ids.push_back(r->scene().add(*mesh, glm::translate(glm::mat4(1.0f), at) * glm::scale(glm::mat4(1.0f), glm::vec3(0.09f))));
  }
  const CameraMatrices cam = test::testCamera(1.0f);
  lightFromAbove(*r, cam);
  ImageRGBA8 triangleBatched;
  for (RenderPath path : {RenderPath::Triangle, RenderPath::Stencil, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth}) {
    SCOPED_TRACE(renderPathName(path));
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 batched = test::renderImage(*r, cam, s, kSize, kSize);
    const int drawsBatched = r->stats().drawCalls;
    EXPECT_GE(r->scene().batchCount(), 1u);
    s.tuning.batchObjects = false;
    const ImageRGBA8 alone = test::renderImage(*r, cam, s, kSize, kSize);
    const int drawsAlone = r->stats().drawCalls;
    EXPECT_EQ(r->scene().batchCount(), 0u);
    std::size_t differ = 0;
    int largest = 0;
    for (std::size_t i = 0; i < batched.pixels.size(); i += 4) {
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(batched.pixels[i + c]) - int(alone.pixels[i + c])));
      differ += d > 1;
      largest = std::max(largest, d);
    }
    EXPECT_LE(differ, std::size_t(kSize * kSize * 3 / 1000)) << differ << " pixels differ, by up to " << largest;
    EXPECT_LT(drawsBatched * 10, drawsAlone) << drawsBatched << " draws against " << drawsAlone;
    if (path == RenderPath::Triangle) triangleBatched = batched;
    if (path == RenderPath::Stencil) {
      EXPECT_TRUE(std::equal(batched.pixels.begin(), batched.pixels.end(), triangleBatched.pixels.begin()));
    }
    std::printf("%-8s batched: %d draws, alone %d; %zu pixels differ, by up to %d\n", renderPathName(path), drawsBatched, drawsAlone, differ,
                largest);
  }
  // Half the objects moved far to the side: culled, their outlines neither found nor drawn,
  // and the frame is the one with them hidden.
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.tuning.batchObjects = false;
  s.lines.silhouettes = true;
  for (std::size_t i = 0; i < ids.size(); i += 2) r->scene().setVisible(ids[i], false);
  const ImageRGBA8 hidden = test::renderImage(*r, cam, s, kSize, kSize);
  const int linesHidden = r->stats().lines;
  EXPECT_EQ(r->stats().surfacesCulled, 0);
  for (std::size_t i = 0; i < ids.size(); i += 2) {
    r->scene().setVisible(ids[i], true);
    ASSERT_TRUE(r->scene().setTransform(ids[i], glm::translate(glm::mat4(1.0f), glm::vec3(40.0f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.09f))));
  }
  const ImageRGBA8 moved = test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_EQ(r->stats().surfacesCulled, 32);
  EXPECT_GT(linesHidden, 0);
  EXPECT_EQ(r->stats().lines, linesHidden);
  EXPECT_TRUE(std::equal(moved.pixels.begin(), moved.pixels.end(), hidden.pixels.begin()));
}

// The same palette given to many objects is uploaded once and shared, and the objects that
// share it are batched together: half of 32 spheres in the wood palette, half in the main one,
// draw as they do one by one, in two batches.
TEST_F(SceneFixture, ObjectsGivenTheSamePaletteShareOneUploadAndABatch) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  const Palette wood = test::shippedPalette("wood");
  const Mesh sphere = icosphere(2);
  std::vector<ModelId> ids;
  for (int i = 0; i < 32; ++i)
    ids.push_back(r->scene().add(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(-0.7f + 0.2f * float(i % 8), -0.6f + 0.3f * float(i / 8), 0.0f)) *
                                             glm::scale(glm::mat4(1.0f), glm::vec3(0.09f))));
  for (std::size_t i = 0; i < ids.size(); i += 2) ASSERT_TRUE(r->scene().setPalette(ids[i], wood));
  const GpuPalette* first = r->scene().find(ids[0])->palette();
  ASSERT_NE(first, nullptr);
  for (std::size_t i = 0; i < ids.size(); i += 2) EXPECT_EQ(r->scene().find(ids[i])->palette(), first) << "object " << i;
  const CameraMatrices cam = test::testCamera(1.0f);
  lightFromAbove(*r, cam);
  RenderSettings s;
  s.path = RenderPath::Pixel;
  const ImageRGBA8 batched = test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_EQ(r->scene().batchCount(), 2u);
  s.tuning.batchObjects = false;
  const ImageRGBA8 alone = test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_TRUE(std::equal(batched.pixels.begin(), batched.pixels.end(), alone.pixels.begin()));
}

// Per-object tone ranges with batches: a batch of one material is fitted one range of its own,
// as its objects are each: 32 near-black spheres (left) beside 32 near-white ones (right), in
// two batches, read within 0.05 of their lightness drawn one by one, and the dark ones lighter
// than under the scene's one range.
TEST_F(SceneFixture, ABatchOfOneMaterialIsFittedAToneRangeOfItsOwn) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  std::deque<Mesh> meshes;
  for (float grey : {0.04f, 0.9f}) meshes.push_back(test::sphereInMaterial(2, grey < 0.5f ? "dark" : "bright", glm::vec3(grey)));
  for (int i = 0; i < 64; ++i) {
    const bool dark = i % 8 < 4;
    r->scene().add(meshes[dark ? 0 : 1], glm::translate(glm::mat4(1.0f), glm::vec3(-0.75f + 0.2f * float(i % 8), -0.7f + 0.2f * float(i / 8), 0.0f)) *
                                             glm::scale(glm::mat4(1.0f), glm::vec3(0.09f)));
  }
  const CameraMatrices cam = test::testCamera(1.0f);
  lightFromAbove(*r, cam);
  const ImageRGBA32F geometry = test::renderGeometry(*r, cam, FrameOutput::EyePosition, kSize, kSize);
  // The mean luminance of the dark spheres' pixels (the left half's covered ones).
  auto darkLightness = [&](const ImageRGBA8& img) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize / 2; ++x) {
        const std::size_t i = std::size_t(y * kSize + x);
        if (!covered(geometry, i)) continue;
        sum += luminance(img, i);
        ++n;
      }
    return n ? sum / n : 0.0;
  };
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.toneRange = ToneRange::PerObject;
  const double batched = darkLightness(test::renderImage(*r, cam, s, kSize, kSize));
  EXPECT_EQ(r->scene().batchCount(), 2u);
  s.tuning.batchObjects = false;
  const double alone = darkLightness(test::renderImage(*r, cam, s, kSize, kSize));
  s.tuning.batchObjects = true;
  s.toneRange = ToneRange::Auto;
  const double scene = darkLightness(test::renderImage(*r, cam, s, kSize, kSize));
  std::printf("dark spheres' lightness: batched %.3f, each alone %.3f, the scene's range %.3f\n", batched, alone, scene);
  EXPECT_NEAR(batched, alone, 0.05);
  EXPECT_GT(batched, scene + 0.05);
}

TEST_F(SceneFixture, TheAnchoredPatternFollowsEachModelAlone) {
  const Mesh a = icosphere(3), b = torus(48, 24);
  const ModelId ia = r->scene().add(a, glm::translate(glm::mat4(1.0f), glm::vec3(-0.4f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.4f)));
  const ModelId ib = r->scene().add(b, glm::translate(glm::mat4(1.0f), glm::vec3(0.4f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.4f)));
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("crosshatch")));
  RenderSettings s;
  s.pattern = PatternSpace::Anchored;
  const CameraMatrices cam = test::testCamera(1.0f);
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  const PatternFrame a0 = r->scene().find(ia)->patterns().frame(), b0 = r->scene().find(ib)->patterns().frame();
  // B moves 0.1 to the right: its pattern moves with it, A's stays.
  ASSERT_TRUE(r->scene().setTransform(ib, glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.4f))));
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  const PatternFrame a1 = r->scene().find(ia)->patterns().frame(), b1 = r->scene().find(ib)->patterns().frame();
  EXPECT_NEAR(glm::length(a1.translation - a0.translation), 0.0f, 0.05f);
  EXPECT_GT(b1.translation.x - b0.translation.x, 3.0f) << "B's pattern did not move right with it";
}

// The window draws offscreen where a frame's passes share the framebuffer's depth; the renderer
// says so before the frame, and what it says is what the frame then does, for every path,
// orientation and pattern, on a sparse and a dense mesh.
TEST_F(SceneFixture, TheFramebufferIsAskedForBeforeTheFrame) {
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  const Mesh sparse = icosphere(2), dense = icosphere(5);
  const CameraMatrices cam = test::testCamera(1.0f);
  int shared = 0, checked = 0;
  for (const Mesh* mesh : {&sparse, &dense}) {
    r->scene().setOnly(mesh);
    for (RenderPath path : userRenderPaths())
      for (OrientSource orient : {OrientSource::None, OrientSource::Curvature, OrientSource::Light, OrientSource::Fixed})
        for (PatternSpace pattern : {PatternSpace::Screen, PatternSpace::Object}) {
          RenderSettings s;
          s.path = path;
          s.orient.source = orient;
          s.pattern = pattern;
          const bool said = r->sharesFramebufferDepth(cam, s, {0, 0, kSize, kSize});
          (void)test::renderImage(*r, cam, s, kSize, kSize);
          EXPECT_EQ(said, r->stats().surfaceBuffers > 0) << renderPathName(path) << " orient " << int(orient) << " pattern " << int(pattern)
                                                         << " on " << mesh->triangleCount() << " triangles";
          shared += said;
          ++checked;
        }
  }
  EXPECT_GT(shared, 4);
  EXPECT_LT(shared, checked);
}

// Two spheres side by side, the right one with a palette of its own: on every path that draws
// a palette the left is drawn exactly as without it and the right takes the other palette's
// colours; hidden, the right one is gone and the left unchanged.
TEST_F(SceneFixture, EachModelIsDrawnWithItsOwnPaletteAndCanBeHidden) {
  const Mesh sphere = icosphere(3);
  const glm::mat4 left = glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.45f));
  const glm::mat4 right = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.45f));
  ASSERT_TRUE(r->palettes().setMain(test::greyRamp(8)));
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 0.0f);
  const ModelId a = r->scene().add(sphere, left);
  // Saturated pixels: the wood palette's; the grey ramp has none.
  auto colourful = [](const ImageRGBA8& img, bool rightHalf) {
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = rightHalf ? kSize / 2 : 0; x < (rightHalf ? kSize : kSize / 2); ++x) {
        const unsigned char* p = &img.pixels[4 * (std::size_t(y) * kSize + std::size_t(x))];
        n += std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 40;
      }
    return n;
  };
  auto leftHalfDiffers = [](const ImageRGBA8& x, const ImageRGBA8& y) {
    int n = 0;
    for (std::size_t i = 0; i < std::size_t(kSize * kSize); ++i)
      if (int(i % kSize) < kSize / 2)
        for (int c = 0; c < 3; ++c) n += x.pixels[4 * i + std::size_t(c)] != y.pixels[4 * i + std::size_t(c)];
    return n;
  };
  for (const RenderPath path : {RenderPath::Stencil, RenderPath::Triangle, RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth}) {
    SCOPED_TRACE(renderPathName(path));
    RenderSettings s;
    s.path = path;
    const ImageRGBA8 onlyLeft = test::renderImage(*r, cam, s, kSize, kSize);
    const ModelId b = r->scene().add(sphere, right);
    const ImageRGBA8 shared = test::renderImage(*r, cam, s, kSize, kSize);
    ASSERT_TRUE(r->scene().setPalette(b, test::shippedPalette("wood")));
    const ImageRGBA8 own = test::renderImage(*r, cam, s, kSize, kSize);
    EXPECT_EQ(colourful(shared, true), 0);
    EXPECT_GT(colourful(own, true), kSize * kSize / 20) << "the right sphere is not in wood";
    EXPECT_EQ(colourful(own, false), 0) << "the left sphere took the wood palette";
    EXPECT_EQ(leftHalfDiffers(own, shared), 0);
    ASSERT_TRUE(r->scene().setVisible(b, false));
    const ImageRGBA8 hidden = test::renderImage(*r, cam, s, kSize, kSize);
    EXPECT_EQ(test::countDiffering(hidden, onlyLeft), 0) << "a hidden model still shows";
    ASSERT_TRUE(r->scene().setVisible(b, true));
    EXPECT_EQ(test::countDiffering(test::renderImage(*r, cam, s, kSize, kSize), own), 0) << "shown again, it is not as it was";
    r->scene().clearPalette(b);
    EXPECT_EQ(test::countDiffering(test::renderImage(*r, cam, s, kSize, kSize), shared), 0);
    r->scene().remove(b);
  }
  EXPECT_FALSE(r->scene().setPalette(a + 100, test::greyRamp(4)));
  EXPECT_FALSE(r->scene().setVisible(a + 100, false));
}

TEST_F(SceneFixture, EveryPathDrawsADeformedModelAsAStaticCopyOfItsPose) {
  const Mesh rest = test::skinnedCylinder(48, 40);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  Mesh copy = rest;  // the bent pose as a mesh that does not deform
  deformMesh(rest, test::bendJoints(60.0f), {}, copy);
  copy.deformation = MeshDeformation{};
  for (const PathInfo& path : renderPaths()) {
    if (!path.userSelectable) continue;
    SCOPED_TRACE(path.name);
    RenderSettings s;
    s.path = path.id;
    s.lines.silhouettes = true;
    s.lines.creases = true;
    s.orient.source = OrientSource::Light;
    r->scene().clear();
    const ModelId id = r->scene().add(rest);
    (void)test::renderImage(*r, cam, s, kSize, kSize);  // at rest: every cache is built
    // Bent 60 degrees: drawn exactly as the static copy of that pose is.
    ASSERT_TRUE(r->scene().deform(id, test::bendJoints(60.0f), {}));
    const ImageRGBA8 bent = test::renderImage(*r, cam, s, kSize, kSize);
    EXPECT_EQ(r->stats().meshCachesBuilt, 0);
    EXPECT_GT(r->stats().bufferUploads, 0) << "the pose's uploads are not in the frame's figures";
    r->scene().clear();
    (void)r->scene().add(copy);
    EXPECT_EQ(test::countDiffering(bent, test::renderImage(*r, cam, s, kSize, kSize)), 0) << "the posed model is not drawn as its pose";
    // Strokes along the curvature: the field is computed once, on the rest pose, and carried by
    // the skin; the painterly strokes are put back where they were seeded; posing computes no
    // per-mesh cache again.
    s.orient.source = OrientSource::Curvature;
    s.strokes.on = true;
    r->scene().clear();
    const ModelId curved = r->scene().add(rest);
    (void)test::renderImage(*r, cam, s, kSize, kSize);
    const DirectionField* field = r->scene().find(curved)->directionFieldIfComputed();
    ASSERT_NE(field, nullptr);
    for (float degrees : {30.0f, 60.0f, 90.0f}) {
      ASSERT_TRUE(r->scene().deform(curved, test::bendJoints(degrees), {}));
      (void)test::renderImage(*r, cam, s, kSize, kSize);
      EXPECT_EQ(r->stats().meshCachesBuilt, 0);
      EXPECT_EQ(r->scene().find(curved)->directionFieldIfComputed(), field);
    }
  }
}

// A deforming model split into parts by material (per-material palettes): each part's
// triangles follow the pose as the whole's do. The parts read the model's posed vertices and
// take their faces' centroids and normals from it (mesh_subset.h); given the main palette
// again, the split model draws the bent pose as the whole model does, in every path.
TEST_F(SceneFixture, ABendingModelsPartsFollowItsPose) {
  Mesh rest = test::skinnedCylinder(48, 40);
  rest.materials.resize(2);
  rest.materials[0].name = "foot";
  rest.materials[1].name = "head";
  rest.faceMaterials.resize(rest.triangleCount());
  for (std::size_t f = 0; f < rest.triangleCount(); ++f) rest.faceMaterials[f] = rest.faceCentroids[f].y > 0.0f ? 1 : 0;
  const Palette hatch = test::shippedPalette("hatch");
  ASSERT_TRUE(r->palettes().setMain(hatch));
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  for (const PathInfo& path : renderPaths()) {
    if (!path.userSelectable || !path.usesPalette) continue;
    SCOPED_TRACE(path.name);
    RenderSettings s;
    s.path = path.id;
    s.materials = true;
    r->scene().clear();
    r->palettes().clearMaterial("head");
    const ModelId id = r->scene().add(rest);
    (void)test::renderImage(*r, cam, s, kSize, kSize);  // at rest
    ASSERT_TRUE(r->scene().deform(id, test::bendJoints(70.0f), {}));
    const ImageRGBA8 whole = test::renderImage(*r, cam, s, kSize, kSize);
    ASSERT_TRUE(r->palettes().setMaterial("head", hatch));
    ASSERT_TRUE(r->scene().deform(id, test::bendJoints(0.0f), {}));
    (void)test::renderImage(*r, cam, s, kSize, kSize);  // the parts made, at rest
    ASSERT_EQ(r->scene().find(id)->parts().size(), 2u);
    ASSERT_TRUE(r->scene().deform(id, test::bendJoints(70.0f), {}));
    const ImageRGBA8 split = test::renderImage(*r, cam, s, kSize, kSize);
    EXPECT_EQ(test::countDiffering(whole, split), 0) << "the parts do not follow the pose";
  }
  r->palettes().clearMaterial("head");
}

// A pose made on the GPU (animation/gpu_deformation.h) draws what the CPU's pose draws: skin and
// morph target together, in every GPU-lit path, with shadows from the posed mesh and the
// hatching field carried by the skin. The GPU alone poses while nothing reads the mesh on the
// CPU; a per-triangle path then makes the CPU's pose, which lagged until then.
TEST_F(SceneFixture, APoseMadeOnTheGpuDrawsWhatTheCpuPoseDraws) {
  Mesh rest = test::skinnedCylinder(48, 40);
  // One morph target: the surface pushed out along its normal, more towards the head.
  rest.deformation.targetPositions.assign(1, std::vector<glm::vec3>(rest.positions.size()));
  rest.deformation.targetNormals.assign(1, std::vector<glm::vec3>(rest.positions.size(), glm::vec3(0.0f)));
  for (std::size_t i = 0; i < rest.positions.size(); ++i)
    rest.deformation.targetPositions[0][i] = 0.15f * (rest.positions[i].y + 0.75f) * rest.normals[i];
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  Mesh copy = rest;  // the pose as a mesh that does not deform
  deformMesh(rest, test::bendJoints(70.0f), {0.8f}, copy);
  copy.deformation = MeshDeformation{};
  for (RenderPath path : {RenderPath::Vertex, RenderPath::Pixel, RenderPath::Smooth}) {
    for (bool field : {false, true}) {
      SCOPED_TRACE(std::string(pathInfo(path).name) + (field ? ", hatching along the curvature, shadows" : ""));
      RenderSettings s;
      s.path = path;
      s.shadows = field;
      s.ground = field;
      if (field) s.orient.source = OrientSource::Curvature;
      r->scene().clear();
      const ModelId id = r->scene().add(rest);
      (void)test::renderImage(*r, cam, s, kSize, kSize);
      ASSERT_TRUE(r->scene().deform(id, test::bendJoints(70.0f), {0.8f}));
      const ImageRGBA8 gpu = test::renderImage(*r, cam, s, kSize, kSize);
      EXPECT_EQ(r->stats().gpuPoses, 1);
      EXPECT_EQ(r->stats().cpuPoses, 0) << "the CPU posed a mesh nothing read there";
      EXPECT_TRUE(r->scene().find(id)->cpuPoseStale());
      EXPECT_EQ(r->stats().meshCachesBuilt, 0);
      // --deform cpu: the CPU poses and uploads, as before.
      r->scene().clear();
      const ModelId cpuId = r->scene().add(rest);
      (void)test::renderImage(*r, cam, s, kSize, kSize);
      ASSERT_TRUE(r->scene().deform(cpuId, test::bendJoints(70.0f), {0.8f}));
      s.deform = PosePlacement::Cpu;
      const ImageRGBA8 cpu = test::renderImage(*r, cam, s, kSize, kSize);
      EXPECT_EQ(r->stats().gpuPoses, 0);
      EXPECT_EQ(r->stats().cpuPoses, 1);
      // The GPU's float arithmetic is not the CPU's: an edge pixel may round the other way.
      EXPECT_LE(test::countDiffering(gpu, cpu), kSize * kSize / 400) << "the GPU's pose is not drawn as the CPU's";
      if (field) continue;  // a static copy's field is the posed surface's own, not the rest one carried
      r->scene().clear();
      (void)r->scene().add(copy);
      EXPECT_EQ(test::countDiffering(cpu, test::renderImage(*r, cam, s, kSize, kSize)), 0);
    }
  }
  // A per-triangle path reads the faces on the CPU: the pose the GPU alone made is made there.
  RenderSettings s;
  s.path = RenderPath::Pixel;
  r->scene().clear();
  const ModelId id = r->scene().add(rest);
  ASSERT_TRUE(r->scene().deform(id, test::bendJoints(70.0f), {0.8f}));
  (void)test::renderImage(*r, cam, s, kSize, kSize);
  ASSERT_TRUE(r->scene().find(id)->cpuPoseStale());
  s.path = RenderPath::Triangle;
  const ImageRGBA8 triangles = test::renderImage(*r, cam, s, kSize, kSize);
  EXPECT_EQ(r->stats().cpuPoses, 1);
  EXPECT_FALSE(r->scene().find(id)->cpuPoseStale());
  r->scene().clear();
  (void)r->scene().add(copy);
  EXPECT_EQ(test::countDiffering(triangles, test::renderImage(*r, cam, s, kSize, kSize)), 0);
}

// The occlusion bake is taken once, at rest, and kept as the mesh bends (per-mesh caches never
// follow the pose). How wrong that is: against a bake of the bent pose itself, per vertex.
TEST_F(SceneFixture, TheOcclusionBakeIsKeptFromTheRestPoseAndThisIsHowWrongItIsBent) {
  const Mesh rest = test::skinnedCylinder(48, 40);
  ASSERT_TRUE(r->palettes().setMain(test::shippedPalette("hatch")));
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  RenderSettings s;
  s.occlusion = true;
  const ModelId id = r->scene().add(rest);
  (void)test::renderImage(*r, cam, s, 64, 64);
  ASSERT_TRUE(r->scene().first()->occlusionBake() && r->scene().first()->occlusionBake()->done());
  const std::vector<float> atRest = r->scene().first()->occlusionBake()->values();
  Mesh bent = rest;
  deformMesh(rest, test::bendJoints(90.0f), {}, bent);
  bent.deformation = MeshDeformation{};
  ASSERT_TRUE(r->scene().deform(id, test::bendJoints(90.0f), {}));
  (void)test::renderImage(*r, cam, s, 64, 64);
  EXPECT_EQ(r->stats().meshCachesBuilt, 0);
  ASSERT_TRUE(r->scene().first()->occlusionBake() && r->scene().first()->occlusionBake()->done());
  EXPECT_EQ(r->scene().first()->occlusionBake()->values(), atRest) << "the bake followed the pose";
  r->scene().clear();
  (void)r->scene().add(bent);
  (void)test::renderImage(*r, cam, s, 64, 64);
  ASSERT_TRUE(r->scene().first()->occlusionBake() && r->scene().first()->occlusionBake()->done());
  const std::vector<float>& rebaked = r->scene().first()->occlusionBake()->values();
  ASSERT_EQ(rebaked.size(), atRest.size());
  // All vertices, and those of the bend (the middle fifth, where the two joints blend).
  double sum = 0.0, sumBend = 0.0, worst = 0.0;
  int n = 0, nBend = 0, over = 0;
  for (std::size_t v = 0; v < rebaked.size(); ++v) {
    const double d = std::fabs(double(rebaked[v]) - double(atRest[v]));
    sum += d;
    ++n;
    worst = std::max(worst, d);
    over += d > 0.1;
    if (std::fabs(rest.positions[v].y) < 0.15f) {
      sumBend += d;
      ++nBend;
    }
  }
  std::printf("occlusion kept from the rest pose of a cylinder bent 90 degrees, against a bake of the bent pose: mean |difference| "
              "%.3f over every vertex, %.3f over the bend's, largest %.3f, %.1f%% of vertices off by more than 0.1\n",
              sum / n, sumBend / std::max(nBend, 1), worst, 100.0 * over / n);
  EXPECT_GT(worst, 0.0) << "a bent tube occludes itself differently: the two bakes cannot agree";
}

// The object pattern on a bending surface: each surface point keeps its texel as the skinned
// cylinder bends 90 degrees (it is read at the rest pose's point, so by construction; this
// measures it). A palette whose one layer spells each texel's index in its colour; surface
// points are the mesh's vertices, followed through the bend from the geometry, read where they
// project while visible (their pixel's eye depth theirs) and facing the camera, compared frame
// to frame within one octave of the pattern. Screen-space hatching, for scale.
TEST_F(SceneFixture, TheObjectPatternStaysOnABendingSurface) {
  const Palette coded = test::texelIndexPalette();
  ASSERT_TRUE(r->palettes().setMain(coded));
  const Mesh rest = test::skinnedCylinder(64, 60);
  const ModelId id = r->scene().add(rest);
  const int w = 200, h = 200, frames = 16;
  const CameraMatrices cam = test::testCamera(1.0f, 0.0f, 10.0f);
  const float pixelSize = 2.0f / (cam.projection[1][1] * float(h));  // object units per pixel at depth 1
  Mesh posed = rest;
  for (RenderPath path : {RenderPath::Pixel, RenderPath::Stencil, RenderPath::Triangle}) {
    double share[2] = {0.0, 0.0};
    for (PatternSpace space : {PatternSpace::Screen, PatternSpace::Object}) {
      RenderSettings s;
      s.path = path;
      s.pattern = space;
      std::vector<glm::ivec3> before(rest.positions.size(), glm::ivec3(-1));
      std::vector<int> octaveBefore(rest.positions.size(), 0);
      int compared = 0, changed = 0;
      double slidTexels = 0.0;
      for (int f = 0; f <= frames; ++f) {
        const float degrees = 90.0f * float(f) / float(frames);
        ASSERT_TRUE(r->scene().deform(id, test::bendJoints(degrees), {}));
        deformMesh(rest, test::bendJoints(degrees), {}, posed);
        const ImageRGBA8 img = test::renderImage(*r, cam, s, w, h);
        const ImageRGBA32F eye = test::renderGeometry(*r, cam, FrameOutput::EyePosition, w, h);
        for (std::size_t v = 0; v < rest.positions.size(); ++v) {
          const glm::vec4 pe = cam.view * glm::vec4(posed.positions[v], 1.0f);
          const glm::vec4 c = cam.projection * pe;
          const int x = int(std::floor((c.x / c.w * 0.5f + 0.5f) * w)), y = int(std::floor((c.y / c.w * 0.5f + 0.5f) * h));
          glm::ivec3 code(-1);
          // The octave the point's depth gives (texels 2^k object units wide; pattern.glsl):
          // compared only within one, as crossing one changes every texel by design.
          int octave = 0;
          std::frexp(-pe.z * pixelSize, &octave);
          // Seen from the front (at grazing angles a pixel's rounding spans many texels).
          const glm::vec3 ne = glm::normalize(glm::mat3(cam.view) * posed.normals[v]);
          const bool facing = glm::dot(ne, -glm::normalize(glm::vec3(pe))) > 0.5f;
          if (facing && x >= 1 && y >= 1 && x < w - 1 && y < h - 1) {
            const float* g = &eye.pixels[(std::size_t(y) * w + std::size_t(x)) * 4];
            if (g[3] > 0.0f && std::abs(g[2] - pe.z) < 0.02f) {
              const std::uint8_t* t = &img.pixels[(std::size_t(h - 1 - y) * w + std::size_t(x)) * 4];
              code = glm::ivec3(t[0], t[1], t[2]);
              // Compared with the last frame's texel where both saw it at one octave; within a
              // pixel of where it projects (the projection rounds).
              if (before[v].x >= 0 && before[v].z == code.z && octaveBefore[v] == octave) {
                bool found = false;
                for (int dy = -1; dy <= 1 && !found; ++dy)
                  for (int dx = -1; dx <= 1 && !found; ++dx) {
                    const std::uint8_t* n = &img.pixels[(std::size_t(h - 1 - y - dy) * w + std::size_t(x + dx)) * 4];
                    found = n[0] == before[v].x && n[1] == before[v].y;
                  }
                ++compared;
                changed += !found;
                if (!found) {
                  // How far, in texels (a level's 64 or 32 wrap around).
                  const int step = code.z ? 8 : 4, period = code.z ? 32 : 64;
                  const auto apart = [&](int a, int b) {
                    const int d = std::abs(a - b) / step;
                    return std::min(d, period - d);
                  };
                  slidTexels += std::hypot(apart(code.x, before[v].x), apart(code.y, before[v].y));
                }
              }
            }
          }
          before[v] = code;
          octaveBefore[v] = octave;
        }
      }
      share[space == PatternSpace::Object] = compared ? double(changed) / compared : 1.0;
      // Texels are 1 to 2 pixels wide: 1.5 on average.
      std::printf("bending 90 degrees over %d frames, %s, %s pattern: %.4f of the visible surface points changed texel per frame, "
                  "slide %.3f px per point per frame (%d compared)\n",
                  frames, pathInfo(path).name, choiceName(space), share[space == PatternSpace::Object],
                  compared ? 1.5 * slidTexels / compared : 0.0, compared);
      ASSERT_GT(compared, 1000);
    }
    EXPECT_LT(share[1], 0.01) << pathInfo(path).name;
    EXPECT_LT(share[1] * 10.0, share[0]) << pathInfo(path).name;
  }
}

}  // namespace
}  // namespace npr
