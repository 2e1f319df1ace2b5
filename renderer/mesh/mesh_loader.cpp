// Mesh file loading (see mesh_loader.h). The OBJ parser is our own because OpenMesh's reader
// loses data we must keep: it reads floats (a model offset by 1e7 loses its shape), fans
// concave polygons, and drops faces its halfedge structure refuses.
#include "renderer/mesh/mesh_loader.h"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "renderer/core/json.h"
#include "renderer/mesh/mesh_generators.h"

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

// ---------------------------------------------------------------------------------------
// [SECTION] Polygon triangulation

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool pointInTriangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double d1 = cross2(a, b, p), d2 = cross2(b, c, p), d3 = cross2(c, a, p);
  return d1 >= 0 && d2 >= 0 && d3 >= 0;
}

}  // namespace

std::vector<int> triangulatePolygon(const std::vector<glm::dvec3>& poly) {
  const int n = static_cast<int>(poly.size());
  std::vector<int> tris;
  if (n < 3) return tris;
  tris.reserve(static_cast<size_t>(n - 2) * 3);
  if (n == 3) return {0, 1, 2};
  // Newell normal gives the polygon's plane even for concave polygons; drop its largest axis.
  glm::dvec3 nrm(0.0);
  for (int i = 0; i < n; ++i) {
    const glm::dvec3& a = poly[i];
    const glm::dvec3& b = poly[(i + 1) % n];
    nrm.x += (a.y - b.y) * (a.z + b.z);
    nrm.y += (a.z - b.z) * (a.x + b.x);
    nrm.z += (a.x - b.x) * (a.y + b.y);
  }
  const glm::dvec3 an = glm::abs(nrm);
  const int drop = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = nrm[drop] >= 0 ? 1.0 : -1.0;  // makes the projected polygon counter-clockwise
  std::vector<glm::dvec2> p(n);
  for (int i = 0; i < n; ++i) p[i] = {poly[i][u], poly[i][v] * sign};

  std::vector<int> ring(n);
  for (int i = 0; i < n; ++i) ring[i] = i;
  int guard = 0;
  while (ring.size() > 3 && guard < n * n) {
    ++guard;
    bool clipped = false;
    const int m = static_cast<int>(ring.size());
    for (int k = 0; k < m; ++k) {
      const int i0 = ring[(k + m - 1) % m], i1 = ring[k], i2 = ring[(k + 1) % m];
      if (cross2(p[i0], p[i1], p[i2]) <= 0) continue;  // reflex or degenerate corner
      bool inside = false;
      for (int j : ring) {
        if (j == i0 || j == i1 || j == i2) continue;
        if (pointInTriangle(p[j], p[i0], p[i1], p[i2])) { inside = true; break; }
      }
      if (inside) continue;
      tris.insert(tris.end(), {i0, i1, i2});
      ring.erase(ring.begin() + k);
      clipped = true;
      break;
    }
    if (!clipped) break;  // degenerate or self-intersecting: finish with a fan below
  }
  // What is left (a triangle, or a polygon with no ear) is fanned so coverage stays n-2 triangles.
  for (size_t k = 1; k + 1 < ring.size(); ++k) tris.insert(tris.end(), {ring[0], ring[k], ring[k + 1]});
  return tris;
}

namespace {

// ---------------------------------------------------------------------------------------
// [SECTION] OBJ parsing

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

// Adds triangles to the halfedge mesh; faces it refuses (complex edges, duplicates, flipped
// neighbours, repeated corners) are drawn on their own copies of the vertices and counted.
void buildTriMesh(const std::vector<glm::vec3>& verts, const std::vector<std::array<int, 3>>& tris, Mesh& m) {
  TriMesh& mesh = m.mesh;
  mesh.reserve(verts.size(), tris.size() * 3 / 2 + 16, tris.size());
  std::vector<TriMesh::VertexHandle> vh(verts.size());
  for (size_t i = 0; i < verts.size(); ++i) vh[i] = mesh.add_vertex(TriMesh::Point(verts[i].x, verts[i].y, verts[i].z));
  std::size_t refused = 0;
  // OpenMesh prints an error line for each refused face; we count them in the report instead.
  auto& errlog = omerr();
  errlog.disable();
  for (const auto& t : tris) {
    const auto fh = mesh.add_face(vh[static_cast<size_t>(t[0])], vh[static_cast<size_t>(t[1])], vh[static_cast<size_t>(t[2])]);
    if (fh.is_valid()) continue;
    ++refused;
    TriMesh::VertexHandle c[3];
    for (int k = 0; k < 3; ++k) {
      const TriMesh::Point p = mesh.point(vh[static_cast<size_t>(t[k])]);  // a copy: add_vertex may reallocate the points
      c[k] = mesh.add_vertex(p);
    }
    mesh.add_face(c[0], c[1], c[2]);
  }
  errlog.enable();
  m.report.non_manifold_faces = refused;
  if (refused)
    m.report.warnings.push_back(std::to_string(refused) +
                                " faces were refused by the halfedge structure (non-manifold edge, duplicate or "
                                "inconsistently oriented face); they are drawn on copied vertices");
}

// Centres the model on its bounding-box centre and scales it into the unit sphere, in double
// precision, before anything becomes float.
std::vector<glm::vec3> normalizePositions(const std::vector<glm::dvec3>& in, const std::vector<char>* valid, LoadReport& report) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (size_t i = 0; i < in.size(); ++i) {
    if (valid && !(*valid)[i]) continue;
    lo = glm::min(lo, in[i]);
    hi = glm::max(hi, in[i]);
  }
  if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);
  const glm::dvec3 centre = (lo + hi) * 0.5;
  double radius = 0.0;
  for (size_t i = 0; i < in.size(); ++i)
    if (!valid || (*valid)[i]) radius = std::max(radius, glm::length(in[i] - centre));
  const double scale = radius > 0.0 && std::isfinite(1.0 / radius) ? 1.0 / radius : 1.0;
  report.original_centre = centre;
  report.original_scale = scale;
  std::vector<glm::vec3> out(in.size());
  for (size_t i = 0; i < in.size(); ++i) out[i] = glm::vec3((in[i] - centre) * scale);
  return out;
}

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

Result<Mesh> loadWithOpenMesh(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path + ": no such file"};
  if (fs::is_directory(path, ec)) return Error{path + ": is a directory, not a mesh file"};
  if (fs::file_size(path, ec) == 0) return Error{path + ": the file is empty"};
  Mesh m;
  m.report.file = path;
  TriMesh raw;
  OpenMesh::IO::Options opt;
  auto& errlog = omerr();
  errlog.disable();
  const bool ok = OpenMesh::IO::read_mesh(raw, path, opt);
  errlog.enable();
  if (!ok) return Error{path + ": OpenMesh could not read this file (corrupt, or not the format its extension says)"};
  if (raw.n_faces() == 0) return Error{path + ": contains no faces; nothing to draw"};
  std::vector<glm::dvec3> pts(raw.n_vertices());
  for (auto v : raw.vertices()) {
    const auto& p = raw.point(v);
    pts[static_cast<size_t>(v.idx())] = {p[0], p[1], p[2]};
  }
  std::vector<std::array<int, 3>> tris;
  tris.reserve(raw.n_faces());
  for (auto f : raw.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : raw.fv_range(f)) if (k < 3) t[static_cast<size_t>(k++)] = v.idx();
    tris.push_back(t);
  }
  m.report.warnings.push_back("read through OpenMesh's " + fs::path(path).extension().string() +
                              " reader: coordinates are single precision and faces it refused are not counted");
  std::vector<glm::vec3> verts = normalizePositions(pts, nullptr, m.report);
  buildTriMesh(verts, tris, m);
  return m;
}

}  // namespace

std::string LoadReport::toJson() const {
  std::ostringstream o;
  o << "{\"file\":" << json::string(file) << ",\"vertices\":" << vertices << ",\"triangles\":" << triangles
    << ",\"polygons_triangulated\":" << polygons_triangulated << ",\"skipped_faces\":" << skipped_faces
    << ",\"non_manifold_faces\":" << non_manifold_faces << ",\"warnings\":[";
  for (size_t i = 0; i < warnings.size(); ++i) o << (i ? "," : "") << json::string(warnings[i]);
  o << "],\"load_ms\":" << json::number(load_ms, "%.3f") << "}";
  return o.str();
}

Result<Mesh> loadMesh(const std::string& path) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Result<Mesh> m = Error{""};
  if (ext == ".obj") m = loadObj(path);
  else if (ext == ".ply" || ext == ".off" || ext == ".stl" || ext == ".om") m = loadWithOpenMesh(path);
  else {
    std::error_code ec;
    if (!fs::exists(path, ec)) return Error{path + ": no such file"};
    if (fs::is_directory(path, ec)) return Error{path + ": is a directory, not a mesh file"};
    return Error{path + ": unsupported mesh format '" + ext + "' (use .obj, .ply, .off, .stl or .om)"};
  }
  if (!m) return m;
  finalizeMesh(*m);
  m->report.load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

Result<Mesh> loadModel(const std::string& nameOrPath) {
  if (std::optional<Mesh> generated = generatedMesh(nameOrPath)) return std::move(*generated);
  return loadMesh(nameOrPath);
}

}  // namespace npr
