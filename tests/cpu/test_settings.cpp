// CPU tier: the settings table (app/settings/). Every row is well formed; every saved row
// round-trips through a style file's text with random valid values; every row is an option of
// the command line that sets it; values out of range are refused with the row's own form.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "app/cli.h"
#include "app/settings/setting.h"
#include "app/settings/style_file.h"
#include "renderer/core/image_io.h"
#include "support/test_util.h"

namespace npr {
namespace {

// A random value the row accepts, as text.
std::string randomValue(const Setting& row, std::mt19937& rng) {
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  switch (row.type) {
    case SettingType::Bool: return pick(2) ? "on" : "off";
    case SettingType::Int: return std::to_string(std::uniform_int_distribution<int>(int(row.min), int(row.max))(rng));
    case SettingType::Float: {
      // Log-uniform over wide ranges, so small values are drawn too; the ends now and then.
      const std::size_t end = pick(10);
      if (end == 0) return formatFloat(float(row.min));
      if (end == 1) return formatFloat(float(row.max));
      const double lo = std::max(row.min, 1e-3);
      const double v = row.logarithmic && row.min > 0 ? std::exp(uniform(std::log(lo), std::log(row.max))) : uniform(row.min, row.max);
      return formatFloat(std::clamp(float(v), float(row.min), float(row.max)));
    }
    case SettingType::Choice: return row.choices[pick(row.choices.size())];
    case SettingType::Kinds: {
      std::string out;
      for (const std::string& c : row.choices)
        if (pick(2)) out += (out.empty() ? "" : ",") + c;
      return out.empty() ? "none" : out;
    }
    case SettingType::Colour: return formatFloat(float(uniform(0, 1))) + "," + formatFloat(float(uniform(0, 1))) + "," + formatFloat(float(uniform(0, 1)));
    case SettingType::Vector: return formatFloat(float(uniform(-9, 9))) + "," + formatFloat(float(uniform(-9, 9))) + "," + formatFloat(float(uniform(-9, 9)));
    case SettingType::File: {
      const char* shipped[] = {"palettes/crosshatch/crosshatch.palette", "palettes/stipple/stipple.palette", "palettes/gooch/gooch.palette"};
      if (row.key != "palette" && pick(3) == 0) return "none";
      return std::filesystem::absolute(std::filesystem::path(NPR_SOURCE_DIR) / shipped[pick(3)]).lexically_normal().string();
    }
    case SettingType::Text:
      if (row.key == "orient") {
        const std::size_t k = pick(4);
        return k < 3 ? row.choices[k] : formatFloat(float(uniform(0, 179)));
      }
      if (row.key == "bands") {
        std::string out;
        float t = float(uniform(0, 0.5));
        for (std::size_t i = 0, n = pick(5); i < n; ++i, t += float(uniform(0.01, 0.7))) out += (out.empty() ? "" : ",") + formatFloat(t);
        return out.empty() ? "none" : out;
      }
      if (row.key == "stroke-size") return formatFloat(float(uniform(1, 256))) + "x" + formatFloat(float(uniform(1, 256)));
      if (row.key == "line-set") {  // 0 to 3 sets, each with some of the keys, one per line
        const char* kinds[] = {"silhouette", "crease", "boundary", "material", "intersection"};
        const char* visibility[] = {"visible", "hidden", "both"};
        std::string out;
        for (std::size_t i = 0, n = pick(4); i < n; ++i) {
          std::string set = kinds[pick(5)];
          if (pick(2)) set += std::string(",") + kinds[pick(5)];
          if (pick(2)) set += std::string(" visibility=") + visibility[pick(3)];
          if (pick(2)) set += " width=" + formatFloat(float(uniform(0.1, 64)));
          if (pick(2)) set += pick(4) ? " colour=" + formatFloat(float(uniform(0, 1))) + "," + formatFloat(float(uniform(0, 1))) + ",0" : std::string(" colour=tone");
          if (pick(2)) set += " dash=" + formatFloat(float(uniform(0.5, 20))) + "," + formatFloat(float(uniform(0.5, 20)));
          if (pick(2)) set += " taper=" + formatFloat(float(uniform(0, 100)));
          if (pick(3) == 0) set += std::string(" materials=") + (pick(2) ? "Paint*" : "Glass,Chrome");
          if (pick(3) == 0) set += " texture=brush";
          if (pick(3) == 0) set += " curvature=" + formatFloat(float(uniform(-4, 4)));
          if (pick(2)) set += std::string(" falloff=") + (pick(2) ? "on" : "off");
          if (pick(2)) set += std::string(" sketchy=") + (pick(2) ? "on" : "off");
          out += (out.empty() ? "" : "\n") + set;
        }
        return out.empty() ? "none" : out;
      }
      return row.example;
  }
  return row.example;
}

TEST(SettingsTable, EveryRowIsWellFormedAndItsDefaultParsesBack) {
  std::set<std::string> keys, sections;
  for (const SettingSection& s : settingSections()) sections.insert(s.name);
  const Look defaults;
  for (const Setting& row : settingsTable()) {
    EXPECT_TRUE(keys.insert(row.key).second) << "two rows named " << row.key;
    EXPECT_TRUE(sections.count(row.section)) << row.key << ": no section " << row.section;
    EXPECT_FALSE(row.help.empty()) << row.key;
    EXPECT_FALSE(row.label.empty()) << row.key;
    ASSERT_TRUE(row.format && row.parse) << row.key;
    if (row.type == SettingType::Bool) {
      EXPECT_TRUE(row.boolRef) << row.key;
    }
    if (row.type == SettingType::Int) {
      EXPECT_TRUE(row.intRef && row.min <= row.max) << row.key;
    }
    if (row.type == SettingType::Float) {
      EXPECT_TRUE(row.floatRef && row.min <= row.max) << row.key;
    }
    if (row.type == SettingType::Choice || row.type == SettingType::Kinds) {
      EXPECT_FALSE(row.choices.empty()) << row.key;
    }
    if (row.key == "palette") continue;  // no default palette file in a bare look
    Look l = defaults;
    const Status back = row.parse(row.format(defaults), l);
    EXPECT_TRUE(back) << row.key << " '" << row.format(defaults) << "': " << back.error();
    EXPECT_EQ(row.format(l), row.format(defaults)) << row.key;
    EXPECT_EQ(findSetting(row.key), &row);
  }
  EXPECT_EQ(findSetting("frobnicate"), nullptr);
}

// The whole look, drawn at random row by row, written as a style and read back, is the same
// look: no row is lost, truncated or read into another.
TEST(SettingsTable, RandomLooksRoundTripThroughStyleText) {
  std::mt19937 rng(20261126);
  for (int trial = 0; trial < 200; ++trial) {
    Look look;
    for (const Setting& row : settingsTable()) {
      const std::string v = randomValue(row, rng);
      ASSERT_TRUE(row.parse(v, look)) << row.key << " '" << v << "'";
      // Numbers straight into the fields, full float precision: what a slider leaves.
      std::uniform_real_distribution<float> unit(0.0f, 1.0f);
      if (row.floatRef) *row.floatRef(look) = std::clamp(float(row.min + (row.max - row.min) * unit(rng)), float(row.min), float(row.max));
      if (row.vectorRef) *row.vectorRef(look) = glm::vec3(unit(rng), unit(rng), unit(rng));
    }
    const std::string text = lookText(look);
    Look back;
    std::istringstream in(text);
    std::string line;
    std::set<std::string> seen;
    std::map<const Setting*, std::string> lists;  // a repeated row's lines make one value
    while (std::getline(in, line)) {
      const std::string key = line.substr(0, line.find(' ')), value = line.substr(line.find(' ') + 1);
      const Setting* row = findSetting(key);
      ASSERT_NE(row, nullptr) << line;
      // Palettes are saved by a shipped name where they have one, read back through the resolver.
      const std::string read = row->type == SettingType::File ? findPalette(value, ".").value_or(value) : value;
      if (row->repeated) lists[row] += (lists[row].empty() ? "" : "\n") + read;
      else ASSERT_TRUE(row->parse(read, back)) << line;
      seen.insert(key);
    }
    for (const auto& [row, value] : lists) ASSERT_TRUE(row->parse(value, back)) << row->key << " " << value;
    for (const Setting& row : settingsTable()) {
      if (!row.saved) continue;
      EXPECT_TRUE(seen.count(row.key)) << "not saved: " << row.key;
      EXPECT_EQ(row.format(back), row.format(look)) << row.key << " (trial " << trial << ")";
    }
    // The fields themselves, not only their text.
    EXPECT_EQ(back.render.orient, look.render.orient);
    EXPECT_EQ(back.render.patternScale, look.render.patternScale);
    EXPECT_EQ(back.render.strokes.density, look.render.strokes.density);
    EXPECT_EQ(back.render.lines.silhouetteColour, look.render.lines.silhouetteColour);
    EXPECT_EQ(back.light, look.light);
    EXPECT_EQ(back.render.bands, look.render.bands);
  }
}

// Line sets: one per line of a style file or per --line-set; each item says what is wrong with
// which set, and a bad list changes nothing.
TEST(SettingsTable, LineSetsAreAListOneItemPerLine) {
  std::vector<LineSet> sets;
  std::string why;
  ASSERT_TRUE(parseLineSets("silhouette width=3; crease,intersection visibility=both colour=0,0,1 dash=4,2", sets, &why)) << why;
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_TRUE(sets[0].has(0) && !sets[0].has(1));
  EXPECT_EQ(sets[0].width, 3.0f);
  EXPECT_TRUE(sets[1].has(1) && sets[1].has(4) && !sets[1].has(0));
  EXPECT_EQ(sets[1].visibility, LineSet::Visibility::Both);
  EXPECT_EQ(sets[1].dash, glm::vec2(4.0f, 2.0f));
  EXPECT_EQ(formatLineSets(sets), "silhouette width=3\ncrease,intersection visibility=both width=2 colour=0,0,1 dash=4,2");
  for (const auto& [bad, reason] : std::vector<std::pair<std::string, std::string>>{
           {"silhouette width=3\nhatching", "set 2: unknown line kind"},
           {"crease width=0", "set 1: width must be"},
           {"crease colour=2,0,0", "set 1: colour must be"},
           {"crease dash=4", "set 1: dash must be"},
           {"crease visibility=sometimes", "set 1: visibility must be"},
           {"crease taper", "set 1: expected KEY=VALUE"},
           {"crease taper=-1", "set 1: taper must be"},
           {"crease taper=nan", "set 1: taper must be"},
           {"crease materials=", "set 1: materials must name at least one material"},
           {"crease texture=", "set 1: texture must be brush or an image file"},
           {"crease curvature=5", "set 1: curvature must be"},
           {"crease visibility=hidden occlusion=1.5", "set 1: occlusion must be 0..3"},
           {"crease visibility=hidden occlusion=4", "set 1: occlusion must be 0..3"},
           {"crease visibility=hidden occlusion=nan", "set 1: occlusion must be 0..3"},
           {"crease shade=on", "set 1: unknown key 'shade'"},
           {";", "no set"}}) {
    EXPECT_FALSE(parseLineSets(bad, sets, &why)) << bad;
    EXPECT_NE(why.find(reason), std::string::npos) << bad << ": " << why;
    EXPECT_EQ(sets.size(), 2u) << "a bad list changed the sets";
  }
  std::vector<LineSet> limited;
  ASSERT_TRUE(parseLineSets("silhouette visibility=hidden occlusion=2", limited, &why)) << why;
  EXPECT_EQ(limited[0].occlusion, 2);
  EXPECT_EQ(formatLineSets(limited), "silhouette visibility=hidden width=2 occlusion=2");
  ASSERT_TRUE(parseLineSets("none", sets, &why));
  EXPECT_TRUE(sets.empty());
  // Objects by name, with wildcards; a set naming objects leaves the scene's intersections alone.
  ASSERT_TRUE(parseLineSets("crease objects=Cylinder*,arm_?", sets, &why)) << why;
  EXPECT_EQ(formatLineSets(sets), "crease width=2 objects=Cylinder*,arm_?");
  for (const auto& [name, applies] : std::vector<std::pair<std::string, bool>>{
           {"Cylinder", true}, {"Cylinder.001", true}, {"arm_L", true}, {"arm_", false}, {"arm_LL", false}, {"cylinder", false}})
    EXPECT_EQ(sets[0].appliesTo(&name), applies) << name;
  EXPECT_FALSE(sets[0].appliesTo(nullptr));
  LineSettings ls;
  ls.creases = ls.silhouettes = true;
  ls.sets = sets;
  const std::string cylinder = "Cylinder", body = "body";
  EXPECT_EQ(ls.baseKinds(&cylinder), 1u);   // its creases are the set's
  EXPECT_EQ(ls.baseKinds(&body), 3u);       // elsewhere the base style keeps them
  EXPECT_FALSE(parseLineSets("crease objects=", sets, &why));
  EXPECT_NE(why.find("objects must name"), std::string::npos) << why;
  // Matching backtracks to the last star only: a pattern of many stars against a long name that
  // fails at its end answers at once (a recursive match would take years).
  const std::string longName(4000, 'a');
  ASSERT_TRUE(parseLineSets("crease objects=*a*a*a*a*a*a*a*a*a*a*a*a*b", sets, &why)) << why;
  EXPECT_FALSE(sets[0].appliesTo(&longName));
  // A style file's line-set lines make the list, in order; the kinds `lines` names that no set
  // takes keep the base style.
  test::TempDir d;
  Result<Style> st = loadStyle(d.write("sets.style", "lines silhouette,crease,boundary\nline-set crease width=1\nline-set silhouette visibility=hidden\n"));
  ASSERT_TRUE(st) << st.error();
  Look look;
  for (const auto& v : st->values) ASSERT_TRUE(v.row->parse(v.value, look)) << v.row->key;
  ASSERT_EQ(look.render.lines.sets.size(), 2u);
  EXPECT_EQ(look.render.lines.baseKinds(), 1u << 2);  // boundaries: no set takes them
  EXPECT_EQ(look.render.lines.drawnKinds(), 7u);
  // A texture file: checked when given (a missing one is an error naming the set), found next
  // to the style that names it, and kept as an absolute path so a saved style works anywhere.
  const Setting* row = findSetting("line-set");
  const Status missing = row->parse("silhouette texture=no-such-brush.png", look);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("set 1: texture: "), std::string::npos) << missing.error();
  EXPECT_NE(missing.error().find("no-such-brush.png"), std::string::npos) << missing.error();
  ASSERT_TRUE(row->parse("silhouette texture=brush", look));
  EXPECT_EQ(look.render.lines.sets.at(0).texture, "brush");
  const std::string ink = d.write("ink.png", "");
  ImageRGBA8 img{4, 2, std::vector<std::uint8_t>(32, 200)};
  ASSERT_TRUE(writeImage(ink, img));
  st = loadStyle(d.write("inked.style", "line-set silhouette width=4 texture=ink.png\n"));
  ASSERT_TRUE(st) << st.error();
  ASSERT_EQ(st->values.size(), 1u);
  ASSERT_TRUE(st->values[0].row->parse(st->values[0].value, look)) << st->values[0].value;
  EXPECT_EQ(std::filesystem::path(look.render.lines.sets.at(0).texture), std::filesystem::absolute(ink).lexically_normal());
}

// The drift the table ended: the orientation does not reset its bins; the bins may go to 64.
TEST(SettingsTable, OrientKeepsItsBinsAndBinsTakeTheFullRange) {
  Look look;
  ASSERT_TRUE(findSetting("orient-bins")->parse("64", look));
  ASSERT_TRUE(findSetting("orient")->parse("curvature", look));
  EXPECT_EQ(look.render.orient.bins, 64);
  EXPECT_EQ(look.render.orient.source, OrientSource::Curvature);
  EXPECT_FALSE(findSetting("orient-bins")->parse("65", look));
  EXPECT_EQ(findSetting("orient-bins")->max, OrientSettings::kMaxBins);
}

// Values a row refuses, and the message says what it takes.
TEST(SettingsTable, BadValuesAreRefusedWithTheRowsForm) {
  Look look;
  const Look before = look;
  for (const auto& [key, value, says] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"pattern-scale", "100", "0.125..16"},
           {"pattern-scale", "nan", "0.125..16"},
           {"range-scale", "0", "0.01..100"},
           {"shadows", "maybe", "on or off"},
           {"occlusion-method", "raytraced", "baked or screen"},
           {"light", "1,2", "X,Y,Z"},
           {"light", "1,nan,2", "X,Y,Z"},
           {"silhouette-colour", "2,0,0", "0..1"},
           {"lines", "silhouette,glow", "silhouette"},
           {"bands", "1,0.5", "ascending"},
           {"stroke-size", "0x4", "LxW"},
           {"orient-bins", "2.5", "integer"},
           {"stroke-budget", "-1", "0..4000000"}}) {
    const Status s = findSetting(key)->parse(value, look);
    ASSERT_FALSE(s) << key << " " << value;
    EXPECT_NE(s.error().find(says), std::string::npos) << key << ": " << s.error();
  }
  EXPECT_EQ(lookText(look), lookText(before));
}

// Every row is an option of the command line (or says it is not), and the option sets it.
TEST(SettingsTable, EveryRowIsACommandLineOptionThatSetsIt) {
  std::mt19937 rng(7);
  for (const Setting& row : settingsTable()) {
    if (!row.cli) continue;
    const std::string value = randomValue(row, rng);
    std::vector<std::string> args{"npr-viewer", "--headless"};
    if (row.type == SettingType::Bool && !row.cliTakesValue) args.push_back(value == "on" ? "--" + row.key : "--no-" + row.key);
    else if (row.repeated && value != "none") {  // the option once per item
      std::istringstream items(value);
      for (std::string item; std::getline(items, item);) args.insert(args.end(), {"--" + row.key, item});
    } else args.insert(args.end(), {"--" + row.key, value});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    const ParseOutcome parsed = parseCommandLine(int(argv.size()), argv.data());
    ASSERT_TRUE(parsed.options) << row.key << " " << value;
    const SettingValue* given = parsed.options->setting(row.key);
    ASSERT_NE(given, nullptr) << row.key;
    Look expected, got = parsed.options->look();
    ASSERT_TRUE(row.parse(value, expected));
    EXPECT_EQ(row.format(got), row.format(expected)) << row.key;
  }
}

// Control bytes (C0, DEL, C1) or bytes that are not UTF-8: what a terminal must never get.
bool hasRawBytes(const std::string& message) {
  for (std::size_t i = 0; i < message.size();) {
    const unsigned char c = static_cast<unsigned char>(message[i]);
    if (c < 0x20 || c == 0x7f) return true;
    if (c < 0x80) { ++i; continue; }
    const std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
    if (n == 0 || c > 0xF4 || i + n > message.size()) return true;
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(message[i + k]) & 0xC0) != 0x80) return true;
    if (c == 0xC2 && static_cast<unsigned char>(message[i + 1]) < 0xA0) return true;  // C1 controls
    i += n;
  }
  return false;
}

// A style file's bytes never reach the terminal raw: escape sequences and binary come back as
// \xNN, long values cut; the line is still named.
TEST(StyleFiles, MessagesShowTheFilesBytesEscaped) {
  test::TempDir d;
  const std::string esc = d.write("esc.style", "name x\npath \x1b[31mred\x1b[0m\n");
  Result<Style> st = loadStyle(esc);
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().find("esc.style line 2"), std::string::npos) << st.error();
  EXPECT_NE(st.error().find("\\x1b[31m"), std::string::npos) << st.error();
  EXPECT_FALSE(hasRawBytes(st.error()));
  Result<Style> key = loadStyle(d.write("key.style", std::string("\xff\xfe\x07" "bell 1\n")));
  ASSERT_FALSE(key);
  EXPECT_FALSE(hasRawBytes(key.error())) << key.error();
  Result<Style> longValue = loadStyle(d.write("long.style", "pattern " + std::string(5000, 'z') + "\n"));
  ASSERT_FALSE(longValue);
  EXPECT_LT(longValue.error().size(), 400u);
}

// Random style files (keys of the table with random values, random bytes, long lines) are read
// or refused with the file and line named: never a crash, never raw bytes in the message.
TEST(StyleFiles, RandomFilesAreReadOrRefusedWithTheLineNamed) {
  std::mt19937 rng(42);
  test::TempDir d;
  const auto& table = settingsTable();
  std::uniform_int_distribution<int> byte(0, 255);
  int refused = 0, read = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string text;
    for (int line = 0, n = int(rng() % 6) + 1; line < n; ++line) {
      const Setting& row = table[rng() % table.size()];
      switch (rng() % 4) {
        case 0: text += row.key + " " + randomValue(row, rng); break;
        case 1: text += row.key + " " + std::to_string(int(rng() % 2000) - 1000) + "," + std::to_string(rng() % 7); break;
        case 2:
          text += row.key + " ";
          for (int i = 0, m = int(rng() % 40); i < m; ++i) text += char(byte(rng));
          break;
        default:
          for (int i = 0, m = int(rng() % 60); i < m; ++i) text += char(byte(rng));
      }
      text += "\n";
    }
    Result<Style> st = loadStyle(d.write("random.style", text));
    if (st) {
      ++read;
      continue;
    }
    ++refused;
    EXPECT_NE(st.error().find("random.style"), std::string::npos) << st.error();
    EXPECT_FALSE(hasRawBytes(st.error())) << st.error();
  }
  EXPECT_GT(read, 0);
  EXPECT_GT(refused, 0);
}

// Random command lines built from the table's options: parsed or refused with exit status 2,
// the message free of raw bytes. 60 lines: each builds the whole command line (CLI11, every
// row), 70 ms under the sanitizers.
TEST(SettingsTable, RandomCommandLinesAreParsedOrRefused) {
  std::mt19937 rng(9);
  const auto& table = settingsTable();
  std::uniform_int_distribution<int> byte(1, 255);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<std::string> args{"npr-viewer", "--headless"};
    for (int i = 0, n = int(rng() % 4) + 1; i < n; ++i) {
      const Setting& row = table[rng() % table.size()];
      if (!row.cli) continue;
      if (row.type == SettingType::Bool && !row.cliTakesValue) {
        args.push_back((rng() % 2 ? "--" : "--no-") + row.key);
        continue;
      }
      args.push_back("--" + row.key);
      std::string value = randomValue(row, rng);
      if (rng() % 3 == 0) {
        value.clear();
        for (int k = 0, m = int(rng() % 12) + 1; k < m; ++k) value += char(byte(rng));
      }
      args.push_back(value);
    }
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    testing::internal::CaptureStderr();
    const ParseOutcome parsed = parseCommandLine(int(argv.size()), argv.data());
    const std::string err = testing::internal::GetCapturedStderr();
    if (parsed.options) continue;
    EXPECT_EQ(parsed.exitCode, 2);
    EXPECT_FALSE(hasRawBytes(err.substr(0, err.empty() ? 0 : err.size() - 1))) << err;
  }
}

}  // namespace
}  // namespace npr

// Files the window writes take the next number in their folder: a second run's F12 never
// replaces the first run's picture.
#include "app/next_free_name.h"
TEST(OutputNames, NextFreeNameNeverReusesANameInTheFolder) {
  npr::test::TempDir d;
  const auto first = npr::nextFreeName(d.path(), "npr-screenshot", ".png");
  EXPECT_EQ(first.filename(), "npr-screenshot-0001.png");
  d.write("npr-screenshot-0001.png", "x");
  d.write("npr-screenshot-0007.png", "x");
  d.write("npr-screenshot-old.png", "x");   // not numbered: ignored
  d.write("npr-lines-0042.svg", "x");       // another kind: ignored
  EXPECT_EQ(npr::nextFreeName(d.path(), "npr-screenshot", ".png").filename(), "npr-screenshot-0008.png");
  EXPECT_EQ(npr::nextFreeName(d.path(), "npr-lines", ".svg").filename(), "npr-lines-0043.svg");
  EXPECT_EQ(npr::nextFreeName(d.path(), "npr-style", ".style").filename(), "npr-style-0001.style");
}

// One resolver for what names a palette or a style: shipped names, folders and files; a typo
// answered with the closest names and the list of what exists.
#include "app/data_directory.h"
#include "app/name_suggestions.h"
TEST(Names, PalettesAndStylesResolveByNameAndTyposGetTheClosestNames) {
  EXPECT_EQ(npr::closestNames("pencl", {"pencil", "charcoal", "stipple"}), std::vector<std::string>{"pencil"});
  EXPECT_EQ(npr::closestNames("cross", {"crosshatch", "cel"}), std::vector<std::string>{"crosshatch"});
  EXPECT_TRUE(npr::closestNames("zzzzzz", {"pencil", "wood"}).empty());
  EXPECT_EQ(npr::didYouMean("wod", {"wood", "gooch"}), " (did you mean wood?)");

  npr::Result<std::string> wood = npr::findPalette("wood", "/nonexistent");
  ASSERT_TRUE(wood) << wood.error();
  EXPECT_EQ(std::filesystem::path(*wood).filename(), "wood.palette");
  EXPECT_EQ(*npr::findPalette("none", "."), "none");
  npr::Result<std::string> typo = npr::findPalette("crosshach", "/nonexistent");
  ASSERT_FALSE(typo);
  EXPECT_NE(typo.error().find("did you mean crosshatch"), std::string::npos) << typo.error();
  EXPECT_NE(typo.error().find("the shipped palettes are"), std::string::npos) << typo.error();
  npr::Result<std::string> pencil = npr::findStyle("pencil");
  ASSERT_TRUE(pencil) << pencil.error();
  EXPECT_EQ(std::filesystem::path(*pencil).filename(), "pencil.style");
  npr::Result<std::string> pencl = npr::findStyle("pencl");
  ASSERT_FALSE(pencl);
  EXPECT_NE(pencl.error().find("did you mean pencil"), std::string::npos) << pencl.error();
  // A saved style names a shipped palette by its name, any other by its path.
  EXPECT_EQ(npr::paletteNameOrPath(npr::defaultPalettePath()), "crosshatch");
  EXPECT_EQ(npr::paletteNameOrPath("/tmp/mine/mine.palette"), "/tmp/mine/mine.palette");
}
