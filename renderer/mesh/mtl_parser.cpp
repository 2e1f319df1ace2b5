// The .mtl reader (see mtl_parser.h).
#include "renderer/mesh/mtl_parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "renderer/mesh/polygon_soup.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

struct Line {
  const char* p;
  const char* e;
  void skip() { while (p < e && isSpace(*p)) ++p; }
  std::string_view word() {
    skip();
    const char* s = p;
    while (p < e && !isSpace(*p)) ++p;
    return {s, static_cast<std::size_t>(p - s)};
  }
  bool number(float& out) {
    skip();
    if (p < e && *p == '+') ++p;
    double d = 0.0;
    auto [q, ec] = std::from_chars(p, e, d);
    if (ec != std::errc() || !std::isfinite(d)) return false;
    p = q;
    out = static_cast<float>(std::clamp(d, -1e6, 1e6));
    return true;
  }
  std::string rest() {
    skip();
    const char* q = e;
    while (q > p && isSpace(q[-1])) --q;
    return std::string(p, q);
  }
};

// Texture statement options (map_Kd -s 1 1 1 -clamp on file.png): how many arguments each
// option takes at most; numbers are consumed up to that count, on/off words once.
int optionArguments(std::string_view o) {
  if (o == "-s" || o == "-o" || o == "-t") return 3;
  if (o == "-mm") return 2;
  if (o == "-bm" || o == "-boost" || o == "-texres" || o == "-imfchan" || o == "-clamp" || o == "-blendu" ||
      o == "-blendv" || o == "-cc" || o == "-type")
    return 1;
  return -1;
}

std::string textureFileName(Line line) {
  while (true) {
    line.skip();
    if (line.p >= line.e || *line.p != '-') break;
    Line save = line;
    const std::string_view opt = line.word();
    const int n = optionArguments(opt);
    if (n < 0) { line = save; break; }  // a file name that starts with '-'
    for (int k = 0; k < n; ++k) {
      Line before = line;
      float f;
      if (line.number(f)) continue;
      line = before;
      const std::string_view w = line.word();
      if (k == 0 && (w == "on" || w == "off" || opt == "-imfchan" || opt == "-type")) continue;
      line = before;
      break;
    }
  }
  std::string name = line.rest();
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
  return name;
}

}  // namespace

std::string resolveMaterialFile(const std::string& folder, const std::string& name) {
  std::string n = name;
  std::replace(n.begin(), n.end(), '\\', '/');
  const fs::path given(n);
  const fs::path first = given.is_absolute() ? given : fs::path(folder) / given;
  std::error_code ec;
  if (fs::exists(first, ec)) return first.lexically_normal().string();
  const fs::path alone = fs::path(folder) / given.filename();
  if (!given.filename().empty() && fs::exists(alone, ec)) return alone.lexically_normal().string();
  return first.lexically_normal().string();
}

void parseMtl(const std::string& path, const std::string& text, std::vector<MtlMaterial>& out, Warnings& warn) {
  const std::string folder = fs::path(path).parent_path().string();
  const char* p = text.data();
  const char* end = p + text.size();
  if (end - p >= 3 && std::equal(p, p + 3, "\xEF\xBB\xBF")) p += 3;
  std::size_t lineNo = 0;
  MtlMaterial* cur = nullptr;
  while (p < end) {
    ++lineNo;
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (!eol) eol = end;
    Line line{p, eol};
    p = eol + 1;
    const std::string_view key = line.word();
    if (key.empty() || key[0] == '#') continue;
    const std::string where = path + " line " + std::to_string(lineNo);
    if (key == "newmtl") {
      out.emplace_back();
      cur = &out.back();
      cur->material.name = line.rest();
      cur->where = where;
      if (cur->material.name.empty()) warn.add(where + ": newmtl without a name; the material cannot be used");
      continue;
    }
    const bool known = key == "Ka" || key == "Kd" || key == "Ks" || key == "Ke" || key == "Ns" || key == "d" || key == "Tr" ||
                       key == "illum" || key == "map_Kd" || key == "map_Ka" || key == "map_d";
    if (!known) continue;  // Ni, Tf, bump, refl, PBR statements...: not part of GL's model
    if (!cur) {
      warn.add(where + ": '" + std::string(key) + "' before any newmtl; ignored");
      continue;
    }
    MeshMaterial& m = cur->material;
    auto colour = [&](glm::vec3& c) {
      Line at = line;
      const std::string_view first = at.word();
      if (first == "spectral" || first == "xyz") {
        warn.add(where + ": " + std::string(key) + " " + std::string(first) + " colours are not supported; default kept");
        return;
      }
      glm::vec3 v;
      if (!line.number(v.r)) {
        warn.add(where + ": " + std::string(key) + " needs 1 or 3 numbers; default kept");
        return;
      }
      // One number means grey (the .mtl convention).
      if (!line.number(v.g)) v.g = v.b = v.r;
      else if (!line.number(v.b)) {
        warn.add(where + ": " + std::string(key) + " needs 1 or 3 numbers; default kept");
        return;
      }
      c = glm::clamp(v, glm::vec3(0.0f), glm::vec3(1.0f));
    };
    auto scalar = [&](float& f, float lo, float hi) {
      float v;
      if (!line.number(v)) {
        warn.add(where + ": " + std::string(key) + " needs a number; default kept");
        return false;
      }
      f = std::clamp(v, lo, hi);
      return true;
    };
    if (key == "Ka") colour(m.ambient);
    else if (key == "Kd") colour(m.diffuse);
    else if (key == "Ks") colour(m.specular);
    else if (key == "Ke") colour(m.emission);
    else if (key == "Ns") scalar(m.shininess, 0.0f, 128.0f);  // a Phong exponent; GL's limit is 128
    else if (key == "d") scalar(m.opacity, 0.0f, 1.0f);
    else if (key == "Tr") {
      float t = 0.0f;
      if (scalar(t, 0.0f, 1.0f)) m.opacity = 1.0f - t;
    } else if (key == "illum") {
      float v = 2.0f;
      if (scalar(v, 0.0f, 10.0f)) m.illum = static_cast<int>(v);
    } else {
      const std::string name = textureFileName(line);
      if (name.empty()) {
        warn.add(where + ": " + std::string(key) + " without a file name; ignored");
        continue;
      }
      const std::string resolved = resolveMaterialFile(folder, name);
      (key == "map_Kd" ? cur->diffuseMapPath : key == "map_Ka" ? cur->ambientMapPath : cur->opacityMapPath) = resolved;
    }
  }
}

}  // namespace npr
