// Names of the settings on the command line and in the overlay (see render_settings.h).
#include "renderer/render_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace npr {

std::string orientName(const OrientSettings& o) {
  switch (o.source) {
    case OrientSource::None: return "none";
    case OrientSource::Curvature: return "curvature";
    case OrientSource::Light: return "light";
    case OrientSource::Fixed: {
      // As short as reads back to the same angle (a saved style keeps it exactly).
      char buf[32];
      for (int digits = 6; digits <= 9; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, double(o.degrees));
        if (std::strtof(buf, nullptr) == o.degrees) break;
      }
      return buf;
    }
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

const char* outlineMethodName(OutlineMethod m) {
  switch (m) {
    case OutlineMethod::Edges: return "edges";
    case OutlineMethod::Offset: return "offset";
    case OutlineMethod::Fatten: return "fatten";
  }
  return "fatten";
}

std::optional<OutlineMethod> parseOutlineMethod(const std::string& s) {
  for (OutlineMethod m : {OutlineMethod::Edges, OutlineMethod::Offset, OutlineMethod::Fatten})
    if (s == outlineMethodName(m)) return m;
  return std::nullopt;
}

bool parseLineKinds(const std::string& list, LineSettings& lines, std::string* unknown) {
  LineSettings kinds = lines;
  kinds.silhouettes = kinds.creases = kinds.boundaries = kinds.materials = kinds.intersections = kinds.imageSpace = kinds.hardware = kinds.rim = false;
  std::size_t start = 0;
  while (list != "none" && start <= list.size()) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    std::string kind = list.substr(start, end - start);
    kind.erase(0, kind.find_first_not_of(" \t"));
    kind.erase(kind.find_last_not_of(" \t") + 1);
    if (kind == "silhouette" || kind == "silhouettes") kinds.silhouettes = true;
    else if (kind == "crease" || kind == "creases") kinds.creases = true;
    else if (kind == "boundary" || kind == "boundaries") kinds.boundaries = true;
    else if (kind == "material" || kind == "materials") kinds.materials = true;
    else if (kind == "intersection" || kind == "intersections") kinds.intersections = true;
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

}  // namespace npr
