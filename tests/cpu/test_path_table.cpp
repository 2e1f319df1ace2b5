// CPU tier: the path table every front end reads (CLI, overlay, benchmark, e2e scripts) and
// the typed program variants the program cache is keyed by.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "renderer/gl/program_cache.h"
#include "renderer/programs/program_variants.h"
#include "renderer/paths/path_table.h"
#include "renderer/paths/render_pass.h"
#include "renderer/settings/render_settings.h"
#include "renderer/settings/choice_names.h"

namespace npr {
namespace {

TEST(PathTable, EveryPathHasExactlyOneRowWithAUniqueName) {
  std::set<int> ids;
  std::set<std::string> names;
  for (const PathInfo& p : renderPaths()) {
    EXPECT_TRUE(ids.insert(static_cast<int>(p.id)).second) << p.name;
    EXPECT_TRUE(names.insert(p.name).second) << p.name;
    EXPECT_FALSE(std::string(p.label).empty()) << p.name;
    EXPECT_EQ(&pathInfo(p.id), &p) << p.name;
    ASSERT_TRUE(parseRenderPath(p.name)) << p.name;
    EXPECT_EQ(*parseRenderPath(p.name), p.id);
    EXPECT_NE(p.create(), nullptr) << p.name;
  }
  // The enumerators run from Stencil to LitTextured without gaps.
  EXPECT_EQ(ids.size(), static_cast<size_t>(RenderPath::LitTextured) + 1);
  EXPECT_EQ(*ids.begin(), 0);
  EXPECT_FALSE(parseRenderPath("sideways"));
}

TEST(PathTable, UserPathsAreTheSelectableRowsInTableOrder) {
  std::vector<RenderPath> expected;
  for (const PathInfo& p : renderPaths())
    if (p.userSelectable) expected.push_back(p.id);
  EXPECT_EQ(userRenderPaths(), expected);
  std::string joined;
  for (RenderPath p : expected) joined += (joined.empty() ? "" : "|") + std::string(renderPathName(p));
  EXPECT_EQ(userRenderPathNames("|"), joined);
  // The shipped paths stay offered (a new row adds to these; it needs no edit here).
  for (const char* name : {"stencil", "triangle", "vertex", "pixel", "smooth", "reference"}) {
    const std::optional<RenderPath> p = parseRenderPath(name);
    ASSERT_TRUE(p) << name;
    EXPECT_TRUE(std::find(expected.begin(), expected.end(), *p) != expected.end()) << name;
  }
  EXPECT_FALSE(pathInfo(RenderPath::LitTextured).userSelectable);
  EXPECT_FALSE(pathInfo(RenderPath::Reference).usesPalette);
  EXPECT_TRUE(pathInfo(RenderPath::Stencil).perTriangle && pathInfo(RenderPath::Triangle).perTriangle);
  EXPECT_FALSE(pathInfo(RenderPath::Pixel).perTriangle);
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

TEST(ProgramVariants, DefinesFollowTheFields) {
  gl::MeshProgram m;
  m.shading = gl::MeshShading::Vertex;
  m.output = gl::MeshOutput::Blend;
  LightingFeatures f;
  f.lightCount = 2;
  f.spot = true;
  m.lighting = f;
  gl::PaletteVariant pv;
  pv.size = 10;
  pv.match = MatchMode::Order;
  m.palette = pv;
  const gl::ProgramSource s = gl::programSource(m);
  EXPECT_EQ(s.vertexFile, "mesh.vert");
  EXPECT_EQ(s.fragmentFile, "mesh.frag");
  for (const char* d : {"PATH_VERTEX", "PER_VERTEX_LIGHTING", "OUTPUT_BLEND", "NUM_LIGHTS 2", "HAS_SPOT", "PALETTE_SIZE 10", "MATCH_ORDER"})
    EXPECT_TRUE(has(s.defines, d)) << d;
  EXPECT_FALSE(has(s.defines, "PALETTE_PRECOMPOSITED"));
  // The per-triangle path lights on the CPU: no lighting defines at all.
  gl::MeshProgram t;
  t.shading = gl::MeshShading::Triangle;
  t.palette = pv;
  for (const std::string& d : gl::programSource(t).defines) EXPECT_EQ(d.find("NUM_LIGHTS"), std::string::npos) << d;
  const gl::ProgramSource q = gl::programSource(gl::QuadProgram{gl::QuadProgram::Kind::Background, true});
  EXPECT_EQ(q.fragmentFile, "quad.frag");
  EXPECT_TRUE(has(q.defines, "QUAD_BACKGROUND") && has(q.defines, "BACKGROUND_IMAGE"));
}

// The outline programs: a geometry stage for the methods that build quads and fattened faces,
// none for the offset method (the rasterizer culls); the rim reads the palette. The
// object-space pattern's quads read its coordinates from the stencil path's buffer.
TEST(ProgramVariants, OutlinesStrokesAndObjectPatterns) {
  const gl::ProgramSource fatten = gl::programSource(gl::OutlineProgram{OutlineMethod::Fatten, std::nullopt});
  EXPECT_EQ(fatten.geometryFile, "outline.geom");
  EXPECT_TRUE(has(fatten.defines, "OUTLINE_FATTEN"));
  const gl::ProgramSource offset = gl::programSource(gl::OutlineProgram{OutlineMethod::Offset, std::nullopt});
  EXPECT_TRUE(offset.geometryFile.empty());
  gl::PaletteVariant pv;
  pv.size = 4;
  pv.pattern = gl::PatternMapping::Object;
  const gl::ProgramSource rim = gl::programSource(gl::OutlineProgram{OutlineMethod::Fatten, pv});
  EXPECT_TRUE(has(rim.defines, "OUTLINE_RIM") && has(rim.defines, "PALETTE_SIZE 4"));
  const gl::ProgramSource strokes = gl::programSource(gl::StrokeProgram{LightingFeatures{}, pv});
  EXPECT_EQ(strokes.vertexFile, "strokes.vert");
  const gl::ProgramSource quad = gl::programSource(gl::QuadProgram{gl::QuadProgram::Kind::Layer, false, gl::PatternMapping::Object});
  EXPECT_TRUE(has(quad.defines, "PATTERN_OBJECT") && has(quad.defines, "PATTERN_OBJECT_BUFFER"));
  gl::MeshProgram m;
  m.palette = pv;
  EXPECT_TRUE(has(gl::programSource(m).defines, "PATTERN_OBJECT"));
  EXPECT_FALSE(has(gl::programSource(m).defines, "PATTERN_OBJECT_BUFFER"));
}

// The settings' text forms: what the command line and style files accept.
TEST(RenderSettingsText, NewKindsMethodsSpacesAndSizes) {
  LineSettings l;
  std::string unknown;
  ASSERT_TRUE(parseLineKinds("silhouette,hardware,rim", l, &unknown));
  EXPECT_TRUE(l.silhouettes && l.hardware && l.rim && !l.creases);
  EXPECT_FALSE(parseLineKinds("silhouette,wobbly", l, &unknown));
  EXPECT_EQ(unknown, "wobbly");
  EXPECT_TRUE(l.hardware);  // untouched on failure
  for (OutlineMethod m : {OutlineMethod::Edges, OutlineMethod::Offset, OutlineMethod::Fatten})
    EXPECT_EQ(parseChoice<OutlineMethod>(choiceName(m)), m);
  EXPECT_FALSE(parseChoice<OutlineMethod>("round"));
  EXPECT_EQ(parseChoice<PatternSpace>("object"), PatternSpace::Object);
  EXPECT_EQ(parseChoice<PatternSpace>(choiceName(PatternSpace::Object)), PatternSpace::Object);
  EXPECT_EQ(parseStrokeSize("16x6"), glm::vec2(16.0f, 6.0f));
  for (const char* bad : {"16", "16x", "0x6", "16x300", "16x6x2", "nanx6", "16x6px"}) EXPECT_FALSE(parseStrokeSize(bad)) << bad;
}

TEST(ProgramVariants, EachFieldMakesADistinctCacheKey) {
  // The cache is keyed by the variant's source (gl::programKey): equal variants must share a
  // key and every field that changes the defines must change the key.
  std::map<std::string, int> cache;
  gl::MeshProgram base;
  base.lighting = LightingFeatures{};
  base.palette = gl::PaletteVariant{};
  std::vector<gl::ProgramVariant> variants = {base};
  auto with = [&](auto change) {
    gl::MeshProgram m = base;
    change(m);
    variants.push_back(m);
  };
  with([](gl::MeshProgram& m) { m.shading = gl::MeshShading::Smooth; });
  with([](gl::MeshProgram& m) { m.output = gl::MeshOutput::Entry; });
  with([](gl::MeshProgram& m) { m.lighting->specular = true; });
  with([](gl::MeshProgram& m) { m.lighting->lightCount = 3; });
  with([](gl::MeshProgram& m) { m.lighting->tone = ToneModel::Gooch; });
  with([](gl::MeshProgram& m) { m.lighting.reset(); });
  with([](gl::MeshProgram& m) { m.palette->size = 30; });
  with([](gl::MeshProgram& m) { m.palette->precomposited = true; });
  with([](gl::MeshProgram& m) { m.palette->match = MatchMode::Colors; });
  with([](gl::MeshProgram& m) { m.palette.reset(); });
  variants.push_back(gl::QuadProgram{gl::QuadProgram::Kind::Layer, false});
  variants.push_back(gl::QuadProgram{gl::QuadProgram::Kind::Background, false});
  variants.push_back(gl::LineProgram{true, false});
  variants.push_back(gl::LineProgram{false, true});
  variants.push_back(gl::EdgeProgram{});
  variants.push_back(gl::MarkerProgram{});
  for (auto method : {OutlineMethod::Edges, OutlineMethod::Offset, OutlineMethod::Fatten})
    variants.push_back(gl::OutlineProgram{method, std::nullopt});
  variants.push_back(gl::OutlineProgram{OutlineMethod::Fatten, gl::PaletteVariant{}});
  variants.push_back(gl::StrokeProgram{LightingFeatures{}, gl::PaletteVariant{}});
  with([](gl::MeshProgram& m) { m.palette->pattern = gl::PatternMapping::Object; });
  with([](gl::MeshProgram& m) { m.shading = gl::MeshShading::PatternCoordinate; });
  variants.push_back(gl::QuadProgram{gl::QuadProgram::Kind::Layer, false, gl::PatternMapping::Object});
  for (size_t i = 0; i < variants.size(); ++i) cache.emplace(gl::programKey(gl::programSource(variants[i])), int(i));
  EXPECT_EQ(cache.size(), variants.size());
  std::set<std::vector<std::string>> defineSets;
  for (const auto& v : variants) {
    const gl::ProgramSource s = gl::programSource(v);
    std::vector<std::string> key = s.defines;
    key.push_back(s.vertexFile + "+" + s.geometryFile + "+" + s.fragmentFile);
    defineSets.insert(key);
  }
  EXPECT_EQ(defineSets.size(), variants.size()) << "two variants compile to the same program";
  gl::MeshProgram same = base;
  EXPECT_FALSE(cache.emplace(gl::programKey(gl::programSource(same)), -1).second);
}

}  // namespace
}  // namespace npr
