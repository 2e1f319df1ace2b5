// Style files (see style_file.h).
#include "app/settings/style_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/data_directory.h"
#include "app/name_suggestions.h"
#include "renderer/core/input_file.h"
#include "renderer/core/printable.h"

namespace npr {
namespace fs = std::filesystem;

std::vector<std::string> discoverStyles() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& f : fs::directory_iterator(fs::path(dataDirectory()) / "palettes" / "styles", ec))
    if (f.path().extension() == ".style") out.push_back(f.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

Result<std::string> findStyle(const std::string& nameOrFile) {
  std::error_code ec;
  if (fs::is_regular_file(nameOrFile, ec)) return nameOrFile;
  const fs::path shipped = fs::path(dataDirectory()) / "palettes" / "styles" / (nameOrFile + ".style");
  if (nameOrFile.find('/') == std::string::npos && fs::is_regular_file(shipped, ec)) return shipped.string();
  const std::vector<std::string> names = shippedStyleNames();
  return Error{"no style named '" + printable(nameOrFile) + "'" + didYouMean(nameOrFile, names) + "; the shipped styles are " + listed(names) +
               ", or give a .style file"};
}

Result<std::string> findPalette(const std::string& name, const std::string& baseDirectory) {
  if (name == "none") return name;
  std::error_code ec;
  const fs::path relative = fs::path(baseDirectory) / name;
  if (!name.empty() && fs::exists(relative, ec)) return relative.string();
  const fs::path shipped = fs::path(dataDirectory()) / "palettes" / name;
  if (!name.empty() && name.find('/') == std::string::npos && fs::is_directory(shipped, ec)) {
    // Its own NAME.palette, as the shipped ones are laid out: the same file a path to it names.
    const fs::path own = shipped / (name + ".palette");
    return fs::is_regular_file(own, ec) ? own.string() : shipped.string();
  }
  const std::vector<std::string> names = shippedPaletteNames();
  return Error{"no palette named '" + printable(name) + "'" + didYouMean(name, names) + "; the shipped palettes are " + listed(names) +
               ", or give a .palette file or a folder holding one"};
}

namespace {
// A line set's texture file named relative to the style file is found there, as its palette
// is: `texture=ink.png` in styles/pen.style reads styles/ink.png when that exists.
std::string resolveLineSetFiles(const std::string& sets, const std::string& baseDirectory) {
  std::istringstream words(sets);
  std::string word, out;
  while (words >> word) {
    constexpr std::string_view key = "texture=";
    if (word.compare(0, key.size(), key) == 0) {
      const fs::path file = word.substr(key.size());
      std::error_code ec;
      if (file != "brush" && file.is_relative() && fs::exists(fs::path(baseDirectory) / file, ec))
        word = std::string(key) + (fs::path(baseDirectory) / file).lexically_normal().string();
    }
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}
}  // namespace

Result<Style> loadStyle(const std::string& path) {
  Result<std::string> text = readInputFile(path, InputKind::Palette);
  if (!text) return Error{text.error()};
  Style st;
  st.file = path;
  st.name = fs::path(path).stem().string();
  const std::string dir = fs::path(path).parent_path().string();
  std::istringstream in(*text);
  std::string raw;
  int lineNo = 0;
  Look scratch;  // every value is checked as it is read
  while (std::getline(in, raw)) {
    ++lineNo;
    const std::string line = trimmed(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::string where = path + " line " + std::to_string(lineNo);
    const auto sp = line.find_first_of(" \t");
    const std::string key = line.substr(0, sp), arg = sp == std::string::npos ? "" : trimmed(line.substr(sp));
    if (key == "name") {
      st.name = arg;
      continue;
    }
    const Setting* row = findSetting(key);
    if (!row) return Error{where + ": unknown key '" + printable(key) + "' (the README's settings reference lists the keys a style may set)"};
    // A palette that is not found is kept as written: the style reads, and applying it says why.
    const std::string value = row->type == SettingType::File ? findPalette(arg, dir).value_or(arg) : key == "line-set" ? resolveLineSetFiles(arg, dir) : arg;
    if (Status s = row->parse(value, scratch); !s) return Error{where + ": " + key + " '" + printable(arg) + "': " + s.error()};
    if (key == "palette") {
      st.palette = value;
      continue;
    }
    // A list's lines make one value (setting.h: repeated).
    auto earlier = std::find_if(st.values.begin(), st.values.end(), [&](const SettingValue& v) { return v.row == row; });
    if (row->repeated && earlier != st.values.end()) earlier->value += "\n" + value;
    else st.values.push_back({row, value, where});
  }
  return st;
}

Status applyStyle(const Style& st, ViewerState& state, Renderer& renderer) {
  std::vector<SettingValue> values;
  if (st.palette) values.push_back({findSetting("palette"), *st.palette, st.file});
  values.insert(values.end(), st.values.begin(), st.values.end());
  if (Status s = applySettings(values, true, state, renderer); !s) return Error{st.file + ": " + s.error()};
  state.note("style " + st.name + " applied");
  state.styleName = st.name;
  return okStatus();
}

std::string styleText(const ViewerState& state, const Renderer& renderer, const std::string& name) {
  return "# Saved by npr-viewer: apply with --style FILE\nname " + name + "\n" + lookText(currentLook(state, renderer));
}

Status saveStyle(const ViewerState& state, const Renderer& renderer, const std::string& name, const std::string& file) {
  std::ofstream out(file);
  out << styleText(state, renderer, name);
  if (!out.flush()) return Error{"cannot write the style file '" + file + "'"};
  return okStatus();
}

}  // namespace npr
