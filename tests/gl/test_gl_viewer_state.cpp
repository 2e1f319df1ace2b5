// GL tier, app level: the viewer's scene state on the headless context. A model or palette
// that fails to load leaves the current one drawing exactly as before.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/settings/style_file.h"
#include "app/viewer_state.h"
#include "gl/gl_test_env.h"
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
  r->setMesh(&mesh);
  ASSERT_TRUE(state.loadPalette(sourcePath("palettes/cel/cel.palette"), *r));
  RenderSettings s;
  s.path = RenderPath::Pixel;
  s.match = state.settings.match;
  const ImageRGBA8 before = renderImage(*r, testCamera(1.0f), s, 64, 64);
  test::TempDir d;
  EXPECT_FALSE(state.loadPalette(d.write("broken.palette", "missing.png\n"), *r));
  EXPECT_FALSE(state.loadModel(d.write("broken.obj", "v 0 0 0\n"), *r));
  EXPECT_EQ(state.palette->name, "Cel (4 tones)");
  const ImageRGBA8 after = renderImage(*r, testCamera(1.0f), s, 64, 64);
  EXPECT_EQ(countDiffering(before, after), 0);
  EXPECT_GE(state.messages.size(), 2u);  // both failures are reported for the overlay
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
  r->setMesh(&*mesh);
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
    r->clearControlPalette(ControlParameter::Shadow);
    r->clearControlPalette(ControlParameter::Occlusion);
  }
}

TEST_F(StyleFixture, SavedStyleLoadsBackAndBadStylesChangeNothing) {
  const Mesh mesh = test::icosphere(3);
  r->setMesh(&mesh);
  ViewerState state;
  ASSERT_TRUE(state.loadPalette(defaultPalettePath(), *r));
  Result<Style> technical = loadStyle(resolveStyle("technical"));
  ASSERT_TRUE(technical) << technical.error();
  ASSERT_TRUE(applyStyle(*technical, state, *r));
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
  EXPECT_EQ(r->lighting().toneModel(), ToneModel::Gooch);
  EXPECT_TRUE(other.settings.ground && other.settings.shadows);
  EXPECT_EQ(other.light, state.light);
  EXPECT_FALSE(other.settings.occlusion);
  EXPECT_EQ(std::filesystem::path(other.shadowPalette).filename(), "stipple.palette");
  EXPECT_TRUE(other.occlusionPalette.empty());
  EXPECT_TRUE(r->hasControlPalette(ControlParameter::Shadow));
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
  r->clearControlPalette(ControlParameter::Shadow);
}

}  // namespace
}  // namespace npr
