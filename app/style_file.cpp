// Style presets (see style_file.h).
#include "app/style_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "renderer/core/input_file.h"

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

std::string resolveStyle(const std::string& nameOrFile) {
  std::error_code ec;
  if (fs::exists(nameOrFile, ec)) return nameOrFile;
  const fs::path shipped = fs::path(dataDirectory()) / "palettes" / "styles" / (nameOrFile + ".style");
  return fs::exists(shipped, ec) ? shipped.string() : nameOrFile;
}

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::optional<float> number(const std::string& s) {
  char* end = nullptr;
  const float v = std::strtof(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

Result<Style> loadStyle(const std::string& path) {
  Result<std::string> text = readInputFile(path, InputKind::Palette);
  if (!text) return Error{text.error()};
  Style st;
  st.file = path;
  st.name = fs::path(path).stem().string();
  const fs::path dir = fs::path(path).parent_path();
  // A shipped palette's folder name, or a path relative to the style file.
  auto resolvePalette = [&](const std::string& arg) {
    std::error_code ec;
    const fs::path shipped = fs::path(dataDirectory()) / "palettes" / arg;
    const fs::path relative = dir / arg;
    return fs::exists(relative, ec) ? relative.string() : fs::is_directory(shipped, ec) ? shipped.string() : relative.string();
  };
  std::istringstream in(*text);
  std::string raw;
  int lineNo = 0;
  LineSettings lines;
  bool anyLine = false;
  while (std::getline(in, raw)) {
    ++lineNo;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const std::string where = path + " line " + std::to_string(lineNo);
    const auto sp = line.find_first_of(" \t");
    const std::string key = line.substr(0, sp), arg = sp == std::string::npos ? "" : trim(line.substr(sp));
    auto bad = [&](const std::string& why) { return Error{where + ": " + key + " " + why + ", got '" + arg + "'"}; };
    if (key == "name") {
      st.name = arg;
    } else if (key == "palette") {
      if (arg.empty()) return bad("needs a shipped palette's name or a path");
      st.palette = resolvePalette(arg);
    } else if (key == "shadow-palette" || key == "occlusion-palette") {
      if (arg.empty()) return bad("needs a shipped palette's name, a path or none");
      (key == "shadow-palette" ? st.shadowPalette : st.occlusionPalette) = arg == "none" ? std::string() : resolvePalette(arg);
    } else if (key == "light") {
      std::stringstream ss(arg);
      std::string t;
      std::vector<float> v;
      while (std::getline(ss, t, ',')) {
        const auto x = number(trim(t));
        if (!x) return bad("must be three finite numbers X,Y,Z");
        v.push_back(*x);
      }
      if (v.size() != 3) return bad("must be three finite numbers X,Y,Z");
      st.light = glm::vec3(v[0], v[1], v[2]);
    } else if (key == "ground" || key == "shadows" || key == "occlusion") {
      if (arg != "on" && arg != "off") return bad("must be on or off");
      (key == "ground" ? st.ground : key == "shadows" ? st.shadows : st.occlusion) = arg == "on";
    } else if (key == "match") {
      if (!(st.match = parseMatchMode(arg))) return bad("must be colors, intensity or order");
    } else if (key == "range-scale") {
      const auto v = number(arg);
      if (!v || *v <= 0.0f) return bad("must be a finite number > 0");
      st.rangeScale = *v;
    } else if (key == "path") {
      const auto p = parseRenderPath(arg);
      if (!p || !pathInfo(*p).userSelectable) return bad("must be one of " + userRenderPathNames());
      st.path = *p;
    } else if (key == "tone") {
      if (!(st.tone = parseToneModel(arg))) return bad("must be opengl, gooch, splashback or charcoal");
    } else if (key == "bands") {
      std::vector<float> b;
      std::stringstream ss(arg);
      std::string t;
      while (std::getline(ss, t, ',')) {
        const auto v = number(trim(t));
        if (!v) return bad("must be numbers separated by commas");
        b.push_back(*v);
      }
      st.bands = b;
    } else if (key == "lines") {
      anyLine = true;
      if (!parseLineKinds(arg, lines)) return bad("must be none or silhouette, crease, boundary, image, hardware, rim separated by commas");
    } else if (key == "line-width") {
      const auto v = number(arg);
      if (!v || *v <= 0.0f || *v > 64.0f) return bad("must be in (0, 64] pixels");
      anyLine = true;
      lines.width = *v;
    } else if (key == "crease-angle") {
      const auto v = number(arg);
      if (!v || *v < 0.0f || *v > 180.0f) return bad("must be in [0, 180] degrees");
      anyLine = true;
      lines.creaseAngle = *v;
    } else if (key == "sketchy") {
      if (arg != "on" && arg != "off") return bad("must be on or off");
      anyLine = true;
      lines.sketchy = arg == "on";
    } else if (key == "strokes") {
      if (arg != "on" && arg != "off") return bad("must be on or off");
      st.strokes = st.strokes.value_or(StrokeSettings{});
      st.strokes->on = arg == "on";
    } else if (key == "stroke-density") {
      const auto v = number(arg);
      if (!v || *v < StrokeSettings::kMinDensity || *v > StrokeSettings::kMaxDensity) return bad("must be in 1..1000000 strokes per unit area");
      st.strokes = st.strokes.value_or(StrokeSettings{});
      st.strokes->density = *v;
    } else if (key == "stroke-size") {
      const std::optional<glm::vec2> size = parseStrokeSize(arg);
      if (!size) return bad("must be LxW in pixels, each 1..256");
      st.strokes = st.strokes.value_or(StrokeSettings{});
      st.strokes->length = size->x;
      st.strokes->width = size->y;
    } else if (key == "outline") {
      const auto m = parseOutlineMethod(arg);
      if (!m) return bad("must be fatten, offset or edges");
      anyLine = true;
      lines.outline = *m;
    } else if (key == "outline-offset") {
      const auto v = number(arg);
      if (!v || *v < LineSettings::kMinOutlineOffset || *v > LineSettings::kMaxOutlineOffset) return bad("must be in [0, 0.2]");
      anyLine = true;
      lines.outlineOffset = *v;
    } else if (key == "pattern") {
      if (!(st.pattern = parsePatternSpace(arg))) return bad("must be screen, anchored or object");
    } else if (key == "pattern-scale") {
      const auto v = number(arg);
      if (!v || *v < RenderSettings::kMinPatternScale || *v > RenderSettings::kMaxPatternScale) return bad("must be in 0.125..16");
      st.patternScale = *v;
    } else if (key == "pattern-filter") {
      if (arg != "nearest" && arg != "linear") return bad("must be nearest or linear");
      st.patternLinear = arg == "linear";
    } else if (key == "orient") {
      if (!(st.orient = parseOrient(arg))) return bad("must be none, curvature, light or an angle in degrees");
    } else {
      return Error{where + ": unknown key '" + key + "' (see the style file format in the README)"};
    }
  }
  if (anyLine) st.lines = lines;
  return st;
}

Status applyStyle(const Style& st, ViewerState& state, Renderer& renderer) {
  for (const auto* control : {&st.shadowPalette, &st.occlusionPalette})
    if (*control && !(*control)->empty())
      if (Result<Palette> p = loadPalette(**control); !p) return Error{st.file + ": control palette not loaded: " + p.error()};
  // The palette first: it may fail, and it brings its own defaults, which the style's own
  // match mode and range scale then override.
  if (st.palette)
    if (Status s = state.loadPalette(*st.palette, renderer); !s) return Error{st.file + ": " + s.error()};
  // Control palettes next. Their files are read before anything changes, so a broken one
  // leaves the look as it was (an upload failing after them is the rare exception).
  if (st.shadowPalette)
    if (Status s = state.setControlPalette(ControlParameter::Shadow, *st.shadowPalette, renderer); !s) return Error{st.file + ": " + s.error()};
  if (st.occlusionPalette)
    if (Status s = state.setControlPalette(ControlParameter::Occlusion, *st.occlusionPalette, renderer); !s) return Error{st.file + ": " + s.error()};
  if (st.tone)
    if (Status s = renderer.lighting().setToneModel(*st.tone, renderer.lighting().toneParameters()); !s) return Error{st.file + ": " + s.error()};
  RenderSettings& s = state.settings;
  if (st.match) s.match = *st.match;
  if (st.rangeScale) s.rangeScale = *st.rangeScale;
  if (st.path) s.path = *st.path;
  if (st.bands) s.bands = *st.bands;
  if (st.lines) {
    const LineSettings& l = *st.lines;
    s.lines.silhouettes = l.silhouettes;
    s.lines.creases = l.creases;
    s.lines.boundaries = l.boundaries;
    s.lines.imageSpace = l.imageSpace;
    s.lines.width = l.width;
    s.lines.creaseAngle = l.creaseAngle;
    s.lines.sketchy = l.sketchy;
    s.lines.hardware = l.hardware;
    s.lines.rim = l.rim;
    s.lines.outline = l.outline;
    s.lines.outlineOffset = l.outlineOffset;
  }
  if (st.strokes) {
    s.strokes.on = st.strokes->on;
    s.strokes.density = st.strokes->density;
    s.strokes.length = st.strokes->length;
    s.strokes.width = st.strokes->width;
  }
  if (st.pattern) s.pattern = *st.pattern;
  if (st.patternScale) s.patternScale = *st.patternScale;
  if (st.patternLinear) s.patternLinearFilter = *st.patternLinear;
  if (st.orient) s.orient = *st.orient;
  if (st.ground) s.ground = *st.ground;
  if (st.shadows) s.shadows = *st.shadows;
  if (st.occlusion) s.occlusion = *st.occlusion;
  if (st.light) state.light = *st.light;
  state.note("style " + st.name + " applied");
  return okStatus();
}

std::string styleText(const ViewerState& state, Renderer& renderer, const std::string& name) {
  const RenderSettings& s = state.settings;
  std::ostringstream o;
  o << "# Saved by npr-viewer: apply with --style FILE\n";
  o << "name " << name << "\n";
  if (state.palette) o << "palette " << fs::absolute(state.palette->file).lexically_normal().string() << "\n";
  o << "match " << matchModeName(s.match) << "\n";
  o << "range-scale " << s.rangeScale << "\n";
  o << "path " << renderPathName(s.path) << "\n";
  o << "tone " << toneModelName(renderer.lighting().toneModel()) << "\n";
  if (!s.bands.empty()) {
    o << "bands ";
    for (size_t i = 0; i < s.bands.size(); ++i) o << (i ? "," : "") << s.bands[i];
    o << "\n";
  }
  std::vector<std::string> kinds;
  if (s.lines.silhouettes) kinds.push_back("silhouette");
  if (s.lines.creases) kinds.push_back("crease");
  if (s.lines.boundaries) kinds.push_back("boundary");
  if (s.lines.imageSpace) kinds.push_back("image");
  if (s.lines.hardware) kinds.push_back("hardware");
  if (s.lines.rim) kinds.push_back("rim");
  o << "lines ";
  if (kinds.empty()) o << "none";
  for (size_t i = 0; i < kinds.size(); ++i) o << (i ? "," : "") << kinds[i];
  o << "\nline-width " << s.lines.width << "\ncrease-angle " << s.lines.creaseAngle << "\nsketchy " << (s.lines.sketchy ? "on" : "off") << "\n";
  o << "outline " << outlineMethodName(s.lines.outline) << "\noutline-offset " << s.lines.outlineOffset << "\n";
  o << "pattern " << patternSpaceName(s.pattern) << "\npattern-scale " << s.patternScale << "\npattern-filter "
    << (s.patternLinearFilter ? "linear" : "nearest") << "\n";
  o << "orient " << orientName(s.orient) << "\n";
  o << "ground " << (s.ground ? "on" : "off") << "\nshadows " << (s.shadows ? "on" : "off") << "\nocclusion " << (s.occlusion ? "on" : "off") << "\n";
  auto control = [](const std::string& file) { return file.empty() ? std::string("none") : fs::absolute(file).lexically_normal().string(); };
  o << "light " << state.light.x << "," << state.light.y << "," << state.light.z << "\n";
  o << "shadow-palette " << control(state.shadowPalette) << "\nocclusion-palette " << control(state.occlusionPalette) << "\n";
  o << "strokes " << (s.strokes.on ? "on" : "off") << "\nstroke-density " << s.strokes.density << "\nstroke-size " << s.strokes.length << "x"
    << s.strokes.width << "\n";
  return o.str();
}

}  // namespace npr
