// OBJ parsing (see obj_parser.h).
#include "renderer/mesh/obj_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "renderer/mesh/polygon_soup.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

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
  ObjParser(const std::string& path, const std::string& text, PolygonSoup& soup, LoadReport& report)
      : path_(path), text_(text), soup_(soup), report_(report), warn_(report.warnings), faces_(soup, report, warn_) {}

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
        return;
      }
      if (!soup_.addVertex(v)) warn_.add(where(line) + ": vertex has a non-finite coordinate; faces using it are skipped");
    } else if (key == "f") {
      corners_.clear();
      const long long count = static_cast<long long>(soup_.vertices.size());
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
        while (p < e && !isSpace(*p)) ++p;  // the /vt/vn parts are not needed
        // Negative indices count back from the last vertex so far; clamp so no arithmetic overflows.
        corners_.push_back(idx > 0 ? idx - 1 : (idx < -count ? -1 : count + idx));
      }
      faces_.add(corners_, "line", line);
    } else if (key == "mtllib") {
      p = skipSpace(p, e);
      const char* q = e;
      while (q > p && isSpace(q[-1])) --q;
      const std::string name(p, q);
      const fs::path mtl = fs::path(path_).parent_path() / name;
      std::error_code ec;
      if (name.empty() || !fs::exists(mtl, ec))
        warn_.add(where(line) + ": material library '" + name + "' not found; materials are not used anyway");
    } else if (key == "vn" || key == "vt" || key == "vp" || key == "g" || key == "o" || key == "s" ||
               key == "usemtl" || key == "l" || key == "p" || key == "cstype" || key == "deg" ||
               key == "curv" || key == "surf" || key == "parm" || key == "end") {
      // Accepted and not needed: normals are recomputed, texture coordinates are unused
      // (palette textures are applied in screen space), groups and materials do not matter.
    } else {
      if (unknownKeywords_ < 5)
        warn_.add(where(line) + ": unknown statement '" + std::string(key.substr(0, 32)) + "' ignored");
      ++unknownKeywords_;
    }
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
  std::size_t unknownKeywords_ = 0;
};

}  // namespace

namespace {

// Parses into a soup; the caller may free the text before the mesh is built.
Status parseInto(const std::string& path, const std::string& text, PolygonSoup& soup, LoadReport& report) {
  if (Status s = checkText(path, text); !s) return s;
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return Error{path + ": the file is empty"};
  report.file = path;
  soup.vertices.reserve(text.size() / 60);
  soup.vertexValid.reserve(text.size() / 60);
  soup.triangles.reserve(text.size() / 30);
  ObjParser(path, text, soup, report).parse();
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

}  // namespace npr
