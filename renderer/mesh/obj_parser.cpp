// OBJ parsing (see obj_parser.h).
#include "renderer/mesh/obj_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "renderer/mesh/mesh_builder.h"
#include "renderer/mesh/polygon_triangulation.h"

namespace npr {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kMaxWarnings = 50;

struct Warnings {
  std::vector<std::string>& out;
  std::size_t dropped = 0;
  void add(std::string w) {
    if (out.size() < kMaxWarnings) out.push_back(std::move(w));
    else ++dropped;
  }
  void finish() {
    if (dropped) out.push_back("... and " + std::to_string(dropped) + " more warnings");
  }
};

// Checks that `path` names a readable regular file and reads it whole.
Result<std::string> readWholeFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) return Error{path + ": no such file"};
  if (fs::is_directory(st)) return Error{path + ": is a directory, not a mesh file"};
  if (!fs::is_regular_file(st)) return Error{path + ": not a regular file"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path + ": cannot be opened for reading (permissions?)"};
  std::string data;
  const auto size = fs::file_size(path, ec);
  if (!ec) data.reserve(size);
  data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return Error{path + ": read error"};
  return data;
}

Status checkText(const std::string& path, const std::string& data) {
  if (data.size() >= 2 && ((unsigned char)data[0] == 0xFF && (unsigned char)data[1] == 0xFE))
    return Error{path + ": is UTF-16 encoded; save it as UTF-8 or ASCII"};
  if (data.size() >= 2 && ((unsigned char)data[0] == 0xFE && (unsigned char)data[1] == 0xFF))
    return Error{path + ": is UTF-16 encoded; save it as UTF-8 or ASCII"};
  const std::size_t n = std::min<std::size_t>(data.size(), 4096);
  if (std::memchr(data.data(), '\0', n)) return Error{path + ": is a binary file, not a text OBJ"};
  return okStatus();
}

struct ObjData {
  std::vector<glm::dvec3> vertices;
  std::vector<char> vertexValid;
  std::vector<std::array<int, 3>> triangles;  // 0-based
};

class ObjParser {
 public:
  ObjParser(const std::string& path, const std::string& text, LoadReport& report)
      : path_(path), text_(text), report_(report), warn_{report.warnings} {}

  Status parse(ObjData& out) {
    const char* p = text_.data();
    const char* end = p + text_.size();
    if (end - p >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;  // UTF-8 byte order mark
    std::size_t line = 0;
    std::vector<int> face;
    std::vector<glm::dvec3> poly;
    while (p < end) {
      ++line;
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
      if (!eol) eol = end;
      parseLine(p, eol, line, out, face, poly);
      p = eol + 1;
    }
    warn_.finish();
    return okStatus();
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

  static const char* skipSpace(const char* p, const char* e) {
    while (p < e && isSpace(*p)) ++p;
    return p;
  }

  std::string where(std::size_t line) const { return path_ + " line " + std::to_string(line); }

  void parseLine(const char* p, const char* e, std::size_t line, ObjData& out, std::vector<int>& face,
                 std::vector<glm::dvec3>& poly) {
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
        out.vertices.push_back(glm::dvec3(0.0));
        out.vertexValid.push_back(0);
        return;
      }
      const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
      if (!finite) warn_.add(where(line) + ": vertex has a non-finite coordinate; faces using it are skipped");
      out.vertices.push_back(finite ? v : glm::dvec3(0.0));
      out.vertexValid.push_back(finite ? 1 : 0);
    } else if (key == "f") {
      face.clear();
      while (true) {
        p = skipSpace(p, e);
        if (p >= e || *p == '#') break;
        long idx = 0;
        const char* start = p;
        if (*p == '+') ++p;
        auto [q, ec] = std::from_chars(p, e, idx);
        if (ec != std::errc() ) {
          warn_.add(where(line) + ": face has a malformed index '" + std::string(start, std::min<const char*>(e, start + 16)) + "'; face skipped");
          ++report_.skipped_faces;
          return;
        }
        p = q;
        while (p < e && !isSpace(*p)) ++p;  // the /vt/vn parts are not needed
        const long count = static_cast<long>(out.vertices.size());
        const long resolved = idx > 0 ? idx - 1 : count + idx;  // negative indices are relative
        if (idx == 0 || resolved < 0 || resolved >= count) {
          warn_.add(where(line) + ": face references vertex " + std::to_string(idx) + " but only " +
                    std::to_string(count) + " vertices are defined so far; face skipped");
          ++report_.skipped_faces;
          return;
        }
        if (!out.vertexValid[static_cast<size_t>(resolved)]) {
          warn_.add(where(line) + ": face uses an invalid vertex; face skipped");
          ++report_.skipped_faces;
          return;
        }
        face.push_back(static_cast<int>(resolved));
      }
      if (face.size() < 3) {
        warn_.add(where(line) + ": face has fewer than 3 vertices; skipped");
        ++report_.skipped_faces;
        return;
      }
      if (face.size() == 3) {
        out.triangles.push_back({face[0], face[1], face[2]});
        return;
      }
      ++report_.polygons_triangulated;
      poly.clear();
      for (int i : face) poly.push_back(out.vertices[static_cast<size_t>(i)]);
      const std::vector<int> tri = triangulatePolygon(poly);
      for (size_t k = 0; k + 2 < tri.size(); k += 3)
        out.triangles.push_back({face[static_cast<size_t>(tri[k])], face[static_cast<size_t>(tri[k + 1])], face[static_cast<size_t>(tri[k + 2])]});
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
  LoadReport& report_;
  Warnings warn_;
  std::size_t unknownKeywords_ = 0;
};

}  // namespace

Result<Mesh> loadObj(const std::string& path) {
  Result<std::string> text = readWholeFile(path);
  if (!text) return Error{text.error()};
  if (Status s = checkText(path, *text); !s) return Error{s.error()};
  Mesh m;
  m.report.file = path;
  ObjData data;
  data.vertices.reserve(text->size() / 60);
  data.triangles.reserve(text->size() / 30);
  ObjParser parser(path, *text, m.report);
  if (Status s = parser.parse(data); !s) return Error{s.error()};
  if (data.triangles.empty()) {
    if (text->find_first_not_of(" \t\r\n") == std::string::npos) return Error{path + ": the file is empty"};
    return Error{path + ": contains no faces (" + std::to_string(data.vertices.size()) +
                 " vertices, but no 'f' lines that could be used); nothing to draw"};
  }
  std::vector<glm::vec3> verts = normalizePositions(data.vertices, &data.vertexValid, m.report);
  buildTriMesh(verts, data.triangles, m);
  return m;
}

}  // namespace npr
