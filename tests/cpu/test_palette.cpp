// CPU tier: palette files, image loading through OpenImageIO, alpha-aware analysis, the
// three match modes, IntensityRangeScale, ties and the extremes.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <limits>
#include <random>

#include "renderer/core/colour.h"
#include "renderer/core/image_io.h"
#include "renderer/palette/palette.h"
#include "renderer/palette/palette_analysis.h"
#include "renderer/palette/palette_matcher.h"
#include "support/test_util.h"

namespace npr {
namespace {

using test::TempDir;

ImageRGBA8 solidImage(int w, int h, glm::vec3 c, float a = 1.0f) {
  ImageRGBA8 img{w, h, std::vector<std::uint8_t>(size_t(w) * h * 4)};
  for (size_t i = 0; i < img.pixels.size(); i += 4) {
    for (int k = 0; k < 3; ++k) img.pixels[i + size_t(k)] = std::uint8_t(std::lround(c[k] * 255));
    img.pixels[i + 3] = std::uint8_t(std::lround(a * 255));
  }
  return img;
}

// Writes images of the given grey levels and a palette file listing them.
std::string greyPalette(const TempDir& d, const std::vector<float>& greys, const std::string& header = "") {
  std::string text = header;
  for (size_t i = 0; i < greys.size(); ++i) {
    const std::string name = "g" + std::to_string(i) + ".png";
    EXPECT_TRUE(writeImage((d.path() / name).string(), solidImage(2, 2, glm::vec3(greys[i]))));
    text += name + "\n";
  }
  return d.write("p.palette", text);
}

std::vector<glm::vec3> greys(std::vector<float> v) {
  std::vector<glm::vec3> out;
  for (float g : v) out.push_back(glm::vec3(g));
  return out;
}

// ---- Palette files ----------------------------------------------------------------------

TEST(PaletteFile, ParsesEntriesCommentsAndOptions) {
  TempDir d;
  const std::string p = greyPalette(d, {0.0f, 0.5f, 1.0f},
                                    "# a comment\n\nname My style\nmatch order\nrange-scale 2.5\nbackground #FF0000\n");
  auto pal = loadPalette(p);
  ASSERT_TRUE(pal) << pal.error();
  EXPECT_EQ(pal->entries.size(), 3u);
  EXPECT_EQ(pal->name, "My style");
  EXPECT_EQ(pal->defaultMatch, MatchMode::Order);
  EXPECT_FLOAT_EQ(*pal->defaultRangeScale, 2.5f);
  EXPECT_EQ(pal->backgroundColour, glm::vec3(1, 0, 0));
  EXPECT_NEAR(pal->entries[1].average.r, 128.0f / 255.0f, 1.5f / 255.0f);  // opaque: the texel itself
}

TEST(PaletteFile, BackgroundImageAndTransparentEntries) {
  TempDir d;
  ASSERT_TRUE(writeImage((d.path() / "bg.png").string(), solidImage(4, 4, glm::vec3(0.2f, 0.4f, 0.6f))));
  ASSERT_TRUE(writeImage((d.path() / "clear.png").string(), solidImage(4, 4, glm::vec3(0.0f), 0.0f)));
  ASSERT_TRUE(writeImage((d.path() / "half.png").string(), solidImage(4, 4, glm::vec3(1.0f), 0.5f)));
  auto pal = loadPalette(d.write("p.palette", "background bg.png\nclear.png\nhalf.png\n"));
  ASSERT_TRUE(pal) << pal.error();
  ASSERT_TRUE(pal->backgroundImage);
  // A fully transparent texture averages to the background.
  EXPECT_NEAR(pal->entries[0].average.r, 0.2f, 1.0f / 255.0f);
  EXPECT_NEAR(pal->entries[0].average.b, 0.6f, 1.0f / 255.0f);
  // Half alpha white over the background: blended on encoded values, as the screen shows it.
  EXPECT_NEAR(pal->entries[1].average.r, 0.5f * 1.0f + 0.5f * 0.2f, 1.5f / 255.0f);
}

TEST(PaletteFile, ReadsGreyAlpha16BitAndFloatImages) {
  TempDir d;
  {  // 16-bit grey + alpha PNG, grey 0.25 fully opaque
    auto out = OIIO::ImageOutput::create((d.path() / "ga16.png").string());
    OIIO::ImageSpec spec(3, 3, 2, OIIO::TypeDesc::UINT16);
    std::vector<std::uint16_t> px(18);
    for (size_t i = 0; i < px.size(); i += 2) { px[i] = 16384; px[i + 1] = 65535; }
    ASSERT_TRUE(out->open((d.path() / "ga16.png").string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, px.data()));
    out->close();
  }
  {  // float RGB EXR with linear 0.2140 (= sRGB 0.5)
    auto out = OIIO::ImageOutput::create((d.path() / "f.exr").string());
    OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::FLOAT);
    std::vector<float> px(12, 0.21404f);
    ASSERT_TRUE(out->open((d.path() / "f.exr").string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    out->close();
  }
  ASSERT_TRUE(writeImage((d.path() / "t.tga").string(), solidImage(1, 1, glm::vec3(0.75f))));
  auto pal = loadPalette(d.write("p.palette", "ga16.png\nf.exr\nt.tga\n"));
  ASSERT_TRUE(pal) << pal.error();
  EXPECT_NEAR(pal->entries[0].average.g, 0.25f, 1.0f / 255.0f);
  EXPECT_NEAR(pal->entries[1].average.g, 0.5f, 1.5f / 255.0f);
  EXPECT_NEAR(pal->entries[2].average.b, 0.75f, 1.0f / 255.0f);
}

TEST(PaletteFile, FailuresNameTheFileLineAndReason) {
  TempDir d;
  auto missing = loadPalette((d.path() / "none.palette").string());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("none.palette"), std::string::npos);

  auto empty = loadPalette(d.write("empty.palette", "# only a comment\n"));
  ASSERT_FALSE(empty);
  EXPECT_NE(empty.error().find("no images"), std::string::npos);

  auto noImage = loadPalette(d.write("m.palette", "\nmissing.png\n"));
  ASSERT_FALSE(noImage);
  EXPECT_NE(noImage.error().find("m.palette line 2"), std::string::npos) << noImage.error();
  EXPECT_NE(noImage.error().find("missing.png"), std::string::npos);

  d.write("corrupt.png", "\x89PNG\r\n\x1a\n garbage that is not a png");
  auto corrupt = loadPalette(d.write("c.palette", "corrupt.png\n"));
  ASSERT_FALSE(corrupt);
  EXPECT_NE(corrupt.error().find("c.palette line 1"), std::string::npos) << corrupt.error();

  ASSERT_TRUE(writeImage((d.path() / "good.png").string(), solidImage(64, 64, glm::vec3(0.5f))));
  const auto bytes = std::filesystem::file_size(d.path() / "good.png");
  std::filesystem::copy_file(d.path() / "good.png", d.path() / "trunc.png");
  std::filesystem::resize_file(d.path() / "trunc.png", bytes / 2);
  auto trunc = loadPalette(d.write("t.palette", "good.png\ntrunc.png\n"));
  ASSERT_FALSE(trunc);
  EXPECT_NE(trunc.error().find("t.palette line 2"), std::string::npos) << trunc.error();

  d.write("u.xyz", "not an image");
  auto unsupported = loadPalette(d.write("u.palette", "u.xyz\n"));
  ASSERT_FALSE(unsupported);
  EXPECT_NE(unsupported.error().find("u.palette line 1"), std::string::npos);

  std::string many;
  for (int i = 0; i < 257; ++i) many += "good.png\n";
  auto tooMany = loadPalette(d.write("many.palette", many));
  ASSERT_FALSE(tooMany);
  EXPECT_NE(tooMany.error().find("line 257"), std::string::npos) << tooMany.error();
  EXPECT_NE(tooMany.error().find("256"), std::string::npos);

  auto badMode = loadPalette(d.write("b.palette", "match sideways\ngood.png\n"));
  ASSERT_FALSE(badMode);
  EXPECT_NE(badMode.error().find("b.palette line 1"), std::string::npos);
  auto badScale = loadPalette(d.write("s.palette", "range-scale nan\ngood.png\n"));
  ASSERT_FALSE(badScale);
  auto badColour = loadPalette(d.write("bc.palette", "background #12345\ngood.png\n"));
  ASSERT_FALSE(badColour);
}

// Two-dimensional palettes: rows after 'row' lines, the axis that picks them, and every way a
// file with rows can be wrong named by file, line and reason.
TEST(PaletteFile, RowsAndAnAxis) {
  TempDir d;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(writeImage((d.path() / ("g" + std::to_string(i) + ".png")).string(), solidImage(2, 2, glm::vec3(0.4f * float(i)))));
  auto depth = loadPalette(d.write("d.palette", "axis depth 2 4.5\nrow\ng0.png\ng1.png\ng2.png\nrow\ng1.png\ng2.png\ng2.png\n"));
  ASSERT_TRUE(depth) << depth.error();
  EXPECT_EQ(depth->axis.kind, PaletteAxisKind::Depth);
  EXPECT_EQ(depth->axis.rows, 2);
  EXPECT_EQ(depth->columns(), 3);
  EXPECT_FLOAT_EQ(depth->axis.from, 2.0f);
  EXPECT_FLOAT_EQ(depth->axis.to, 4.5f);
  EXPECT_FLOAT_EQ(depth->axis.rowPosition(1.0f), 0.0f);
  EXPECT_FLOAT_EQ(depth->axis.rowPosition(3.25f), 0.5f);
  EXPECT_FLOAT_EQ(depth->axis.rowPosition(9.0f), 1.0f);
  EXPECT_FLOAT_EQ(depth->axis.rowPosition(std::nanf("")), 0.0f);
  // The first row needs no 'row' line of its own; facing defaults to the whole range.
  auto facing = loadPalette(d.write("f.palette", "axis facing\ng0.png\ng1.png\nrow\ng1.png\ng2.png\nrow\ng2.png\ng2.png\n"));
  ASSERT_TRUE(facing) << facing.error();
  EXPECT_EQ(facing->axis.kind, PaletteAxisKind::Facing);
  EXPECT_EQ(facing->axis.rows, 3);
  EXPECT_EQ(facing->columns(), 2);
  EXPECT_FLOAT_EQ(facing->axis.rowPosition(0.75f), 1.5f);
  auto detail = loadPalette(d.write("x.palette", "axis detail 0.2 0.8\ng0.png\nrow\ng1.png\n"));
  ASSERT_TRUE(detail) << detail.error();
  EXPECT_EQ(detail->axis.kind, PaletteAxisKind::Detail);
  EXPECT_FLOAT_EQ(detail->axis.rowPosition(0.5f), 0.5f);
  EXPECT_FLOAT_EQ(paletteAxisValue(PaletteAxisKind::Detail, glm::vec3(0, 0, -3), glm::vec3(0, 0, 1), 0.7f), 0.7f);
  // The report gives both axes and each row's range.
  const std::string report = paletteReportJson(*depth);
  EXPECT_NE(report.find("\"columns\":3,\"rows\":2,\"axis\":{\"kind\":\"depth\",\"from\":2,\"to\":4.5"), std::string::npos) << report;
  EXPECT_NE(report.find("\"row_intensity_ranges\":[["), std::string::npos) << report;
  EXPECT_NE(report.find("\"row\":1,\"column\":2"), std::string::npos) << report;
  // A palette without an axis reports one row.
  auto plain = loadPalette(greyPalette(d, {0.0f, 1.0f}));
  ASSERT_TRUE(plain);
  EXPECT_NE(paletteReportJson(*plain).find("\"columns\":2,\"rows\":1,\"axis\":{\"kind\":\"none\"}"), std::string::npos);

  const auto fails = [&](const std::string& name, const std::string& text, const std::string& where, const std::string& why) {
    auto p = loadPalette(d.write(name, text));
    ASSERT_FALSE(p) << name;
    EXPECT_NE(p.error().find(name + " line " + where), std::string::npos) << p.error();
    EXPECT_NE(p.error().find(why), std::string::npos) << p.error();
  };
  fails("ragged.palette", "axis depth 1 2\ng0.png\ng1.png\nrow\ng1.png\n", "4", "row 2 has 1 image; every row needs as many as the first (2)");
  fails("order.palette", "axis depth 3 3\ng0.png\nrow\ng1.png\n", "1", "3 must be less than 3");
  fails("reverse.palette", "axis facing 0.8 0.2\ng0.png\nrow\ng1.png\n", "1", "must be less than");
  fails("unknown.palette", "axis time\ng0.png\nrow\ng1.png\n", "1", "unknown axis 'time'");
  fails("detailrange.palette", "axis detail 0 2\ng0.png\nrow\ng1.png\n", "1", "'axis detail': FROM and TO lie in [0, 1]");
  fails("nonumbers.palette", "axis depth\ng0.png\nrow\ng1.png\n", "1", "needs NEAR and FAR");
  fails("words.palette", "axis depth near far\ng0.png\nrow\ng1.png\n", "1", "needs two numbers");
  fails("facingrange.palette", "axis facing 0.5 2\ng0.png\nrow\ng1.png\n", "1", "lie in [0, 1]");
  fails("noaxis.palette", "g0.png\nrow\ng1.png\n", "2", "'row' lines need an 'axis' line");
  fails("onerow.palette", "axis depth 1 2\ng0.png\ng1.png\n", "1", "at least two rows");
  fails("empty.palette", "axis depth 1 2\ng0.png\nrow\nrow\ng1.png\n", "4", "an empty row");
  fails("twice.palette", "axis depth 1 2\naxis facing\ng0.png\nrow\ng1.png\n", "2", "a second 'axis' line");
}

TEST(PaletteFile, OneEntryAnd256EntriesAndTinyImages) {
  TempDir d;
  ASSERT_TRUE(writeImage((d.path() / "px.png").string(), solidImage(1, 1, glm::vec3(0.3f))));
  auto one = loadPalette(d.write("one.palette", "px.png\n"));
  ASSERT_TRUE(one) << one.error();
  EXPECT_EQ(one->entries.size(), 1u);
  std::string text;
  for (int i = 0; i < 256; ++i) text += "px.png\n";
  auto full = loadPalette(d.write("full.palette", text));
  ASSERT_TRUE(full) << full.error();
  EXPECT_EQ(full->entries.size(), 256u);
}

TEST(PaletteFile, LargeImageLoads) {
  TempDir d;
  // 8192 wide, 16M texels (a quarter of the square: the sanitizer tier took 10 s over it).
  ASSERT_TRUE(writeImage((d.path() / "big.png").string(), solidImage(8192, 2048, glm::vec3(0.5f))));
  auto pal = loadPalette(d.write("big.palette", "big.png\n"));
  ASSERT_TRUE(pal) << pal.error();
  EXPECT_EQ(pal->entries[0].image.width, 8192);
  EXPECT_NEAR(pal->entries[0].average.r, 0.5f, 1.0f / 255.0f);
}

TEST(PaletteReport, JsonDescribesRangeGapAndMonotonicity) {
  TempDir d;
  auto pal = loadPalette(greyPalette(d, {1.0f, 0.6f, 0.0f}, "match intensity\n"));
  ASSERT_TRUE(pal);
  const std::string j = paletteReportJson(*pal);
  EXPECT_NE(j.find("\"monotonic\":true"), std::string::npos) << j;
  EXPECT_NE(j.find("\"intensity_range\":[0,3]"), std::string::npos) << j;
  EXPECT_NE(j.find("\"largest_gap\":1.8"), std::string::npos) << j;
  const PaletteAnalysis a = analysePalette(*pal);
  EXPECT_FALSE(a.suitabilityWarnings(MatchMode::Intensity).empty());  // uneven gaps
}

TEST(PaletteReport, NarrowPaletteWarnsUnderIntensity) {
  TempDir d;
  auto pal = loadPalette(greyPalette(d, {0.5f, 0.52f, 0.54f}));
  ASSERT_TRUE(pal);
  EXPECT_FALSE(analysePalette(*pal).suitabilityWarnings(MatchMode::Intensity).empty());
}

TEST(PaletteReport, ShippedPalettesLoadAndSuitTheirModes) {
  for (const char* name : {"crosshatch", "stipple", "cel", "gooch", "solarize", "wood", "depth-hatch", "cel-rim"}) {
    const std::string path = std::string(NPR_SOURCE_DIR) + "/palettes/" + name + "/" + name + ".palette";
    auto pal = loadPalette(path);
    ASSERT_TRUE(pal) << pal.error();
    ASSERT_TRUE(pal->defaultMatch) << name;
    const PaletteAnalysis a = analysePalette(*pal);
    EXPECT_TRUE(a.suitabilityWarnings(*pal->defaultMatch).empty()) << name;
    if (*pal->defaultMatch == MatchMode::Intensity) {
      EXPECT_TRUE(a.monotonic) << name;
    }
  }
}

TEST(PaletteReport, HatchingLevelsAreEvenlySpacedAndNest) {
  auto pal = loadPalette(std::string(NPR_SOURCE_DIR) + "/palettes/crosshatch/crosshatch.palette");
  ASSERT_TRUE(pal);
  ASSERT_EQ(pal->entries.size(), 10u);
  const float step = (pal->entries[0].intensity - pal->entries[9].intensity) / 9.0f;
  for (size_t i = 1; i < 10; ++i) {
    EXPECT_NEAR(pal->entries[i - 1].intensity - pal->entries[i].intensity, step, 0.03f) << i;
    // Every inked texel of a lighter level is inked in the darker one.
    const auto& a = pal->entries[i - 1].image.pixels;
    const auto& b = pal->entries[i].image.pixels;
    for (size_t p = 3; p < a.size(); p += 4) ASSERT_LE(a[p], b[p]) << "level " << i << " texel " << p / 4;
  }
}

// ---- Matching ---------------------------------------------------------------------------

TEST(Matcher, IntensityUsesThreeTimesTheBrightestChannel) {
  // Levels 0, 1.5, 3 (sums of grey averages).
  auto m = PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Intensity, 1.0f);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->match({0.0f, 0.0f, 0.0f}), 0);
  EXPECT_EQ(m->match({0.5f, 0.0f, 0.0f}), 1);  // 3 x 0.5 = 1.5, although the sum is 0.5
  EXPECT_EQ(m->match({0.9f, 0.0f, 0.9f}), 2);  // 2.7
  EXPECT_EQ(m->match({0.2f, 0.2f, 0.2f}), 0);  // 0.6 is nearer 0 than 1.5
  EXPECT_EQ(m->match({0.3f, 0.1f, 0.1f}), 1);  // 0.9
}

TEST(Matcher, ColoursPickTheNearestAverage) {
  const std::vector<glm::vec3> avg = {{1, 0, 0}, {0, 0, 1}, {0.5f, 0.5f, 0.5f}};
  auto m = PaletteMatcher::create(avg, MatchMode::Colors, 1.0f);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->match({0.9f, 0.1f, 0.1f}), 0);
  EXPECT_EQ(m->match({0.1f, 0.2f, 0.8f}), 1);
  EXPECT_EQ(m->match({0.6f, 0.5f, 0.4f}), 2);
  // Exhaustive check of the candidate-list search against a linear scan.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec3> many;
  for (int i = 0; i < 200; ++i) many.push_back({u(rng), u(rng), u(rng)});
  auto big = PaletteMatcher::create(many, MatchMode::Colors, 1.0f);
  ASSERT_TRUE(big);
  for (int q = 0; q < 20000; ++q) {
    const glm::vec3 c(u(rng), u(rng), u(rng));
    int best = 0;
    for (int t = 1; t < 200; ++t)
      if (glm::dot(many[size_t(t)] - c, many[size_t(t)] - c) < glm::dot(many[size_t(best)] - c, many[size_t(best)] - c)) best = t;
    ASSERT_EQ(big->match(c), best) << q;
  }
}

TEST(Matcher, OrderIndexesThePaletteByBrightness) {
  // Averages do not matter in order mode.
  auto m = PaletteMatcher::create(greys({0.3f, 0.3f, 0.3f, 0.3f}), MatchMode::Order, 1.0f);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->match({0, 0, 0}), 0);
  EXPECT_EQ(m->match({0.2f, 0.2f, 0.2f}), 0);  // sum 0.6 -> floor(0.6 x 4 / 3) = 0
  EXPECT_EQ(m->match({0.3f, 0.3f, 0.3f}), 1);  // 0.9 -> 1
  EXPECT_EQ(m->match({0.6f, 0.6f, 0.6f}), 2);  // 1.8 -> 2
  EXPECT_EQ(m->match({1, 1, 1}), 3);
}

TEST(Matcher, TiesGoToTheLowestIndex) {
  // Exactly between levels 0 and 1.5 (q = 0.75), and duplicate levels.
  auto m = PaletteMatcher::create(greys({0.0f, 0.5f, 0.5f, 0.0f}), MatchMode::Intensity, 1.0f);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->match({0.25f, 0.0f, 0.0f}), 0);
  EXPECT_EQ(m->match({0.5f, 0.5f, 0.5f}), 1);  // entries 1 and 2 are equal: 1
  EXPECT_EQ(m->match({0, 0, 0}), 0);           // entries 0 and 3 are equal: 0
  auto c = PaletteMatcher::create({{0, 0, 0}, {1, 1, 1}, {1, 1, 1}}, MatchMode::Colors, 1.0f);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->match({0.5f, 0.5f, 0.5f}), 0);  // equidistant from 0 and 1
  EXPECT_EQ(c->match({0.9f, 0.9f, 0.9f}), 1);
}

TEST(Matcher, RangeScaleSpreadsAboutTheMidpoint) {
  // Levels 1.2, 1.5, 1.8 (midpoint 1.5). With S = 5 they become 0, 1.5, 3.
  auto narrow = PaletteMatcher::create(greys({0.4f, 0.5f, 0.6f}), MatchMode::Intensity, 1.0f);
  auto spread = PaletteMatcher::create(greys({0.4f, 0.5f, 0.6f}), MatchMode::Intensity, 5.0f);
  ASSERT_TRUE(narrow && spread);
  EXPECT_NEAR(spread->levels()[0], 0.0f, 1e-5f);
  EXPECT_NEAR(spread->levels()[2], 3.0f, 1e-5f);
  const glm::vec3 dim(0.35f);  // q = 1.05
  EXPECT_EQ(narrow->match(dim), 0);
  EXPECT_EQ(spread->match(dim), 1);  // 1.05 is nearer 1.5 than 0 after spreading
  EXPECT_EQ(spread->match(glm::vec3(0.2f)), 0);
  // Colours scale about the box midpoint too.
  auto cs = PaletteMatcher::create({{0.4f, 0.4f, 0.4f}, {0.6f, 0.6f, 0.6f}}, MatchMode::Colors, 5.0f);
  ASSERT_TRUE(cs);
  EXPECT_NEAR(cs->scaledAverages()[0].r, 0.0f, 1e-5f);
  EXPECT_NEAR(cs->scaledAverages()[1].r, 1.0f, 1e-5f);
}

TEST(Matcher, RangeScaleExtremes) {
  const auto avg = greys({0.1f, 0.4f, 0.9f});
  for (float bad : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity()}) {
    auto m = PaletteMatcher::create(avg, MatchMode::Intensity, bad);
    ASSERT_FALSE(m) << bad;
    EXPECT_NE(m.error().find("IntensityRangeScale"), std::string::npos);
  }
  for (float ok : {1e-30f, 1e-6f, 1e6f, 3e38f})
    for (MatchMode mode : {MatchMode::Colors, MatchMode::Intensity, MatchMode::Order}) {
      auto m = PaletteMatcher::create(avg, mode, ok);
      ASSERT_TRUE(m) << ok;
      for (float g : {0.0f, 0.3f, 0.5f, 1.0f}) {
        const int i = m->match(glm::vec3(g));
        EXPECT_TRUE(i >= 0 && i < 3);
        const PaletteBlend b = m->matchSmooth(glm::vec3(g));
        EXPECT_TRUE(b.a >= 0 && b.a < 3 && b.b >= 0 && b.b < 3 && b.t >= 0.0f && b.t <= 1.0f && std::isfinite(b.t));
      }
    }
}

TEST(Matcher, ZeroRangePaletteHasNoDivisionByZero) {
  auto m = PaletteMatcher::create(greys({0.5f, 0.5f, 0.5f}), MatchMode::Intensity, 3.0f);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->match(glm::vec3(0.0f)), 0);
  EXPECT_EQ(m->match(glm::vec3(1.0f)), 0);
  EXPECT_TRUE(std::isfinite(m->tonePosition(glm::vec3(0.7f))));
}

TEST(Matcher, PropertyRandomColoursAlwaysGiveAValidIndex) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> u(-2.0f, 3.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (int size : {1, 2, 10, 256}) {
    std::vector<glm::vec3> avg;
    std::uniform_real_distribution<float> c(0.0f, 1.0f);
    for (int i = 0; i < size; ++i) avg.push_back({c(rng), c(rng), c(rng)});
    for (MatchMode mode : {MatchMode::Colors, MatchMode::Intensity, MatchMode::Order})
      for (float scale : {0.01f, 1.0f, 100.0f}) {
        auto m = PaletteMatcher::create(avg, mode, scale);
        ASSERT_TRUE(m);
        for (int q = 0; q < 3000; ++q) {
          glm::vec3 col(u(rng), u(rng), u(rng));
          if (q % 7 == 0) col[q % 3] = (q % 2) ? nan : ((q % 3) ? inf : -inf);
          const int i = m->match(col);
          ASSERT_TRUE(i >= 0 && i < size) << i;
          const PaletteBlend b = m->matchSmooth(col);
          ASSERT_TRUE(b.a >= 0 && b.a < size && b.b >= 0 && b.b < size && b.t >= 0.0f && b.t <= 1.0f);
        }
      }
  }
}

TEST(Matcher, LookupTablesAgreeWithTheExactMatch) {
  auto m = PaletteMatcher::create(greys({0.05f, 0.3f, 0.55f, 0.8f}), MatchMode::Intensity, 1.0f);
  ASSERT_TRUE(m);
  const auto lut = m->buildLutIndex1D();
  const int L = PaletteMatcher::kLut1DSize;
  for (int i = 0; i < L; ++i) EXPECT_EQ(lut[size_t(i)], m->match(glm::vec3(float(i) / float(L - 1))));
  const auto blend = m->buildLutBlend1D();
  const PaletteBlend b = m->matchSmooth(glm::vec3(0.5f));
  const size_t bin = size_t(std::lround(0.5f * float(L - 1)));
  EXPECT_EQ(int(blend[bin * 4]), b.a);
  EXPECT_EQ(int(blend[bin * 4 + 1]), b.b);
}

TEST(Matcher, SmoothBlendsTheBracketingEntries) {
  auto m = PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Intensity, 1.0f);
  ASSERT_TRUE(m);
  const PaletteBlend b = m->matchSmooth(glm::vec3(0.25f));  // q = 0.75: halfway 0 .. 1.5
  EXPECT_EQ(b.a, 0);
  EXPECT_EQ(b.b, 1);
  EXPECT_NEAR(b.t, 0.5f, 1e-5f);
  auto c = PaletteMatcher::create({{0, 0, 0}, {1, 0, 0}}, MatchMode::Colors, 1.0f);
  ASSERT_TRUE(c);
  const PaletteBlend cb = c->matchSmooth({0.25f, 0, 0});  // distances 0.25 and 0.75
  EXPECT_EQ(cb.a, 0);
  EXPECT_EQ(cb.b, 1);
  EXPECT_NEAR(cb.t, 0.25f, 1e-5f);
}

TEST(Matcher, CelBandsMoveTheDecisionsAndBlendOnlyAtTheEdges) {
  // Levels 0, 1.5, 3; nearest would switch at 0.75 and 2.25. Thresholds 0.5 and 2.8 instead.
  auto m = PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Intensity, 1.0f, {0.5f, 2.8f});
  ASSERT_TRUE(m) << m.error();
  auto at = [](float q) { return glm::vec3(q / 3.0f); };  // a grey whose query is q
  EXPECT_EQ(m->match(at(0.4f)), 0);
  EXPECT_EQ(m->match(at(0.6f)), 1);
  EXPECT_EQ(m->match(at(2.7f)), 1);
  EXPECT_EQ(m->match(at(2.9f)), 2);
  // Hard bands: no blending away from a threshold, a ramp across it.
  EXPECT_EQ(m->matchSmooth(at(1.5f)).t, 0.0f);
  const PaletteBlend edge = m->matchSmooth(at(0.5f));
  EXPECT_EQ(edge.a, 0);
  EXPECT_EQ(edge.b, 1);
  EXPECT_NEAR(edge.t, 0.5f, 1e-3f);
  EXPECT_NEAR(m->matchSmooth(at(0.5f + PaletteMatcher::kBandEdge * 0.5f)).t, 0.75f, 1e-2f);
  // Refused: wrong count, not ascending, not finite, colours mode.
  EXPECT_FALSE(PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Intensity, 1.0f, {0.5f}));
  EXPECT_FALSE(PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Intensity, 1.0f, {2.0f, 1.0f}));
  EXPECT_FALSE(PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Intensity, 1.0f, {0.5f, NAN}));
  EXPECT_FALSE(PaletteMatcher::create(greys({0.0f, 0.5f, 1.0f}), MatchMode::Colors, 1.0f, {0.5f, 2.8f}));
}

TEST(Colour, SrgbRoundTrips) {
  for (float v : {0.0f, 0.001f, 0.04f, 0.2f, 0.5f, 0.99f, 1.0f}) EXPECT_NEAR(linearToSrgb(srgbToLinear(v)), v, 1e-5f);
  EXPECT_EQ(linearToSrgb(std::numeric_limits<float>::quiet_NaN()), 0.0f);
}

}  // namespace
}  // namespace npr
