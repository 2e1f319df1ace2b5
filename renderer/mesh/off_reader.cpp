// The OFF reader (see mesh_formats.h): "[ST][C][N]OFF", then vertex, face and edge counts,
// one vertex per line (extra values such as colours ignored), one face per line ("n i0 .. in-1",
// a colour may follow). Binary OFF and the 4D/nD variants are refused with a message.
#include <string_view>

#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/polygon_soup.h"
#include "renderer/mesh/text_cursor.h"

namespace npr {

Result<Mesh> parseOff(const std::string& name, std::string bytes) {
  TextCursor in(bytes.data(), bytes.data() + bytes.size());
  auto at = [&](const std::string& what) { return Error{name + " line " + std::to_string(in.line()) + ": " + what}; };
  std::string_view magic = in.token();
  for (std::string_view prefix : {"ST", "C", "N"})
    if (magic.substr(0, prefix.size()) == prefix && magic.size() > prefix.size()) magic.remove_prefix(prefix.size());
  if (magic != "OFF") {
    if (magic.size() >= 3 && magic.substr(magic.size() - 3) == "OFF")
      return at("the OFF variant '" + std::string(magic.substr(0, 16)) + "' (4D or n-dimensional) is not supported");
    return Error{name + ": not an OFF file (it does not start with 'OFF')"};
  }
  if (!in.atEndOfLine()) {
    const char* keep = in.position();
    if (in.token() == "BINARY") return at("binary OFF is not supported; save it as ASCII OFF, PLY or OBJ");
    in = TextCursor(keep, bytes.data() + bytes.size());
  }
  unsigned long long nv = 0, nf = 0, ne = 0;
  in.skipSpaceAndComments();
  if (!in.integer(nv) || !in.integer(nf)) return at("expected the vertex and face counts after 'OFF'");
  if (!in.integer(ne)) ne = 0;  // the edge count is optional in practice and unused
  // Each vertex line holds at least "0 0 0" and each face "3 0 1 2", so counts the file cannot
  // hold are refused before anything is allocated.
  const std::size_t left = static_cast<std::size_t>(bytes.data() + bytes.size() - in.position());
  if (nv > left / 5 + 1 || nf > left / 7 + 1)
    return at(std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces cannot fit in the " +
              std::to_string(left) + " bytes that follow: the header is corrupt or the file truncated");
  LoadReport report;
  report.file = name;
  Warnings warn(report.warnings);
  PolygonSoup soup;
  soup.vertices.reserve(nv);
  soup.vertexValid.reserve(nv);
  soup.triangles.reserve(nf);
  for (unsigned long long i = 0; i < nv; ++i) {
    in.skipSpaceAndComments();
    glm::dvec3 v(0.0);
    if (!in.number(v.x) || !in.number(v.y) || !in.number(v.z))
      return at("vertex " + std::to_string(i) + " of " + std::to_string(nv) + " is missing or has fewer than 3 numbers");
    if (!soup.addVertex(v)) warn.add(name + " line " + std::to_string(in.line()) + ": vertex has a non-finite coordinate; faces using it are skipped");
    in.skipLine();
  }
  FaceBuilder faces(soup, report, warn);
  std::vector<long long> corners;
  for (unsigned long long f = 0; f < nf; ++f) {
    in.skipSpaceAndComments();
    unsigned long long n = 0;
    if (!in.integer(n)) {
      if (in.atEnd()) {
        warn.add(name + ": the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces (truncated?)");
        break;
      }
      return at("face " + std::to_string(f) + ": expected its corner count");
    }
    if (n > nv) return at("face " + std::to_string(f) + " has " + std::to_string(n) + " corners, more than the " + std::to_string(nv) + " vertices");
    corners.clear();
    const std::size_t line = in.line();
    bool ok = true;
    for (unsigned long long k = 0; k < n && ok; ++k) {
      long long idx = 0;
      ok = in.integer(idx);
      corners.push_back(idx);
    }
    in.skipLine();
    if (!ok) {
      warn.add(name + " line " + std::to_string(line) + ": face has fewer indices than its count says; face skipped");
      ++report.skipped_faces;
      continue;
    }
    faces.add(corners, "line", line);
  }
  warn.finish();
  std::string().swap(bytes);  // not needed while building
  return buildMesh(std::move(soup), std::move(report));
}

}  // namespace npr
