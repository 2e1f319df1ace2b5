// GL tier, app level: the viewer's scene state on the headless context. A model or palette
// that fails to load leaves the current one drawing exactly as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/settings/style_file.h"
#include "app/viewer_state.h"
#include "app/window/export_job.h"
#include "app/window/style_thumbnails.h"
#include "gl/gl_test_env.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/mesh/mesh_loader.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::renderImage;
using test::sourcePath;
using test::testCamera;

using Fixture = test::RendererFixture;
using test::countDiffering;

TEST_F(Fixture, FailedPaletteLoadKeepsTheCurrentOne) {
  ViewerState state;
  const Mesh mesh = test::icosphere(3);
  r->scene().setOnly(&mesh);
  ASSERT_TRUE(state.loadPalette(sourcePath("palettes/cel/cel.palette"), *r));
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.match = state.settings.match;
  const ImageRGBA8 before = renderImage(*r, testCamera(1.0f), s, 64, 64);
  test::TempDir d;
  const Status palette = state.loadPalette(d.write("broken.palette", "missing.png\n"), *r);
  const Status model = state.loadModel(d.write("broken.obj", "v 0 0 0\n"), *r);
  ASSERT_FALSE(palette);
  ASSERT_FALSE(model);
  EXPECT_EQ(state.palette->name, "Cel (4 tones)");
  const ImageRGBA8 after = renderImage(*r, testCamera(1.0f), s, 64, 64);
  EXPECT_EQ(countDiffering(before, after), 0);
  // Each failure says what did not load, once, for the caller to report (not noted here too).
  EXPECT_NE(palette.error().find("palette not loaded: "), std::string::npos) << palette.error();
  EXPECT_NE(model.error().find("model not loaded: "), std::string::npos) << model.error();
  EXPECT_TRUE(state.problems.empty());
}

}  // namespace
}  // namespace npr

namespace npr {
namespace {

// Style presets: every shipped style loads, applies and draws, with a golden image each; a
// saved style loads back to the same settings; a bad style changes nothing and says where.
using StyleFixture = test::RendererFixture;
TEST_F(StyleFixture, EveryShippedStyleAppliesAndMatchesItsGolden) {
  const std::vector<std::string> styles = discoverStyles();
  ASSERT_GE(styles.size(), 7u);
  auto mesh = loadMesh(test::sourcePath("models/teapot.obj"));
  ASSERT_TRUE(mesh);
  r->scene().setOnly(&*mesh);
  for (const std::string& file : styles) {
    ViewerState state;
    ASSERT_TRUE(state.loadPalette(defaultPalettePath(), *r));
    Result<Style> style = loadStyle(file);
    ASSERT_TRUE(style) << style.error();
    ASSERT_TRUE(applyStyle(*style, state, *r)) << file;
    ASSERT_TRUE(style->palette.has_value()) << file << " names no palette";
    const std::string name = std::filesystem::path(file).stem().string();
    test::expectGolden("style-" + name, test::renderImage(*r, test::testCamera(1.0f), state.settings, 160, 160), 0.005, 0.004);
    ASSERT_TRUE(r->lighting().setToneModel(ToneModel::OpenGL, r->lighting().toneParameters()));
    r->palettes().clearControl(ControlParameter::Shadow);
    r->palettes().clearControl(ControlParameter::Occlusion);
  }
}

TEST_F(StyleFixture, SavedStyleLoadsBackAndBadStylesChangeNothing) {
  const Mesh mesh = test::icosphere(3);
  r->scene().setOnly(&mesh);
  ViewerState state;
  ASSERT_TRUE(state.loadPalette(defaultPalettePath(), *r));
  Result<Style> technical = loadStyle(*findStyle("technical"));
  ASSERT_TRUE(technical) << technical.error();
  ASSERT_TRUE(applyStyle(*technical, state, *r));
  ASSERT_EQ(state.settings.lines.sets.size(), 3u);  // its line sets, one per line of the file
  EXPECT_EQ(state.settings.lines.sets[2].visibility, LineSet::Visibility::Hidden);
  // Ground, shadows and a control palette travel with the look too.
  state.settings.ground = state.settings.shadows = true;
  state.light = glm::vec3(1.0f, 4.0f, -2.5f);
  ASSERT_TRUE(state.setControlPalette(ControlParameter::Shadow, test::sourcePath("palettes/stipple/stipple.palette"), *r));
  test::TempDir d;
  const std::string saved = d.write("saved.style", styleText(state, *r, "round trip"));
  ViewerState other;
  ASSERT_TRUE(other.loadPalette(defaultPalettePath(), *r));
  ASSERT_TRUE(r->lighting().setToneModel(ToneModel::OpenGL, r->lighting().toneParameters()));
  Result<Style> back = loadStyle(saved);
  ASSERT_TRUE(back) << back.error();
  ASSERT_TRUE(applyStyle(*back, other, *r));
  EXPECT_EQ(other.palette->name, state.palette->name);
  EXPECT_EQ(other.settings.path, state.settings.path);
  EXPECT_EQ(other.settings.match, state.settings.match);
  EXPECT_EQ(other.settings.lines.silhouettes, state.settings.lines.silhouettes);
  EXPECT_EQ(other.settings.lines.creases, state.settings.lines.creases);
  EXPECT_EQ(other.settings.lines.creaseAngle, state.settings.lines.creaseAngle);
  EXPECT_EQ(formatLineSets(other.settings.lines.sets), formatLineSets(state.settings.lines.sets));
  EXPECT_EQ(r->lighting().toneModel(), ToneModel::Gooch);
  EXPECT_TRUE(other.settings.ground && other.settings.shadows);
  EXPECT_EQ(other.light, state.light);
  EXPECT_FALSE(other.settings.occlusion);
  EXPECT_EQ(std::filesystem::path(other.shadowPalette).filename(), "stipple.palette");
  EXPECT_TRUE(other.occlusionPalette.empty());
  EXPECT_TRUE(r->palettes().hasControl(ControlParameter::Shadow));
  // Bad styles: the reason with file and line, and the look as it was.
  const std::string before = styleText(other, *r, "x");
  for (const auto& [text, line] : std::vector<std::pair<std::string, int>>{{"name A\nfrobnicate 3\n", 2},
                                                                           {"path sideways\n", 1},
                                                                           {"\nrange-scale nan\n", 2},
                                                                           {"lines silhouette,glow\n", 1},
                                                                           {"pattern-scale 100\n", 1},
                                                                           {"shadows maybe\n", 1},
                                                                           {"light 1,2\n", 1},
                                                                           {"light 1,nan,2\n", 1},
                                                                           {"name B\nshadow-palette\n", 2}}) {
    Result<Style> bad = loadStyle(d.write("bad.style", text));
    ASSERT_FALSE(bad) << text;
    EXPECT_NE(bad.error().find("bad.style line " + std::to_string(line)), std::string::npos) << bad.error();
  }
  Result<Style> missing = loadStyle(d.write("missing.style", "path smooth\npalette nowhere/none.palette\nlines crease\n"));
  ASSERT_TRUE(missing);  // the file parses; its palette fails when applied
  EXPECT_FALSE(applyStyle(*missing, other, *r));
  EXPECT_EQ(styleText(other, *r, "x"), before);
  Result<Style> brokenControl = loadStyle(d.write("control.style", "shadows on\nshadow-palette nowhere/none.palette\n"));
  ASSERT_TRUE(brokenControl);
  EXPECT_FALSE(applyStyle(*brokenControl, other, *r));
  EXPECT_EQ(styleText(other, *r, "x"), before);
  r->palettes().clearControl(ControlParameter::Shadow);
}

}  // namespace
}  // namespace npr

namespace npr {
namespace {

// Scenes of several files: fitted into the unit sphere as a whole (the camera, light and
// ground are sized for it), laid out apart on request, and a file that fails leaves the scene
// as it was, drawing the same picture.
using SceneStateFixture = test::RendererFixture;

float sceneRadius(const ViewerState& state, float* nearest = nullptr) {
  float far = 0.0f, close = 1e9f;
  for (const ViewerObject& o : state.scene.objects()) {
    const glm::mat4 t = state.scene.toViewer(o.file) * o.inFile;
    for (const glm::vec3& p : o.mesh->positions) {
      const float d = glm::length(glm::vec3(t * glm::vec4(p, 1.0f)));
      far = std::max(far, d);
      close = std::min(close, d);
    }
  }
  if (nearest) *nearest = close;
  return far;
}

TEST_F(SceneStateFixture, SeveralFilesAreOneSceneFittedToTheUnitSphere) {
  ViewerState state;
  ASSERT_TRUE(state.loadPalette(sourcePath("palettes/crosshatch/crosshatch.palette"), *r));
  const std::vector<std::string> files = {sourcePath("models/bunny.obj"), sourcePath("models/teapot.obj")};
  ASSERT_TRUE(state.loadModels(files, false, *r));
  ASSERT_EQ(state.scene.objects().size(), 2u);
  EXPECT_EQ(r->scene().size(), 2u);
  EXPECT_NEAR(sceneRadius(state), 1.0f, 0.02f);
  // In a row the two stand apart: the bunny left of the teapot, neither overlapping the other.
  state.scene.setLayout(Layout::Row, *r);
  EXPECT_NEAR(sceneRadius(state), 1.0f, 0.02f);
  const auto& objects = state.scene.objects();
  const float bunnyX = (state.scene.toViewer(objects[0].file) * objects[0].inFile)[3].x;
  const float teapotX = (state.scene.toViewer(objects[1].file) * objects[1].inFile)[3].x;
  EXPECT_LT(bunnyX + 0.3f, teapotX);

  RenderSettings s;
  s.path = RenderPath::Pixel;
  const ImageRGBA8 before = renderImage(*r, testCamera(1.0f), s, 96, 96);
  test::TempDir d;
  EXPECT_FALSE(state.loadModels({sourcePath("models/teapot.obj"), d.write("broken.obj", "v 0 0 0\n")}, true, *r));
  EXPECT_FALSE(state.loadModels({d.write("broken.glb", "glTF nothing")}, false, *r));
  ASSERT_EQ(state.scene.objects().size(), 2u);
  EXPECT_EQ(r->scene().size(), 2u);
  EXPECT_EQ(countDiffering(before, renderImage(*r, testCamera(1.0f), s, 96, 96)), 0);
  // Picking: the ray through the teapot's centre on screen meets the teapot; the corner of
  // the view meets nothing; framing the picked object looks at its centre.
  const CameraMatrices view = testCamera(1.0f);
  const glm::vec4 teapot = state.scene.sphere(1);
  const glm::vec4 clip = view.projection * view.view * glm::vec4(glm::vec3(teapot), 1.0f);
  const std::optional<std::size_t> hit = state.scene.pick(view, glm::vec2(clip) / clip.w);
  ASSERT_TRUE(hit);
  EXPECT_EQ(*hit, 1u);
  EXPECT_FALSE(state.scene.pick(view, glm::vec2(0.98f, 0.98f)));
  state.scene.setVisible(1, false, *r);
  EXPECT_FALSE(state.scene.pick(view, glm::vec2(clip) / clip.w)) << "a hidden object was picked";
  state.scene.setVisible(1, true, *r);
  state.camera.frameSphere(glm::vec3(teapot), teapot.w);
  EXPECT_LT(glm::length(state.camera.target() - glm::vec3(teapot)), 1e-6f);
  EXPECT_LT(state.camera.distance(), 3.0f);

  // Added beside it, a third object; the scene is fitted again.
  ASSERT_TRUE(state.loadModels({sourcePath("models/teapot.obj")}, true, *r));
  EXPECT_EQ(state.scene.objects().size(), 3u);
  EXPECT_NEAR(sceneRadius(state), 1.0f, 0.02f);
}

TEST_F(SceneStateFixture, TheFilesCameraAndLightsAreUsed) {
  test::TempDir d;
  // A unit square in z = 0 seen by a camera 4 units up the z axis, lit by a red directional
  // light from +z.
  const float p[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
  std::string bin(reinterpret_cast<const char*>(p), 48);
  bin.append(reinterpret_cast<const char*>(idx), 12);
  d.write("square.bin", bin);
  const std::string gltf = d.write("lit.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1,2]}],
    "nodes":[{"mesh":0},{"camera":0,"translation":[0,0,4]},{"extensions":{"KHR_lights_punctual":{"light":0}}}],
    "cameras":[{"type":"perspective","perspective":{"yfov":0.5,"znear":0.1,"zfar":20}}],
    "extensionsUsed":["KHR_lights_punctual"],
    "extensions":{"KHR_lights_punctual":{"lights":[{"type":"directional","color":[1,0,0],"intensity":3}]}},
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,0],"max":[1,1,0]},
                 {"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"}],
    "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":12}],
    "buffers":[{"uri":"square.bin","byteLength":60}]})");
  ViewerState state;
  ASSERT_TRUE(state.loadModels({gltf}, false, *r));
  ASSERT_TRUE(state.useFileCamera(1));
  EXPECT_FALSE(state.useFileCamera(2));
  const CameraMatrices cam = state.view(1.0f);
  // The square's centre is straight ahead: the middle of the picture.
  const glm::vec4 clip = cam.projection * cam.view * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-4f);
  EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-4f);
  // Its corner (1, 1) in the file, fitted by the scene's scale, is where yfov 0.5 puts it.
  const glm::vec4 corner = cam.projection * cam.view * glm::vec4(glm::vec3(state.scene.toViewer(0) * glm::vec4(1, 1, 0, 1)), 1.0f);
  EXPECT_NEAR(corner.y / corner.w, 1.0f / (4.0f * std::tan(0.25f)), 1e-3f);
  // Lit by the file's red light: the reference path shows a red square.
  ASSERT_TRUE(state.applyLight(*r, cam));
  EXPECT_TRUE(r->lighting().light(0).enabled);
  EXPECT_NEAR(r->lighting().light(0).diffuse.r, 1.0f, 1e-6f);
  EXPECT_NEAR(r->lighting().light(0).diffuse.g, 0.0f, 1e-6f);
  for (int i = 1; i < kMaxLights; ++i) EXPECT_FALSE(r->lighting().light(i).enabled);
  RenderSettings s;
  s.path = RenderPath::Reference;
  const ImageRGBA8 img = renderImage(*r, cam, s, 64, 64);
  const unsigned char* centre = &img.pixels[4 * (32 * 64 + 32)];
  EXPECT_GT(centre[0], centre[1] + 60) << "not lit red";
  // Without them, the viewer's white light again.
  state.fileLights = false;
  ASSERT_TRUE(state.applyLight(*r, cam));
  EXPECT_NEAR(r->lighting().light(0).diffuse.g, 1.0f, 1e-6f);
}

// An object that slides ten of its sizes across the scene stays in the frame all through its
// motion: the camera frames its poses over the animation, not its rest place alone.
TEST_F(SceneStateFixture, AnAnimatedSceneIsFramedOverItsWholeMotion) {
  test::TempDir d;
  const float p[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const std::uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
  const float times[2] = {0.0f, 2.0f};
  const float slide[6] = {0, 0, 0, 20, 0, 0};
  std::string bin(reinterpret_cast<const char*>(p), 48);
  bin.append(reinterpret_cast<const char*>(idx), 12);
  bin.append(reinterpret_cast<const char*>(times), 8);
  bin.append(reinterpret_cast<const char*>(slide), 24);
  d.write("slide.bin", bin);
  const std::string gltf = d.write("slide.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
    "nodes":[{"mesh":0,"translation":[0,-3,0]},{"mesh":0,"translation":[0,3,0]}],
    "meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
    "animations":[{"channels":[{"sampler":0,"target":{"node":1,"path":"translation"}}],
                   "samplers":[{"input":2,"output":3}]}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,0],"max":[1,1,0]},
                 {"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"},
                 {"bufferView":2,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[2]},
                 {"bufferView":3,"componentType":5126,"count":2,"type":"VEC3"}],
    "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":12},
                   {"buffer":0,"byteOffset":60,"byteLength":8},{"buffer":0,"byteOffset":68,"byteLength":24}],
    "buffers":[{"uri":"slide.bin","byteLength":92}]})");
  ViewerState state;
  state.viewAspect = 1.0f;
  ASSERT_TRUE(state.loadModels({gltf}, false, *r));
  ASSERT_NEAR(state.animationLength(), 2.0, 1e-6);
  const CameraMatrices cam = state.view(1.0f);
  // Every corner of both squares, at every tenth of the motion, inside the picture; the
  // sliding square's last pose reaches near the picture's edge (framed, not lost in it).
  float reach = 0.0f;
  for (int k = 0; k <= 10; ++k) {
    state.playback.time = 0.2 * k;
    state.poseScene(*r);
    for (const ViewerObject& o : state.scene.objects())
      for (const glm::vec3& v : o.mesh->positions) {
        const glm::vec4 clip = cam.projection * cam.view * o.placed * glm::vec4(v, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        EXPECT_LE(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0f) << o.name << " at " << state.playback.time << " s is outside the frame";
        reach = std::max(reach, std::abs(ndc.x));
      }
  }
  EXPECT_GT(reach, 0.6f) << "the motion is framed with room to spare";
}

// Ctrl+E's picture beyond the GL's framebuffer limit is a poster, drawn tile by tile between
// the window's frames: the whole size is written, nothing is under its name until it is
// finished, and one cancelled after its first tile leaves nothing behind.
TEST_F(SceneStateFixture, AnExportBeyondTheFramebufferLimitIsAPosterInTiles) {
  test::TempDir d;
  ViewerState state;
  ASSERT_TRUE(state.loadPalette(sourcePath("palettes/crosshatch/crosshatch.palette"), *r));
  ASSERT_TRUE(state.loadModels({sourcePath("models/bunny.obj")}, false, *r));
  ExportRequest request;
  request.path = (d.path() / "poster.png").string();
  request.size = {maxFramebufferSide() + 100, 48};
  Result<std::unique_ptr<ExportJob>> job = ExportJob::start(request, state);
  ASSERT_TRUE(job) << job.error();
  int steps = 0;
  for (bool done = false; !done; ++steps) {
    Result<bool> step = (*job)->step(state, *r, 0.0);  // one tile a step
    ASSERT_TRUE(step) << step.error();
    done = *step;
    if (!done) {
      EXPECT_FALSE(std::filesystem::exists(request.path)) << "written under its name before it was finished";
    }
  }
  EXPECT_GE(steps, 2) << "not drawn in tiles";
  EXPECT_NE((*job)->label().find("tile"), std::string::npos) << (*job)->label();
  job->reset();
  // Its size from the PNG's header (IHDR: width and height, big-endian, at bytes 16 and 20):
  // the image readers refuse pictures this wide, as they should for palettes.
  std::ifstream png(request.path, std::ios::binary);
  unsigned char header[24] = {};
  ASSERT_TRUE(png.read(reinterpret_cast<char*>(header), 24));
  const auto be32 = [&](int at) { return int(header[at]) << 24 | int(header[at + 1]) << 16 | int(header[at + 2]) << 8 | int(header[at + 3]); };
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(header + 12), 4), "IHDR");
  EXPECT_EQ(be32(16), request.size.x);
  EXPECT_EQ(be32(20), request.size.y);

  request.path = (d.path() / "cancelled.png").string();
  {
    Result<std::unique_ptr<ExportJob>> cancelled = ExportJob::start(request, state);
    ASSERT_TRUE(cancelled) << cancelled.error();
    ASSERT_TRUE((*cancelled)->step(state, *r, 0.0));
  }
  std::vector<std::string> left;
  for (const auto& e : std::filesystem::directory_iterator(d.path())) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"poster.png"}) << "a cancelled poster left a file";
}

TEST_F(SceneStateFixture, AnimationPosesWhatItMovesCarriesChildrenAndLeavesTheRestStill) {
  ViewerState state;
  ASSERT_TRUE(state.loadPalette(sourcePath("palettes/crosshatch/crosshatch.palette"), *r));
  ASSERT_TRUE(state.loadModels({sourcePath("models/pendulum.gltf")}, false, *r));
  ASSERT_EQ(state.scene.animationNames(), std::vector<std::string>{"swing and bounce"});
  EXPECT_NEAR(state.animationLength(), 2.0, 1e-6);
  const auto& objects = state.scene.objects();
  ASSERT_EQ(objects.size(), 5u);  // base, arm, bob, ball, growing box
  auto origin = [&](std::size_t i) { return glm::vec3(objects[i].placed[3]); };
  RenderSettings s;
  s.path = RenderPath::Pixel;
  const ImageRGBA8 atStart = renderImage(*r, testCamera(1.0f), s, 96, 96);
  std::vector<glm::mat4> start;
  for (const ViewerObject& o : objects) start.push_back(o.placed);
  const float armToBob = glm::length(origin(2) - origin(1));

  state.playback.time = 0.5;
  state.poseScene(*r);
  EXPECT_EQ(objects[0].placed, start[0]) << "the base has no animation and moved";
  for (std::size_t i = 1; i < 5; ++i) EXPECT_NE(objects[i].placed, start[i]) << objects[i].name << " did not move";
  // The bob is the arm's child: carried rigidly, at the same distance from the arm.
  EXPECT_NEAR(glm::length(origin(2) - origin(1)), armToBob, 1e-5f);
  // At 0.5 s the swing passes through the bottom: the bob straight under the pivot, the arm
  // vertical (the pivot's rotation is the identity there).
  EXPECT_NEAR(origin(1).x, origin(2).x, 1e-5f);
  EXPECT_GT(countDiffering(atStart, renderImage(*r, testCamera(1.0f), s, 96, 96)), 100);

  // None: the rest pose, as the file places the nodes without animation.
  state.playback.choice = {AnimationChoice::Which::None, 0};
  state.poseScene(*r);
  for (const ViewerObject& o : objects) {
    const glm::mat4 rest = state.scene.toViewer(o.file) * o.inFile;
    for (int c = 0; c < 4; ++c) EXPECT_LT(glm::length(glm::vec4(o.placed[c] - rest[c])), 1e-5f) << o.name;
  }
  // Back to the start: the same picture as before.
  state.playback.choice = {};
  state.playback.time = 0.0;
  state.poseScene(*r);
  EXPECT_EQ(countDiffering(atStart, renderImage(*r, testCamera(1.0f), s, 96, 96)), 0);

  // The clock loops over the animation's length; a paused one stays.
  state.playback.time = 1.9;
  state.playback.playing = true;
  state.playback.advance(0.2, state.animationLength());
  EXPECT_NEAR(state.playback.time, 0.1, 1e-9);
  state.playback.playing = false;
  state.playback.advance(0.2, state.animationLength());
  EXPECT_NEAR(state.playback.time, 0.1, 1e-9);
  // --animation by name, number, all, none; a wrong one is named with the choices.
  EXPECT_TRUE(parseAnimationChoice("swing and bounce", state.scene.animationNames()));
  EXPECT_EQ(parseAnimationChoice("1", state.scene.animationNames())->one, 0u);
  const Result<AnimationChoice> wrong = parseAnimationChoice("walk", state.scene.animationNames());
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.error().find("swing and bounce"), std::string::npos) << wrong.error();
  EXPECT_FALSE(parseAnimationChoice("2", state.scene.animationNames()));
}

}  // namespace
}  // namespace npr

namespace npr {
namespace {

// A model added to a scene laid out as its files place it (Shift-drop, Ctrl+Shift+O) is set
// beside the scene at the scene's size, whatever its units: a teapot a thousand times larger
// than the bunny neither swallows it nor, the other way round, shrinks to a speck.
using AddFixture = test::RendererFixture;
TEST_F(AddFixture, AnAddedModelStandsBesideTheSceneAtItsSize) {
  test::TempDir d;
  std::string big;
  {
    auto teapot = loadMesh(test::sourcePath("models/teapot.obj"));
    ASSERT_TRUE(teapot);
    Mesh m = *teapot;
    for (glm::vec3& p : m.positions) p *= 1000.0f;
    test::writeObj(m, (d.path() / "big-teapot.obj").string());
    big = (d.path() / "big-teapot.obj").string();
  }
  for (const bool tinyFirst : {true, false}) {
    ViewerState state;
    ASSERT_TRUE(state.loadPalette(defaultPalettePath(), *r));
    ASSERT_TRUE(state.loadModel(tinyFirst ? test::sourcePath("models/bunny.obj") : big, *r));
    ASSERT_TRUE(state.loadModels({tinyFirst ? big : test::sourcePath("models/bunny.obj")}, true, *r));
    ASSERT_EQ(state.scene.objects().size(), 2u);
    const glm::vec4 a = state.scene.sphere(0), b = state.scene.sphere(1);
    const float ratio = b.w / a.w;
    EXPECT_GT(ratio, 0.5f) << "the added model is a speck beside the scene";
    EXPECT_LT(ratio, 2.0f) << "the added model swallows the scene";
    EXPECT_GT(glm::distance(glm::vec3(a), glm::vec3(b)), 0.9f * (a.w + b.w)) << "the added model overlaps the scene";
  }
}

}  // namespace
}  // namespace npr

namespace npr {
namespace {

// The style menu's pictures: one drawn per frame the menu asks, each the scene in that style
// (the styles' pictures differ), by a renderer of their own that is let go once all are drawn;
// the window's renderer draws exactly as before, its tone range where it was.
TEST_F(Fixture, StylePicturesAreDrawnOneAFrameAsideFromTheWindowsRenderer) {
  ViewerState live;
  live.echo = false;
  ASSERT_TRUE(live.loadModel(sourcePath("models/bunny.obj"), *r));
  ASSERT_TRUE(live.loadPalette(sourcePath("palettes/crosshatch/crosshatch.palette"), *r));
  live.frameScene();
  const CameraMatrices cam = live.view(float(StyleThumbnails::kWidth) / float(StyleThumbnails::kHeight));
  const ImageRGBA8 before = renderImage(*r, cam, live.settings, 96, 72);
  const std::optional<glm::vec2> toneBefore = r->toneRange();

  StyleThumbnails pictures;
  ASSERT_TRUE(pictures.drawStep(live));
  EXPECT_EQ(pictures.drawn(), 0u) << "drawn without the menu asking";
  const std::vector<std::string> styles = discoverStyles();
  ASSERT_GE(styles.size(), 3u);
  for (std::size_t i = 0; i < styles.size(); ++i) {
    pictures.request();
    const Status st = pictures.drawStep(live);
    ASSERT_TRUE(st) << st.error();
    EXPECT_EQ(pictures.drawn(), i + 1) << "not one picture a frame";
  }
  EXPECT_TRUE(pictures.holdsRenderer());
  pictures.request();
  ASSERT_TRUE(pictures.drawStep(live));
  EXPECT_FALSE(pictures.holdsRenderer()) << "the second renderer is kept after every picture is drawn";
  // Each picture shows the bunny: ink in its middle; cel's and charcoal's differ in colour.
  auto mean = [](const ImageRGBA8& img) {
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < img.pixels.size(); i += 4) sum += glm::dvec3(img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]);
    return sum / double(img.pixels.size() / 4);
  };
  std::optional<ImageRGBA8> celPicture, charcoalPicture;
  for (const std::string& s : styles) {
    if (std::filesystem::path(s).stem() == "cel") celPicture = pictures.picture(s);
    if (std::filesystem::path(s).stem() == "charcoal") charcoalPicture = pictures.picture(s);
  }
  ASSERT_TRUE(celPicture && charcoalPicture);
  EXPECT_EQ(celPicture->width, StyleThumbnails::kWidth);
  const glm::dvec3 a = mean(*celPicture), b = mean(*charcoalPicture);
  std::printf("mean colour: cel %.0f %.0f %.0f, charcoal %.0f %.0f %.0f\n", a.x, a.y, a.z, b.x, b.y, b.z);
  EXPECT_GT(glm::length(a - b), 10.0) << "the pictures do not show their styles";
  // The window's renderer: the same frame, the same tone range, its palette still crosshatch.
  const ImageRGBA8 after = renderImage(*r, cam, live.settings, 96, 72);
  EXPECT_EQ(countDiffering(before, after), 0);
  EXPECT_EQ(r->toneRange().has_value(), toneBefore.has_value());
  if (toneBefore && r->toneRange()) {
    EXPECT_EQ(*r->toneRange(), *toneBefore);
  }
  EXPECT_EQ(live.palette->name, "Crosshatch");
}

}  // namespace
}  // namespace npr
