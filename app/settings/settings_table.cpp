// The settings table (see setting.h): one row per user setting, grouped by the feature it
// belongs to. Adding a setting is adding a row here and using its field; the command line,
// style files, the overlay and docs/settings.md follow.
#include "app/settings/setting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "renderer/core/image_io.h"
#include "renderer/paths/path_table.h"
#include "renderer/settings/choice_names.h"

namespace npr {
namespace {

template <class T>
using Ref = std::function<T&(Look&)>;

Status why(const std::string& form) { return Error{"use " + form}; }

std::optional<double> number(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string part;
  while (std::getline(ss, part, ',')) out.push_back(trimmed(part));
  if (!s.empty() && s.back() == ',') out.push_back("");
  return out;
}

Setting base(const char* key, const char* label, const char* section, const char* help, SettingType type) {
  Setting s;
  s.key = key, s.label = label, s.section = section, s.help = help, s.type = type;
  return s;
}

Setting boolRow(const char* key, const char* label, const char* section, const char* help, Ref<bool> ref) {
  Setting s = base(key, label, section, help, SettingType::Bool);
  s.format = [ref](const Look& l) { return std::string(ref(const_cast<Look&>(l)) ? "on" : "off"); };
  s.parse = [ref](const std::string& v, Look& l) -> Status {
    if (v != "on" && v != "off") return why("on or off");
    ref(l) = v == "on";
    return okStatus();
  };
  s.boolRef = [ref](Look& l) { return &ref(l); };
  return s;
}

Setting floatRow(const char* key, const char* label, const char* section, const char* help, double min, double max, Ref<float> ref,
                 bool logarithmic = false) {
  Setting s = base(key, label, section, help, SettingType::Float);
  s.min = min, s.max = max, s.logarithmic = logarithmic;
  s.format = [ref](const Look& l) { return formatFloat(ref(const_cast<Look&>(l))); };
  const std::string form = "a number in " + s.valueForm();
  s.parse = [ref, min, max, form](const std::string& v, Look& l) -> Status {
    const std::optional<double> x = number(v);
    if (!x || *x < min || *x > max) return why(form);
    ref(l) = float(*x);
    return okStatus();
  };
  s.floatRef = [ref](Look& l) { return &ref(l); };
  return s;
}

Setting intRow(const char* key, const char* label, const char* section, const char* help, int min, int max, Ref<int> ref) {
  Setting s = base(key, label, section, help, SettingType::Int);
  s.min = min, s.max = max;
  s.format = [ref](const Look& l) { return std::to_string(ref(const_cast<Look&>(l))); };
  const std::string form = "an integer in " + s.valueForm();
  s.parse = [ref, min, max, form](const std::string& v, Look& l) -> Status {
    const std::optional<double> x = number(v);
    if (!x || *x != std::floor(*x) || *x < min || *x > max) return why(form);
    ref(l) = int(*x);
    return okStatus();
  };
  s.intRef = [ref](Look& l) { return &ref(l); };
  return s;
}

// A choice among named values of an enum (or any type with ==).
template <class T>
Setting choiceRow(const char* key, const char* label, const char* section, const char* help, std::vector<std::pair<std::string, T>> values,
                  Ref<T> ref) {
  Setting s = base(key, label, section, help, SettingType::Choice);
  for (const auto& [name, value] : values) s.choices.push_back(name);
  const std::string form = s.valueForm();
  s.format = [ref, values](const Look& l) {
    for (const auto& [name, value] : values)
      if (value == ref(const_cast<Look&>(l))) return name;
    return values.front().first;
  };
  s.parse = [ref, values, form](const std::string& v, Look& l) -> Status {
    for (const auto& [name, value] : values)
      if (name == v) {
        ref(l) = value;
        return okStatus();
      }
    return why(form);
  };
  return s;
}

// A choice among an enum's values, by the names settings/choice_names.h gives them.
template <class T>
Setting choiceRow(const char* key, const char* label, const char* section, const char* help, Ref<T> ref) {
  std::vector<std::pair<std::string, T>> values;
  for (const auto& [name, value] : ChoiceNames<T>::values) values.emplace_back(name, value);
  return choiceRow<T>(key, label, section, help, std::move(values), ref);
}

Setting vectorRow(const char* key, const char* label, const char* section, const char* help, SettingType type, Ref<glm::vec3> ref) {
  Setting s = base(key, label, section, help, type);
  s.format = [ref](const Look& l) {
    const glm::vec3 v = ref(const_cast<Look&>(l));
    return formatFloat(v.x) + "," + formatFloat(v.y) + "," + formatFloat(v.z);
  };
  const bool colour = type == SettingType::Colour;
  s.parse = [ref, colour](const std::string& v, Look& l) -> Status {
    const std::vector<std::string> parts = splitCommas(v);
    glm::vec3 out(0.0f);
    if (parts.size() != 3) return why(colour ? "three numbers R,G,B in 0..1" : "three finite numbers X,Y,Z");
    for (int i = 0; i < 3; ++i) {
      const std::optional<double> x = number(parts[size_t(i)]);
      if (!x || std::fabs(*x) > 1e6 || (colour && (*x < 0.0 || *x > 1.0)))
        return why(colour ? "three numbers R,G,B in 0..1" : "three finite numbers X,Y,Z");
      out[i] = float(*x);
    }
    ref(l) = out;
    return okStatus();
  };
  s.vectorRef = [ref](Look& l) { return &ref(l); };
  return s;
}

// A palette file: a path (resolved by the caller: shipped names and style-relative paths), or
// none when `optional`.
Setting fileRow(const char* key, const char* label, const char* section, const char* help, Ref<std::string> ref, bool optional) {
  Setting s = base(key, label, section, help, SettingType::File);
  s.format = [ref](const Look& l) {
    const std::string& f = ref(const_cast<Look&>(l));
    return f.empty() ? std::string("none") : std::filesystem::absolute(f).lexically_normal().string();
  };
  s.parse = [ref, optional](const std::string& v, Look& l) -> Status {
    if (v == "none" && optional) {
      ref(l).clear();
      return okStatus();
    }
    // Whether the file loads is found when it is applied (a style that names a missing palette
    // reads, and changes nothing when applied).
    if (v.empty() || v == "none") return why(optional ? "a shipped palette's name, a path or none" : "a shipped palette's name or a path");
    ref(l) = v;
    return okStatus();
  };
  return s;
}

std::vector<Setting> buildTable() {
  using K = SettingType;
  std::vector<Setting> t;
  // --- palette and tone
  {
    Setting p = fileRow("palette", "palette", "palette", "The palette: a shipped palette's folder name or a .palette file (loaded first; its match mode and range scale are the defaults)",
                        [](Look& l) -> std::string& { return l.palette; }, false);
    p.cli = false;  // --palette takes several files: an action of its own
    t.push_back(p);
  }
  t.push_back(choiceRow<MatchMode>("match", "match (M)", "palette", "How lit colours pick palette entries (default: the palette's)",
                                   [](Look& l) -> MatchMode& { return l.render.match; }));
  t.push_back(floatRow("range-scale", "tone spread (+/-)", "palette", "IntensityRangeScale: spreads the palette about its midpoint", 0.01, 100.0,
                       [](Look& l) -> float& { return l.render.rangeScale; }, true));
  t.push_back(choiceRow<ToneRange>("tone-range", "tone range", "palette",
                                   "auto: the palette's levels fitted onto the 2nd to 95th percentile of the lit tones on screen, each frame from "
                                   "its own view (the range scale spreads about them; not with band thresholds); per-object: each object fitted "
                                   "to its own tones (a dark object beside a bright one); fixed: the palette's own range",
                                   [](Look& l) -> ToneRange& { return l.render.toneRange; }));
  t.push_back(choiceRow<ToneBlend>("tone-blend", "between levels", "palette",
                                   "The smooth path between two levels: mix (blend them, greying their strokes) or threshold (whole "
                                   "strokes of one level or the other, per texel: crisp tone for nested palettes such as the drawn ones, with intensity matching)",
                                   [](Look& l) -> ToneBlend& { return l.render.toneBlend; }));
  t.back().shown = [](const Look& l) { return l.render.path == RenderPath::Smooth; };
  t.push_back(boolRow("palette-axis", "rows by depth or facing", "palette",
                      "A palette with rows (axis depth or facing): on, the row follows the surface's distance or facing; off, the first row only",
                      [](Look& l) -> bool& { return l.render.paletteAxis; }));
  {
    Setting b = base("bands", "cel band edges", "palette",
                     "Cel band thresholds T1,T2,... on the match query axis [0,3], strictly ascending (one fewer than the palette's tones); none: the nearest level",
                     K::Text);
    b.example = "0.8,1.6";
    b.format = [](const Look& l) {
      std::string out;
      for (float v : l.render.bands) out += (out.empty() ? "" : ",") + formatFloat(v);
      return out.empty() ? std::string("none") : out;
    };
    b.parse = [](const std::string& v, Look& l) -> Status {
      std::vector<float> bands;
      if (v != "none")
        for (const std::string& part : splitCommas(v)) {
          const std::optional<double> x = number(part);
          if (!x || std::fabs(*x) > 1e6 || (!bands.empty() && float(*x) <= bands.back())) return why("none or strictly ascending numbers T1,T2,...");
          bands.push_back(float(*x));
        }
      l.render.bands = bands;
      return okStatus();
    };
    t.push_back(b);
  }
  t.push_back(choiceRow<ToneModel>("tone", "tone", "palette", "The lighting model the palette matches against",
                                   [](Look& l) -> ToneModel& { return l.tone; }));
  auto goochLike = [](const Look& l) { return l.tone == ToneModel::Gooch || l.tone == ToneModel::Splashback; };
  for (auto [key, label, help, ref] : std::vector<std::tuple<const char*, const char*, const char*, Ref<float>>>{
           {"tone-blue", "blue", "Gooch and splashback tone: the cool colour's blue", [](Look& l) -> float& { return l.toneParameters.blue; }},
           {"tone-yellow", "yellow", "Gooch and splashback tone: the warm colour's yellow", [](Look& l) -> float& { return l.toneParameters.yellow; }},
           {"tone-alpha", "alpha", "Gooch and splashback tone: the diffuse colour's share of the cool colour", [](Look& l) -> float& { return l.toneParameters.alpha; }},
           {"tone-beta", "beta", "Gooch and splashback tone: the diffuse colour's share of the warm colour", [](Look& l) -> float& { return l.toneParameters.beta; }}}) {
    Setting s = floatRow(key, label, "palette", help, 0.0, 1.0, ref);
    s.shown = goochLike;
    t.push_back(s);
  }
  {
    Setting a = floatRow("splash-alpha", "splash alpha", "palette", "Splashback tone: the back light's share", 0.0, 1.0,
                         [](Look& l) -> float& { return l.toneParameters.splashAlpha; });
    Setting p = floatRow("splash-power", "splash power", "palette", "Splashback tone: the back light's falloff exponent", 0.0, 16.0,
                         [](Look& l) -> float& { return l.toneParameters.splashPower; });
    a.shown = p.shown = [](const Look& l) { return l.tone == ToneModel::Splashback; };
    t.push_back(a);
    t.push_back(p);
  }
  // --- render path
  {
    std::vector<std::pair<std::string, RenderPath>> paths;
    for (RenderPath p : userRenderPaths()) paths.emplace_back(renderPathName(p), p);
    t.push_back(choiceRow<RenderPath>("path", "path (P)", "path", "Where lighting is sampled and how the palette reaches the screen", paths,
                                      [](Look& l) -> RenderPath& { return l.render.path; }));
  }
  t.push_back(choiceRow<AntiAliasing>(
      "aa", "anti-aliasing", "path",
      "Anti-aliasing: edges smooths the pixel and vertex paths' tone edges in the shader (the match taken at four points of "
      "each pixel, the pattern untouched; about 1.1x a frame on a CPU rasterizer); ssaaK also draws the frame at K times the "
      "width and height (line widths, strokes and the pattern's texel too) and box-filters it down: silhouettes and the "
      "per-triangle paths' edges too, about K^2 the fill; fxaa: edges, then a post-process filter over the frame (one full-screen pass; "
      "it softens the palette's pattern too); off: none. Lines always keep their own one-pixel soft rim",
      {{"off", AntiAliasing::Off}, {"edges", AntiAliasing::Edges}, {"ssaa2", AntiAliasing::Ssaa2}, {"ssaa3", AntiAliasing::Ssaa3}, {"ssaa4", AntiAliasing::Ssaa4},
       {"fxaa", AntiAliasing::Fxaa}},
      [](Look& l) -> AntiAliasing& { return l.render.aa; }));
  t.push_back(choiceRow<TriangleLighting>("triangle-lighting", "triangle lighting", "path",
                                          "Where the per-triangle paths (stencil, triangle) light: cpu, gpu (read back), auto (gpu with shadows)",
                                          [](Look& l) -> TriangleLighting& { return l.render.triangleLighting; }));
  t.back().shown = [](const Look& l) { return l.render.path == RenderPath::Triangle || l.render.path == RenderPath::Stencil; };
  t.push_back(choiceRow<PosePlacement>("deform", "pose meshes on", "path",
                                       "Where a skinned or morphing mesh is posed: gpu (always, and the CPU too when the frame reads the mesh there: "
                                       "per-triangle paths, object-space lines, strokes, the anchored pattern), cpu (uploaded each pose), "
                                       "auto (gpu, but cpu where a software rasterizer's frame reads the mesh on the CPU)",
                                       [](Look& l) -> PosePlacement& { return l.render.deform; }));
  t.push_back(boolRow("gouraud", "reference lit per vertex", "path", "Reference path: per-vertex (Gouraud) instead of per-pixel (Phong) lighting",
                      [](Look& l) -> bool& { return l.render.referenceGouraud; }));
  t.push_back(boolRow("materials", "model materials", "path", "Light with the model's own materials, vertex colours and texture maps",
                      [](Look& l) -> bool& { return l.render.materials; }));
  t.back().cliTakesValue = true;  // `--materials on|off`, as it always was
  for (auto [key, label, help, ref] : std::vector<std::tuple<const char*, const char*, const char*, Ref<bool>>>{
           {"stencil-scissor", "scissor buckets", "Stencil path: bound each bucket's quads to its triangles' screen rectangle",
            [](Look& l) -> bool& { return l.render.stencilScissor; }},
           {"stencil-skip-empty", "skip empty buckets", "Stencil path: draw nothing for buckets with no triangle",
            [](Look& l) -> bool& { return l.render.stencilSkipEmpty; }},
           {"stencil-masks-first", "masks first", "Stencil path: mark every bucket's pixels before any quad (off: the original's mask, quad, quad)",
            [](Look& l) -> bool& { return l.render.stencilMasksFirst; }}}) {
    Setting s = boolRow(key, label, "path", help, ref);
    s.shown = [](const Look& l) { return l.render.path == RenderPath::Stencil; };
    t.push_back(s);
  }
  // --- pattern
  t.push_back(choiceRow<PatternSpace>("pattern", "pattern (T)", "pattern",
                                      "Where the palette's pattern lives: screen (the original), anchored (follows the object, stays flat), object (glued to the surface)",
                                      [](Look& l) -> PatternSpace& { return l.render.pattern; }));
  t.push_back(boolRow("pattern-rotation", "pattern turns with object", "pattern", "Anchored patterns turn with the object (off: they only move and scale)",
                      [](Look& l) -> bool& { return l.render.patternFollowsRotation; }));
  t.back().cliAliases = {{"--pattern-no-rotation", "off"}};
  t.back().shown = [](const Look& l) { return l.render.pattern == PatternSpace::Anchored; };
  t.push_back(floatRow("pattern-scale", "pattern scale", "pattern",
                       "Size of a palette texel in screen pixels (default: the window's content scale, 1 headless)",
                       RenderSettings::kMinPatternScale, RenderSettings::kMaxPatternScale, [](Look& l) -> float& { return l.render.patternScale; },
                       true));
  t.push_back(choiceRow<bool>("pattern-filter", "pattern filter", "pattern",
                              "Scaled or anchored patterns: nearest (one fetch) or linear (bilinear in linear light: smoother, slower)",
                              {{"nearest", false}, {"linear", true}}, [](Look& l) -> bool& { return l.render.patternLinearFilter; }));
  // --- orientation
  {
    Setting o = base("orient", "orient strokes", "orientation",
                     "Hatching direction: none (the texture's own), curvature (along the form), light (along the light's gradient) or DEGREES (a fixed screen angle)",
                     K::Text);
    o.example = "curvature";
    o.choices = {"none", "curvature", "light"};
    o.format = [](const Look& l) { return orientName(l.render.orient); };
    o.parse = [](const std::string& v, Look& l) -> Status {
      const std::optional<OrientSettings> parsed = parseOrient(v);
      if (!parsed) return why("none, curvature, light or an angle in degrees");
      // The source and angle only: the bins are a row of their own.
      l.render.orient.source = parsed->source;
      l.render.orient.degrees = parsed->degrees;
      return okStatus();
    };
    t.push_back(o);
  }
  t.push_back(intRow("orient-bins", "stroke angle steps", "orientation", "Steps the stroke turn is quantised to over 180 degrees", OrientSettings::kMinBins,
                     OrientSettings::kMaxBins, [](Look& l) -> int& { return l.render.orient.bins; }));
  t.back().shown = [](const Look& l) { return l.render.orient.source != OrientSource::None; };
  // --- light
  t.push_back(vectorRow("light", "light", "light", "Light position X,Y,Z in model radii (the model fits a unit sphere)", K::Vector,
                        [](Look& l) -> glm::vec3& { return l.light; }));
  // --- ground, shadows and occlusion
  t.push_back(boolRow("ground", "ground plane", "shadows", "A ground plane under the model, drawn with the same palette and path",
                      [](Look& l) -> bool& { return l.render.ground; }));
  t.push_back(boolRow("shadows", "shadows", "shadows", "Cast shadows from every enabled light",
                      [](Look& l) -> bool& { return l.render.shadows; }));
  t.push_back(fileRow("shadow-palette", "in shadow", "shadows", "Control image: a palette drawn where cast shadows fall (needs shadows)",
                      [](Look& l) -> std::string& { return l.shadowPalette; }, true));
  t.back().shown = [](const Look& l) { return l.render.shadows; };
  t.push_back(boolRow("occlusion", "occlusion", "occlusion", "Ambient occlusion darkens crevices",
                      [](Look& l) -> bool& { return l.render.occlusion; }));
  auto occluded = [](const Look& l) { return l.render.occlusion; };
  t.push_back(floatRow("occlusion-strength", "occlusion strength", "occlusion", "How much the occlusion darkens", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.occlusionStrength; }));
  t.back().shown = occluded;
  t.push_back(choiceRow<OcclusionMethod>("occlusion-method", "occlusion from", "occlusion",
                                         "baked (per vertex, once per mesh) or screen (per pixel, every frame; pixel, smooth and reference paths)",
                                         [](Look& l) -> OcclusionMethod& { return l.render.occlusionMethod; }));
  t.back().shown = occluded;
  t.push_back(floatRow("occlusion-reach", "occlusion reach", "occlusion", "Screen-space occlusion's reach, in model radii", 0.01, 10.0,
                       [](Look& l) -> float& { return l.render.screenOcclusionRadius; }, true));
  t.back().shown = [](const Look& l) { return l.render.occlusion && l.render.occlusionMethod == OcclusionMethod::Screen; };
  t.push_back(fileRow("occlusion-palette", "in crevices", "occlusion", "Control image: a palette drawn in crevices (needs occlusion)",
                      [](Look& l) -> std::string& { return l.occlusionPalette; }, true));
  t.back().shown = occluded;
  t.push_back(boolRow("control-palettes", "shadow and crevice palettes", "occlusion", "Draw the control-image palettes (off: the main palette alone, to compare)",
                      [](Look& l) -> bool& { return l.render.controlPalettes; }));
  t.back().shown = [](const Look& l) { return !l.shadowPalette.empty() || !l.occlusionPalette.empty(); };
  // --- painterly strokes
  t.push_back(boolRow("strokes", "brush strokes", "strokes", "Painterly brush strokes over the path: particles on the surface, coloured by the palette",
                      [](Look& l) -> bool& { return l.render.strokes.on; }));
  auto stroked = [](const Look& l) { return l.render.strokes.on; };
  t.push_back(floatRow("stroke-density", "stroke density", "strokes", "Strokes per unit area of the model fitted to the unit sphere",
                       StrokeSettings::kMinDensity, StrokeSettings::kMaxDensity, [](Look& l) -> float& { return l.render.strokes.density; }, true));
  t.back().shown = stroked;
  t.back().applyOnRelease = true;  // density reseeds the strokes
  t.push_back(intRow("stroke-budget", "stroke budget", "strokes", "At most this many strokes", 0, StrokeSettings::kMaxBudget,
                     [](Look& l) -> int& { return l.render.strokes.budget; }));
  t.back().shown = stroked;
  t.back().applyOnRelease = true;
  {
    Setting s = base("stroke-size", "stroke size", "strokes", "Stroke length x width in pixels, LxW, each 1..256", K::Text);
    s.example = "24x8";
    s.format = [](const Look& l) { return formatFloat(l.render.strokes.length) + "x" + formatFloat(l.render.strokes.width); };
    s.parse = [](const std::string& v, Look& l) -> Status {
      const std::optional<glm::vec2> size = parseStrokeSize(v);
      if (!size) return why("LxW in pixels, each 1..256");
      l.render.strokes.length = size->x;
      l.render.strokes.width = size->y;
      return okStatus();
    };
    s.shown = stroked;
    t.push_back(s);
  }
  // --- lines
  {
    // One list: the choices the overlay offers, the order a style file writes them, the message.
    // The object-space kinds (kLineKinds), then the image-space and outline ones.
    static const std::vector<std::string> kinds = [] {
      std::vector<std::string> out;
      for (const LineKindRow& row : kLineKinds) out.push_back(row.name);
      for (const char* other : {"image", "hardware", "rim"}) out.push_back(other);
      return out;
    }();
    Setting k = base("lines", "lines", "lines", "Feature lines: none, or kinds separated by commas", K::Kinds);
    k.choices = kinds;
    k.format = [](const Look& l) {
      const LineSettings& s = l.render.lines;
      std::string out;
      for (std::size_t i = 0; i < kinds.size(); ++i) {
        const bool on = i < std::size_t(kLineKindCount) ? s.*kLineKinds[i].on
                        : kinds[i] == "image"         ? s.imageSpace
                        : kinds[i] == "hardware"      ? s.hardware
                                                      : s.rim;
        if (on) out += (out.empty() ? "" : ",") + kinds[i];
      }
      return out.empty() ? std::string("none") : out;
    };
    k.parse = [](const std::string& v, Look& l) -> Status {
      if (!parseLineKinds(v, l.render.lines)) {
        std::string list;
        for (const std::string& name : kinds) list += (list.empty() ? "" : ", ") + name;
        return why("none, or " + list + " separated by commas");
      }
      return okStatus();
    };
    t.push_back(k);
  }
  t.push_back(floatRow("line-width", "line width", "lines", "Line width in pixels", 0.1, 64.0, [](Look& l) -> float& { return l.render.lines.width; }));
  t.push_back(floatRow("crease-angle", "crease angle", "lines", "Dihedral angle above which an edge is a crease, degrees", 0.0, 180.0,
                       [](Look& l) -> float& { return l.render.lines.creaseAngle; }));
  t.push_back(floatRow("suggestive-threshold", "suggestive contour cut-off", "lines",
                       "Suggestive contours: how strongly the radial curvature must rise toward the eye (DeCarlo et al.'s t_d, times the "
                       "mesh's radius squared); higher keeps fewer, stronger lines",
                       LineSettings::kMinSuggestiveThreshold, LineSettings::kMaxSuggestiveThreshold,
                       [](Look& l) -> float& { return l.render.lines.suggestiveThreshold; }));
  t.back().shown = [](const Look& l) { return (l.render.lines.drawnKinds() & 32u) != 0; };
  t.push_back(boolRow("sketchy", "sketchy", "lines", "Draw each line as a few jittered strokes", [](Look& l) -> bool& { return l.render.lines.sketchy; }));
  t.push_back(boolRow("hidden-lines", "hidden lines", "lines", "Also draw the hidden parts of the silhouettes, creases, boundaries and material lines, dashed",
                      [](Look& l) -> bool& { return l.render.lines.hidden; }));
  {
    Setting sets = base("line-set", "line sets", "lines",
                        "A line set: object-space kinds drawn in a style of their own, over the kinds `lines` names that no set takes; "
                        "repeat it for several, drawn in order. KINDS [visibility=visible|hidden|both] [width=W] [colour=R,G,B|tone] [dash=ON,OFF] [taper=PIXELS] "
                        "[texture=brush|FILE (stretched along each stroke)] [curvature=GAIN (-4..4: wider where the surface curves more)] [occlusion=LEVEL (1..3: hidden parts drawn only behind at most that many surfaces)] [falloff=on|off] [sketchy=on|off] [objects=NAME,... (* and ? match)] "
                        "[materials=NAME,...]",
                        K::Text);
    sets.example = "silhouette,crease visibility=hidden width=1 dash=4,3";
    sets.repeated = true;
    sets.format = [](const Look& l) { return formatLineSets(l.render.lines.sets); };
    sets.parse = [](const std::string& v, Look& l) -> Status {
      std::string reason;
      std::vector<LineSet> sets;
      if (!parseLineSets(v, sets, &reason)) return Error{reason};
      // A texture file is checked now (its header: a readable image within the limits), so a
      // typo is an error where it was typed, not a plain line later; and kept as an absolute
      // path, as palettes are, so a saved style works from any folder.
      for (std::size_t i = 0; i < sets.size(); ++i) {
        std::string& file = sets[i].texture;
        if (file.empty() || file == "brush") continue;
        if (Result<ImageSize> size = readImageSize(file); !size) return Error{"set " + std::to_string(i + 1) + ": texture: " + size.error()};
        std::error_code ec;
        const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
        if (!ec && absolute.string().find_first_of(" \t") == std::string::npos) file = absolute.lexically_normal().string();
      }
      l.render.lines.sets = std::move(sets);
      return okStatus();
    };
    t.push_back(sets);
  }
  t.push_back(boolRow("line-falloff", "depth falloff", "lines", "Thinner lines with distance", [](Look& l) -> bool& { return l.render.lines.depthFalloff; }));
  t.push_back(floatRow("edge-threshold", "image edge cut-off", "lines", "Image-space edges: the Sobel threshold on depth and normals", 0.01, 4.0,
                       [](Look& l) -> float& { return l.render.lines.imageThreshold; }, true));
  t.back().shown = [](const Look& l) { return l.render.lines.imageSpace; };
  t.push_back(choiceRow<OutlineMethod>("outline", "outline method", "lines",
                                       "Hardware outlines from back faces: fatten (even widths), offset or edges",
                                       [](Look& l) -> OutlineMethod& { return l.render.lines.outline; }));
  t.back().shown = [](const Look& l) { return l.render.lines.hardware; };
  t.push_back(floatRow("outline-offset", "outline offset", "lines", "Offset outlines: back faces pulled this fraction of their depth towards the eye",
                       LineSettings::kMinOutlineOffset, LineSettings::kMaxOutlineOffset,
                       [](Look& l) -> float& { return l.render.lines.outlineOffset; }));
  t.back().shown = [](const Look& l) { return l.render.lines.hardware && l.render.lines.outline == OutlineMethod::Offset; };
  for (const LineKindRow& row : kLineKinds) {
    const auto colour = row.colour;
    t.push_back(vectorRow(row.colourKey, row.colourLabel, "lines", row.colourHelp, K::Colour,
                          [colour](Look& l) -> glm::vec3& { return l.render.lines.*colour; }));
  }
  // --- depth cue
  t.push_back(boolRow("depth-cue", "depth cue", "depth-cue", "Tone and lines fade toward the paper with distance through the scene",
                      [](Look& l) -> bool& { return l.render.depthCue.on; }));
  auto cued = [](const Look& l) { return l.render.depthCue.on; };
  t.push_back(floatRow("depth-cue-start", "fade from", "depth-cue", "Where the fade starts: 0 the scene's front, 1 its back", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.depthCue.start; }));
  t.back().shown = cued;
  t.push_back(floatRow("depth-cue-end", "fade to", "depth-cue", "Where the fade is whole: 0 the scene's front, 1 its back", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.depthCue.end; }));
  t.back().shown = cued;
  t.push_back(floatRow("depth-cue-strength", "fade strength", "depth-cue", "How much of the paper covers the farthest surfaces", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.depthCue.strength; }));
  t.back().shown = cued;
  // --- vignette
  t.push_back(boolRow("vignette", "vignette", "vignette", "The picture fades into the paper toward the frame's edges, as a book illustration's",
                      [](Look& l) -> bool& { return l.render.vignette.on; }));
  auto vignetted = [](const Look& l) { return l.render.vignette.on; };
  t.push_back(floatRow("vignette-radius", "fade from", "vignette", "Where the fade starts: 0 the frame's centre, 1 its corners", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.vignette.radius; }));
  t.back().shown = vignetted;
  t.push_back(floatRow("vignette-softness", "fade width", "vignette", "How far beyond the radius the fade is whole (0: a hard edge)", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.vignette.softness; }));
  t.back().shown = vignetted;
  t.push_back(floatRow("vignette-strength", "fade strength", "vignette", "How much of the paper covers the frame's corners", 0.0, 1.0,
                       [](Look& l) -> float& { return l.render.vignette.strength; }));
  t.back().shown = vignetted;
  return t;
}

}  // namespace

std::string Setting::valueForm() const {
  auto num = [](double v) {
    char buf[32];
    // Seven digits: a float's bound as it was written (0.2, not 0.200000003).
    std::snprintf(buf, sizeof buf, "%.7g", v);
    return std::string(buf);
  };
  auto joined = [&](const std::string& sep, const std::string& last) {
    std::string out;
    for (size_t i = 0; i < choices.size(); ++i) out += (i == 0 ? "" : i + 1 == choices.size() ? last : sep) + choices[i];
    return out;
  };
  switch (type) {
    case SettingType::Bool: return "on or off";
    case SettingType::Int:
    case SettingType::Float: return num(min) + ".." + num(max);
    case SettingType::Choice: return joined(", ", " or ");
    case SettingType::Kinds: return "none or " + joined(",", ",");
    case SettingType::Colour: return "R,G,B in 0..1";
    case SettingType::Vector: return "X,Y,Z";
    case SettingType::File: return "NAME|PATH|none";
    case SettingType::Text: return example.empty() ? "text" : "e.g. " + example;
  }
  return "";
}

std::string Setting::typeName() const {
  switch (type) {
    case SettingType::Bool: return "on|off";
    case SettingType::Int:
    case SettingType::Float: return "N";
    case SettingType::Choice: {
      std::string out;
      for (const std::string& c : choices) out += (out.empty() ? "" : "|") + c;
      return out.size() <= 28 ? out : "NAME";
    }
    case SettingType::Kinds: return "KINDS";
    case SettingType::Colour: return "R,G,B";
    case SettingType::Vector: return "X,Y,Z";
    case SettingType::File: return "PALETTE|none";
    case SettingType::Text: return "VALUE";
  }
  return "VALUE";
}

const std::vector<Setting>& settingsTable() {
  static const std::vector<Setting> table = buildTable();
  return table;
}

const std::vector<SettingSection>& settingSections() {
  static const std::vector<SettingSection> sections = {
      {"palette", "Palette and tone", false},   {"path", "Render path", false},         {"pattern", "Pattern", false},
      {"orientation", "Hatching direction", false}, {"light", "Light", false},         {"shadows", "Ground and shadows", false},
      {"occlusion", "Ambient occlusion", false}, {"strokes", "Painterly strokes", true}, {"lines", "Lines", true},
      {"depth-cue", "Depth cue", false},        {"vignette", "Vignette", false},
  };
  return sections;
}

const Setting* findSetting(const std::string& key) {
  for (const Setting& s : settingsTable())
    if (s.key == key) return &s;
  return nullptr;
}


std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

}  // namespace npr
