// OBJ parsing (see obj_parser.h), with its material libraries (mtl_parser.h).
#include "renderer/mesh/obj_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <utility>
#include <unordered_map>

#include "renderer/core/image_io.h"
#include "renderer/core/input_file.h"
#include "renderer/core/printable.h"
#include "renderer/mesh/mtl_parser.h"
#include "renderer/mesh/opacity_map.h"

#include "renderer/mesh/polygon_soup.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kMaxMaterials = 65535;

Status checkText(const std::string& path, const std::string& data) {
  if (data.size() >= 2 && ((unsigned char)data[0] == 0xFF && (unsigned char)data[1] == 0xFE))
    return Error{path + ": is UTF-16 encoded; save it as UTF-8 or ASCII"};
  if (data.size() >= 2 && ((unsigned char)data[0] == 0xFE && (unsigned char)data[1] == 0xFF))
    return Error{path + ": is UTF-16 encoded; save it as UTF-8 or ASCII"};
  const std::size_t n = std::min<std::size_t>(data.size(), 4096);
  if (std::memchr(data.data(), '\0', n)) return Error{path + ": is a binary file, not a text OBJ"};
  return okStatus();
}

class ObjParser {
 public:
  // `groups`: when given, each triangle's `o` or `g` group, named in `groupNames`.
  ObjParser(const std::string& path, const std::string& text, PolygonSoup& soup, LoadReport& report,
            std::vector<std::uint32_t>* groups = nullptr, std::vector<std::string>* groupNames = nullptr)
      : path_(path), text_(text), soup_(soup), report_(report), warn_(report.warnings), faces_(soup, report, warn_), groups_(groups),
        groupNames_(groupNames) {
    if (groups_) groupNames_->assign(1, "(no group)");
  }

  void parse() {
    const char* p = text_.data();
    const char* end = p + text_.size();
    if (end - p >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;  // UTF-8 byte order mark
    std::size_t line = 0;
    while (p < end) {
      ++line;
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
      if (!eol) eol = end;
      parseLine(p, eol, line);
      p = eol + 1;
    }
    resolveMaterials();
    report_.vertex_colours = !soup_.colours.empty();
    report_.texture_coordinates = soup_.tracksTexcoords;
    warn_.finish();
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

  static const char* skipSpace(const char* p, const char* e) {
    while (p < e && isSpace(*p)) ++p;
    return p;
  }

  std::string where(std::size_t line) const { return path_ + " line " + std::to_string(line); }

  void parseLine(const char* p, const char* e, std::size_t line) {
    p = skipSpace(p, e);
    if (p == e || *p == '#') return;
    const char* kw = p;
    while (p < e && !isSpace(*p)) ++p;
    const std::string_view key(kw, static_cast<size_t>(p - kw));
    if (key == "v") {
      glm::dvec3 v(0.0);
      bool ok = true;
      for (int i = 0; i < 3; ++i) ok = ok && parseDouble(p, e, v[i]);
      if (!ok) {
        warn_.add(where(line) + ": vertex has fewer than 3 numeric coordinates; faces using it are skipped");
        soup_.vertices.push_back(glm::dvec3(0.0));
        soup_.vertexValid.push_back(0);
        if (!soup_.colours.empty()) soup_.colours.push_back(glm::vec3(1.0f));
        return;
      }
      if (!soup_.addVertex(v)) warn_.add(where(line) + ": vertex has a non-finite coordinate; faces using it are skipped");
      // `v x y z r g b`: a vertex colour (a fourth number alone is the rational weight w).
      double extra[4];
      int n = 0;
      while (n < 4 && parseDouble(p, e, extra[n])) ++n;
      if (n >= 3) {
        // Vertices before the first coloured one are white, glColor's default.
        if (soup_.colours.empty()) soup_.colours.assign(soup_.vertices.size() - 1, glm::vec3(1.0f));
        glm::vec3 c(1.0f);
        for (int k = 0; k < 3; ++k) {
          const double x = extra[n - 3 + k];
          c[k] = std::isfinite(x) ? static_cast<float>(std::clamp(x, 0.0, 1.0)) : 1.0f;
        }
        soup_.colours.push_back(c);
      } else if (!soup_.colours.empty()) {
        soup_.colours.push_back(glm::vec3(1.0f));
      }
    } else if (key == "vt") {
      double uv[2] = {0.0, 0.0};
      if (parseDouble(p, e, uv[0])) (void)parseDouble(p, e, uv[1]);
      for (double& x : uv) x = std::isfinite(x) ? std::clamp(x, -1e6, 1e6) : 0.0;
      soup_.texcoords.emplace_back(static_cast<float>(uv[0]), static_cast<float>(uv[1]));
    } else if (key == "f") {
      corners_.clear();
      cornerTex_.clear();
      const long long count = static_cast<long long>(soup_.vertices.size());
      const long long tcount = static_cast<long long>(soup_.texcoords.size());
      bool allTex = true;
      while (true) {
        p = skipSpace(p, e);
        if (p >= e || *p == '#') break;
        long long idx = 0;
        const char* start = p;
        if (*p == '+') ++p;
        auto [q, ec] = std::from_chars(p, e, idx);
        if (ec != std::errc() || idx == 0) {
          warn_.add(where(line) + ": face has a malformed index '" + std::string(start, std::min<const char*>(e, start + 16)) + "'; face skipped");
          ++report_.skipped_faces;
          return;
        }
        p = q;
        // Negative indices count back from the last vertex so far; clamp so no arithmetic overflows.
        corners_.push_back(idx > 0 ? idx - 1 : (idx < -count ? -1 : count + idx));
        long long t = 0;  // v/vt/vn: the texture coordinate, if any
        if (p < e && *p == '/') {
          ++p;
          if (p < e && *p == '+') ++p;
          auto [q2, ec2] = std::from_chars(p, e, t);
          if (ec2 == std::errc()) p = q2;
          else t = 0;
        }
        while (p < e && !isSpace(*p)) ++p;  // the normal index is not needed: normals are recomputed
        long long ti = t > 0 ? t - 1 : (t < 0 ? (t < -tcount ? tcount : tcount + t) : -1);
        if (ti >= tcount) {
          if (!texWarned_)
            warn_.add(where(line) + ": face references texture coordinate " + std::to_string(t) + " but only " + std::to_string(tcount) +
                      " are defined; such faces have no texture coordinates");
          texWarned_ = true;
          ti = -1;
        }
        allTex = allTex && ti >= 0;
        cornerTex_.push_back(ti >= 0 ? static_cast<int>(std::min<long long>(ti, std::numeric_limits<int>::max())) : -1);
      }
      if (allTex && !cornerTex_.empty() && !soup_.tracksTexcoords) soup_.trackTexcoords();
      if (!allTex) cornerTex_.clear();
      faces_.add(corners_, cornerTex_, currentMaterial_, "line", line);
      if (groups_) groups_->resize(soup_.triangles.size(), currentGroup_);
    } else if (groups_ && (key == "o" || key == "g")) {
      // A group seen again continues its object.
      std::string name = restOfLine(p, e);
      if (name.empty()) name = "group " + std::to_string(groupNames_->size());
      const auto it = std::find(groupNames_->begin(), groupNames_->end(), name);
      if (it != groupNames_->end()) {
        currentGroup_ = static_cast<std::uint32_t>(it - groupNames_->begin());
      } else if (groupNames_->size() >= kMaxGroups) {
        if (!groupsWarned_) warn_.add(where(line) + ": more than " + std::to_string(kMaxGroups) + " groups; the rest join the last");
        groupsWarned_ = true;
      } else {
        currentGroup_ = static_cast<std::uint32_t>(groupNames_->size());
        groupNames_->push_back(name);
      }
    } else if (key == "usemtl") {
      useMaterial(restOfLine(p, e), line);
    } else if (key == "mtllib") {
      readLibraries(restOfLine(p, e), line);
    } else if (key == "vn" || key == "vp" || key == "g" || key == "o" || key == "s" || key == "l" || key == "p" ||
               key == "cstype" || key == "deg" || key == "curv" || key == "surf" || key == "parm" || key == "end") {
      // Accepted and not needed: normals are recomputed, groups do not matter.
    } else {
      if (unknownKeywords_ < 5)
        warn_.add(where(line) + ": unknown statement '" + std::string(key.substr(0, 32)) + "' ignored");
      ++unknownKeywords_;
    }
  }

  static std::string restOfLine(const char* p, const char* e) {
    p = skipSpace(p, e);
    const char* q = e;
    while (q > p && isSpace(q[-1])) --q;
    return std::string(p, q);
  }

  void useMaterial(const std::string& name, std::size_t line) {
    if (!soup_.tracksMaterials) {
      soup_.trackMaterials();
      // Material 0: faces before any usemtl, drawn with the lighting state's material.
      soup_.materials.emplace_back();
      soup_.materials[0].name = "(default)";
      soup_.materials[0].fromLightingState = true;
    }
    auto it = materialIndex_.find(name);
    if (it == materialIndex_.end()) {
      if (soup_.materials.size() >= kMaxMaterials) {
        if (!materialsWarned_) warn_.add(where(line) + ": more than " + std::to_string(kMaxMaterials - 1) + " materials; the rest use the default");
        materialsWarned_ = true;
        currentMaterial_ = 0;
        return;
      }
      it = materialIndex_.emplace(name, static_cast<std::uint16_t>(soup_.materials.size())).first;
      soup_.materials.emplace_back();
      soup_.materials.back().name = name;
      firstUse_.push_back(where(line));
    }
    currentMaterial_ = it->second;
  }

  // `mtllib a.mtl b.mtl`: several libraries, or one whose name has spaces (tried first).
  void readLibraries(const std::string& names, std::size_t line) {
    if (names.empty()) {
      warn_.add(where(line) + ": mtllib without a file name");
      return;
    }
    const std::string folder = fs::path(path_).parent_path().string();
    std::vector<std::string> files;
    std::error_code ec;
    if (fs::exists(resolveMaterialFile(folder, names), ec)) {
      files.push_back(names);
    } else {
      std::size_t a = 0;
      while (a < names.size()) {
        while (a < names.size() && isSpace(names[a])) ++a;
        std::size_t b = a;
        while (b < names.size() && !isSpace(names[b])) ++b;
        if (b > a) files.push_back(names.substr(a, b - a));
        a = b;
      }
    }
    for (const std::string& name : files) {
      const std::string file = resolveMaterialFile(folder, name);
      auto& libs = report_.material_libraries;
      if (std::find(libs.begin(), libs.end(), file) != libs.end()) continue;
      Result<std::string> text = readInputFile(file, InputKind::MaterialLibrary);
      if (!text) {
        warn_.add(where(line) + ": material library '" + name + "' cannot be read (" + text.error() + "); its materials use the default");
        continue;
      }
      libs.push_back(file);
      parseMtl(file, *text, library_, warn_);
    }
  }

  // The material's transparency, as Blender's importer reads it: `d` (or 1 - `Tr`) times map_d
  // is the surface's alpha, drawn as screen-door transparency (MeshMaterial::Alpha::Blend; a
  // map_d of black and white is a cut-out). map_d is folded into the diffuse map's alpha, the
  // one map coverage reads (opacity_map.h), each pair of maps once. A material with no opacity
  // at all and no map would vanish: `Tr 1` is what exporters that write Tr the other way round
  // mean by opaque, so it is drawn opaque with a warning.
  void transparency(MeshMaterial& m, const std::string& where) {
    if (m.opacityMap < 0 && !(m.opacity < 1.0f)) return;
    if (m.opacityMap < 0 && m.opacity <= 0.0f) {
      warn_.add(where + ": material '" + m.name + "' is wholly transparent (d 0 or Tr 1); drawn opaque, as some exporters write Tr "
                "the other way round");
      m.opacity = 1.0f;
      return;
    }
    m.alpha = MeshMaterial::Alpha::Blend;
    if (m.opacityMap < 0) return;
    const std::pair<int, int> key{m.diffuseMap, m.opacityMap};
    auto it = combinedMaps_.find(key);
    if (it == combinedMaps_.end()) {
      int index = -1;
      if (soup_.textures.size() >= kMaxModelTextures) {
        warn_.add(where + ": more than " + std::to_string(kMaxModelTextures) + " texture maps; material '" + m.name +
                  "' is drawn without its opacity map");
      } else {
        const MeshTexture& opacity = soup_.textures[std::size_t(m.opacityMap)];
        const ImageRGBA8* colour = m.diffuseMap >= 0 ? &soup_.textures[std::size_t(m.diffuseMap)].image : nullptr;
        MeshTexture combined{(m.diffuseMap >= 0 ? soup_.textures[std::size_t(m.diffuseMap)].path + " with " : "") + opacity.path,
                             withOpacityMap(colour, opacity.image)};
        index = static_cast<int>(soup_.textures.size());
        soup_.textures.push_back(std::move(combined));
      }
      it = combinedMaps_.emplace(key, index).first;
    }
    if (it->second < 0) return;
    m.diffuseMap = it->second;
    m.opacityMap = -1;  // drawn through the folded map: the maps apart are not uploaded
  }

  // The maps no material draws any more (folded into another: transparency), so they are
  // neither kept nor uploaded; they stay in the report's list of maps loaded.
  void dropUnusedTextures() {
    std::vector<int> remap(soup_.textures.size(), -1);
    for (const MeshMaterial& m : soup_.materials)
      for (int map : {m.diffuseMap, m.opacityMap})
        if (map >= 0) remap[std::size_t(map)] = 0;
    std::vector<MeshTexture> kept;
    for (std::size_t t = 0; t < soup_.textures.size(); ++t)
      if (remap[t] == 0) {
        remap[t] = static_cast<int>(kept.size());
        kept.push_back(std::move(soup_.textures[t]));
      }
    soup_.textures = std::move(kept);
    for (MeshMaterial& m : soup_.materials)
      for (int* map : {&m.diffuseMap, &m.opacityMap})
        if (*map >= 0) *map = remap[std::size_t(*map)];
  }

  // Gives the used materials the values their libraries define (whichever of usemtl and
  // mtllib came first), and loads their texture maps, each file once.
  void resolveMaterials() {
    if (!soup_.tracksMaterials) return;
    std::unordered_map<std::string, const MtlMaterial*> defined;
    for (const MtlMaterial& m : library_) defined.emplace(m.material.name, &m);  // the first definition wins
    std::unordered_map<std::string, int> textureIndex;
    auto texture = [&](const std::string& file, const std::string& where) -> int {
      if (file.empty()) return -1;
      if (auto it = textureIndex.find(file); it != textureIndex.end()) return it->second;
      int index = -1;
      if (soup_.textures.size() >= kMaxModelTextures) {
        warn_.add(where + ": more than " + std::to_string(kMaxModelTextures) + " texture maps; '" + file + "' is not used");
      } else if (Result<ImageRGBA8> img = loadImage(file, {kMaxModelTextureSide, kMaxModelTextureSide}); !img) {
        warn_.add(where + ": texture map cannot be used (" + img.error() + "); the material is drawn without it");
        report_.textures_missing.push_back(file);
      } else {
        index = static_cast<int>(soup_.textures.size());
        soup_.textures.push_back({file, std::move(*img)});
        report_.textures_loaded.push_back(file);
      }
      textureIndex.emplace(file, index);
      return index;
    };
    for (std::size_t i = 1; i < soup_.materials.size(); ++i) {
      MeshMaterial& m = soup_.materials[i];
      auto it = defined.find(m.name);
      if (it == defined.end()) {
        warn_.add(firstUse_[i - 1] + ": material '" + m.name + "' is not defined in any material library; drawn with the default material");
        m.fromLightingState = true;
        continue;
      }
      const MtlMaterial& def = *it->second;
      m = def.material;
      // illum 0: a constant colour (Kd, unlit); 1: no specular highlight.
      if (m.illum == 0) {
        m.emission = m.diffuse;
        m.ambient = m.diffuse = m.specular = glm::vec3(0.0f);
      } else if (m.illum == 1) {
        m.specular = glm::vec3(0.0f);
      }
      // Ns 0 (what many exporters write for "no gloss") would make GL's highlight cover the
      // whole lit side (x^0 = 1): no modeller means that, and Blender's importer reads it as
      // fully rough. Below an exponent of 1 there is no highlight.
      if (m.shininess < 1.0f) m.specular = glm::vec3(0.0f);
      m.diffuseMap = texture(def.diffuseMapPath.empty() ? def.ambientMapPath : def.diffuseMapPath, def.where);
      m.opacityMap = texture(def.opacityMapPath, def.where);
      transparency(m, def.where);
    }
    if (!combinedMaps_.empty()) dropUnusedTextures();
    report_.materials = soup_.materials.size() - 1;
  }

  bool parseDouble(const char*& p, const char* e, double& out) {
    p = skipSpace(p, e);
    if (p < e && *p == '+') ++p;
    auto [q, ec] = std::from_chars(p, e, out);
    if (ec == std::errc::result_out_of_range) {
      // from_chars leaves `out` unset on overflow: treat it as infinite so the vertex is refused.
      out = std::numeric_limits<double>::infinity();
      while (q < e && !isSpace(*q)) ++q;
      p = q;
      return true;
    }
    if (ec != std::errc()) return false;
    p = q;
    return true;
  }

  const std::string& path_;
  const std::string& text_;
  PolygonSoup& soup_;
  LoadReport& report_;
  Warnings warn_;
  FaceBuilder faces_;
  std::vector<long long> corners_;
  std::vector<int> cornerTex_;
  std::size_t unknownKeywords_ = 0;
  std::uint16_t currentMaterial_ = 0;
  std::unordered_map<std::string, std::uint16_t> materialIndex_;
  std::vector<std::string> firstUse_;  // where each material (after the default) was first used
  std::vector<MtlMaterial> library_;
  std::map<std::pair<int, int>, int> combinedMaps_;  // (diffuse map, opacity map) -> their folded map
  bool texWarned_ = false, materialsWarned_ = false;
  static constexpr std::size_t kMaxGroups = 4096;
  std::vector<std::uint32_t>* groups_;
  std::vector<std::string>* groupNames_;
  std::uint32_t currentGroup_ = 0;
  bool groupsWarned_ = false;
};

}  // namespace

namespace {

// Parses into a soup; the caller may free the text before the mesh is built.
Status parseInto(const std::string& path, const std::string& text, PolygonSoup& soup, LoadReport& report,
                 std::vector<std::uint32_t>* groups = nullptr, std::vector<std::string>* groupNames = nullptr) {
  if (Status s = checkText(path, text); !s) return s;
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return Error{path + ": the file is empty"};
  report.file = path;
  soup.vertices.reserve(text.size() / 60);
  soup.vertexValid.reserve(text.size() / 60);
  soup.triangles.reserve(text.size() / 30);
  ObjParser(path, text, soup, report, groups, groupNames).parse();
  return okStatus();
}

}  // namespace

Result<Mesh> parseObj(const std::string& path, std::string text) {
  LoadReport report;
  PolygonSoup soup;
  if (Status s = parseInto(path, text, soup, report); !s) return Error{s.error()};
  // 34 MB for the 871K-triangle model, not needed while building. (Assigning an empty string
  // would keep the buffer: libstdc++ moves a short string in by copying it.)
  std::string().swap(text);
  return buildMesh(std::move(soup), std::move(report));
}

Result<std::vector<ObjObject>> parseObjObjects(const std::string& path, std::string text) {
  LoadReport report;
  PolygonSoup soup;
  std::vector<std::uint32_t> groups;
  std::vector<std::string> names;
  if (Status s = parseInto(path, text, soup, report, &groups, &names); !s) return Error{s.error()};
  std::string().swap(text);
  groups.resize(soup.triangles.size(), 0);
  std::vector<PolygonSoup> parts = splitSoup(std::move(soup), groups, names.size());
  std::vector<ObjObject> out;
  for (std::size_t g = 0; g < parts.size(); ++g) {
    if (parts[g].triangles.empty()) continue;
    LoadReport r = report;
    r.warnings.clear();  // the file's warnings are reported once, with the first object
    if (out.empty()) r.warnings = report.warnings;
    Result<Mesh> m = buildMesh(std::move(parts[g]), std::move(r));
    if (!m) continue;  // a group of degenerate faces only: nothing to draw
    out.push_back({printable(names[g]), std::move(*m)});
  }
  if (out.empty()) return Error{path + ": contains no faces that could be drawn"};
  return out;
}

}  // namespace npr
