// Names of the settings on the command line and in the overlay (see render_settings.h).
#include "renderer/settings/render_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace npr {

std::string formatFloat(float v) {
  char buf[32];
  for (int digits = 6; digits <= 9; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, double(v));
    if (std::strtof(buf, nullptr) == v) break;
  }
  return buf;
}

std::string orientName(const OrientSettings& o) {
  switch (o.source) {
    case OrientSource::None: return "none";
    case OrientSource::Curvature: return "curvature";
    case OrientSource::Light: return "light";
    case OrientSource::Fixed: return formatFloat(o.degrees);  // a saved style keeps the angle exactly
  }
  return "none";
}

std::optional<OrientSettings> parseOrient(const std::string& s) {
  OrientSettings o;
  if (s == "none") return o;
  if (s == "curvature") o.source = OrientSource::Curvature;
  else if (s == "light") o.source = OrientSource::Light;
  else {
    const std::string number = s.rfind("fixed:", 0) == 0 ? s.substr(6) : s;
    if (number.empty()) return std::nullopt;
    char* end = nullptr;
    const double d = std::strtod(number.c_str(), &end);
    if (end != number.c_str() + number.size() || !std::isfinite(d) || std::fabs(d) > 1e6) return std::nullopt;
    o.source = OrientSource::Fixed;
    o.degrees = float(std::fmod(std::fmod(d, 180.0) + 180.0, 180.0));
  }
  return o;
}

std::optional<glm::vec2> parseStrokeSize(const std::string& s) {
  float l = 0.0f, w = 0.0f;
  char extra = 0;
  if (std::sscanf(s.c_str(), "%fx%f%c", &l, &w, &extra) != 2) return std::nullopt;
  if (!(l >= 1.0f && l <= StrokeSettings::kMaxSize && w >= 1.0f && w <= StrokeSettings::kMaxSize)) return std::nullopt;
  return glm::vec2(l, w);
}

int lineKindIndex(const std::string& name) {
  for (int i = 0; i < kLineKindCount; ++i)
    if (name == kLineKinds[i].name || name == kLineKinds[i].plural) return i;
  return -1;
}

bool parseLineKinds(const std::string& list, LineSettings& lines, std::string* unknown) {
  LineSettings kinds = lines;
  for (const LineKindRow& row : kLineKinds) kinds.*row.on = false;
  kinds.imageSpace = kinds.hardware = kinds.rim = false;
  std::size_t start = 0;
  while (list != "none" && start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    std::string kind = list.substr(start, end - start);
    kind.erase(0, kind.find_first_not_of(" \t"));
    kind.erase(kind.find_last_not_of(" \t") + 1);
    if (const int row = lineKindIndex(kind); row >= 0) kinds.*kLineKinds[row].on = true;
    else if (kind == "image") kinds.imageSpace = true;
    else if (kind == "hardware") kinds.hardware = true;
    else if (kind == "rim") kinds.rim = true;
    else {
      if (unknown) *unknown = kind;
      return false;
    }
    start = end + 1;
  }
  lines = kinds;
  return true;
}

namespace {

bool parseNumber(const std::string& text, float& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  const float v = std::strtof(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return false;
  out = v;
  return true;
}

std::vector<std::string> split(const std::string& text, char by) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(by, start), text.size());
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::string trimBlanks(std::string s) {
  s.erase(0, s.find_first_not_of(" \t\r\n"));
  s.erase(s.find_last_not_of(" \t\r\n") + 1);
  return s;
}

// One set's text; the error says what is wrong in it.
bool parseLineSet(const std::string& text, LineSet& set, std::string& why) {
  std::vector<std::string> words;
  for (std::string w : split(text, ' '))
    if (!(w = trimBlanks(w)).empty()) words.push_back(w);
  if (words.empty()) return why = "empty", false;
  for (const std::string& kind : split(words[0], ',')) {
    const int k = lineKindIndex(trimBlanks(kind));
    if (k < 0) {
      why = "unknown line kind (a set takes";
      for (int i = 0; i < kLineKindCount; ++i) why += std::string(i ? ", " : " ") + kLineKinds[i].name;
      return why += ")", false;
    }
    set.kinds |= std::uint8_t(1u << k);
  }
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::size_t eq = words[i].find('=');
    if (eq == std::string::npos) return why = "expected KEY=VALUE after the kinds", false;
    const std::string key = words[i].substr(0, eq), value = words[i].substr(eq + 1);
    if (key == "visibility") {
      if (value == "visible") set.visibility = LineSet::Visibility::Visible;
      else if (value == "hidden") set.visibility = LineSet::Visibility::Hidden;
      else if (value == "both") set.visibility = LineSet::Visibility::Both;
      else return why = "visibility must be visible, hidden or both", false;
    } else if (key == "width") {
      if (!parseNumber(value, set.width) || set.width < LineSet::kMinWidth || set.width > LineSet::kMaxWidth)
        return why = "width must be a number in 0.1..64 (pixels)", false;
    } else if ((key == "colour" || key == "color") && value == "tone") {
      set.toneColour = true;
      set.colour.reset();
    } else if (key == "colour" || key == "color") {
      const std::vector<std::string> c = split(value, ',');
      glm::vec3 rgb;
      if (c.size() != 3 || !parseNumber(c[0], rgb.r) || !parseNumber(c[1], rgb.g) || !parseNumber(c[2], rgb.b) ||
          glm::any(glm::lessThan(rgb, glm::vec3(0.0f))) || glm::any(glm::greaterThan(rgb, glm::vec3(1.0f))))
        return why = "colour must be R,G,B, each in 0..1, or tone (the palette entry the lit tone matches)", false;
      set.colour = rgb;
      set.toneColour = false;
    } else if (key == "dash") {
      const std::vector<std::string> d = split(value, ',');
      glm::vec2 dash;
      if (d.size() != 2 || !parseNumber(d[0], dash.x) || !parseNumber(d[1], dash.y) || dash.x < 0.0f || dash.y < 0.0f ||
          dash.x > LineSet::kMaxDash || dash.y > LineSet::kMaxDash || (dash.x == 0.0f) != (dash.y == 0.0f))
        return why = "dash must be ON,OFF in pixels (0..1000 each; 0,0 for solid)", false;
      set.dash = dash;
    } else if (key == "taper") {
      if (!parseNumber(value, set.taper) || !(set.taper >= 0.0f) || set.taper > LineSet::kMaxTaper)
        return why = "taper must be a number of pixels in 0..1000 (0: blunt ends)", false;
    } else if (key == "curvature") {
      if (!parseNumber(value, set.curvature) || std::fabs(set.curvature) > LineSet::kMaxCurvatureGain)
        return why = "curvature must be a number in -4..4 (how much wider where the surface curves more; 0: off)", false;
    } else if (key == "occlusion") {
      float level = 0.0f;
      if (!parseNumber(value, level) || level != std::floor(level) || level < 0.0f || level > float(LineSet::kMaxOcclusion))
        return why = "occlusion must be 0..3: the most surfaces in front of a hidden part that is still drawn (0: every one)", false;
      set.occlusion = int(level);
    } else if (key == "texture") {
      if (value.empty() || value.size() > 4096) return why = "texture must be brush or an image file's path (without blanks)", false;
      set.texture = value;
    } else if (key == "objects" || key == "materials") {
      std::vector<std::string>& names = key == "objects" ? set.objects : set.materials;
      names.clear();
      for (const std::string& name : split(value, ','))
        if (!name.empty()) names.push_back(name);
      if (names.empty())
        return why = key + " must name at least one " + (key == "objects" ? "object" : "material") + " (NAME,NAME; * and ? match any text and any character)", false;
    } else if (key == "falloff" || key == "sketchy") {
      if (value != "on" && value != "off") return why = key + " must be on or off", false;
      (key == "falloff" ? set.falloff : set.sketchy) = value == "on";
    } else {
      return why = "unknown key '" + key + "' (visibility, width, colour, dash, taper, texture, curvature, occlusion, falloff, sketchy, objects, materials)", false;
    }
  }
  return true;
}

}  // namespace

namespace {

// '*' any run of characters, '?' any one. Backtracks only to the last star: time at most the
// product of the lengths, whatever the pattern (a recursive match is exponential in the stars).
bool globMatch(const std::string& pattern, const std::string& text) {
  std::size_t p = 0, t = 0, star = std::string::npos, resume = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p, ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = t;
    } else if (star != std::string::npos) {
      p = star + 1;
      t = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace

bool LineSet::takesMaterial(const std::string& name) const {
  if (materials.empty()) return true;
  for (const std::string& pattern : materials)
    if (globMatch(pattern, name)) return true;
  return false;
}

bool LineSet::appliesTo(const std::string* object) const {
  if (!object && !materials.empty()) return false;  // intersections have no material of their own
  if (objects.empty()) return true;
  if (!object) return false;
  for (const std::string& pattern : objects)
    if (globMatch(pattern, *object)) return true;
  return false;
}

bool parseLineSets(const std::string& text, std::vector<LineSet>& sets, std::string* why) {
  std::vector<LineSet> parsed;
  if (trimBlanks(text) != "none") {
    std::string all = text;
    std::replace(all.begin(), all.end(), ';', '\n');
    int n = 0;
    for (const std::string& line : split(all, '\n')) {
      if (trimBlanks(line).empty()) continue;
      ++n;
      LineSet set;
      std::string reason;
      if (!parseLineSet(line, set, reason)) {
        if (why) *why = "set " + std::to_string(n) + ": " + reason;
        return false;
      }
      parsed.push_back(set);
    }
    if (n == 0) {
      if (why) *why = "no set (give KINDS [KEY=VALUE ...], or none)";
      return false;
    }
  }
  sets = std::move(parsed);
  return true;
}

std::string formatLineSets(const std::vector<LineSet>& sets) {
  if (sets.empty()) return "none";
  std::string out;
  for (const LineSet& s : sets) {
    if (!out.empty()) out += "\n";
    std::string kinds;
    for (int k = 0; k < kLineKindCount; ++k)
      if (s.has(k)) kinds += (kinds.empty() ? "" : ",") + std::string(kLineKinds[k].name);
    out += kinds;
    if (s.visibility != LineSet::Visibility::Visible) out += s.visibility == LineSet::Visibility::Hidden ? " visibility=hidden" : " visibility=both";
    out += " width=" + formatFloat(s.width);
    if (s.toneColour) out += " colour=tone";
    else if (s.colour) out += " colour=" + formatFloat(s.colour->r) + "," + formatFloat(s.colour->g) + "," + formatFloat(s.colour->b);
    if (s.dash.x > 0.0f) out += " dash=" + formatFloat(s.dash.x) + "," + formatFloat(s.dash.y);
    if (s.taper > 0.0f) out += " taper=" + formatFloat(s.taper);
    if (!s.texture.empty()) out += " texture=" + s.texture;
    if (s.curvature != 0.0f) out += " curvature=" + formatFloat(s.curvature);
    if (s.occlusion > 0) out += " occlusion=" + std::to_string(s.occlusion);
    if (s.falloff) out += " falloff=on";
    if (s.sketchy) out += " sketchy=on";
    for (std::size_t i = 0; i < s.objects.size(); ++i) out += (i ? "," : " objects=") + s.objects[i];
    for (std::size_t i = 0; i < s.materials.size(); ++i) out += (i ? "," : " materials=") + s.materials[i];
  }
  return out;
}

RenderSettings pixelSizesScaled(const RenderSettings& s, float k) {
  RenderSettings out = s;
  out.lines.width *= k;
  for (LineSet& set : out.lines.sets) {
    set.width *= k;
    set.dash *= k;
    set.taper *= k;
  }
  out.strokes.length *= k;
  out.strokes.width *= k;
  out.patternScale *= k;
  return out;
}

}  // namespace npr
