// The STL reader (see mesh_formats.h). Binary when the file is exactly the size its triangle
// count says (84 + 50 n bytes: some binary files also begin with "solid"), ASCII when it begins
// with "solid", refused otherwise. STL repeats every corner per facet, so corners with the
// same coordinates are welded into one vertex (as OpenMesh's reader does), which gives smooth
// normals and the adjacency that feature lines need. Facet normals in the file are ignored.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "renderer/mesh/mesh_formats.h"
#include "renderer/mesh/polygon_soup.h"
#include "renderer/mesh/text_cursor.h"

namespace npr {
namespace {

struct PointKey {
  std::uint64_t x, y, z;
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
    h ^= k.y + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h ^= k.z + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

// Welds corners by exact coordinates (+0 and -0 are one point).
class Welder {
 public:
  explicit Welder(PolygonSoup& soup) : soup_(soup) {}
  long long index(glm::dvec3 p) {
    for (int k = 0; k < 3; ++k) if (p[k] == 0.0) p[k] = 0.0;
    PointKey key{};
    std::memcpy(&key.x, &p.x, 8);
    std::memcpy(&key.y, &p.y, 8);
    std::memcpy(&key.z, &p.z, 8);
    auto [it, inserted] = map_.try_emplace(key, static_cast<long long>(soup_.vertices.size()));
    if (inserted) soup_.addVertex(p);
    return it->second;
  }
  void reserve(std::size_t n) { map_.reserve(n); }

 private:
  PolygonSoup& soup_;
  std::unordered_map<PointKey, long long, PointKeyHash> map_;
};

float readFloatLE(const unsigned char* b) {
  const std::uint32_t u = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

Result<Mesh> parseBinary(const std::string& name, std::string bytes, std::uint32_t n) {
  LoadReport report;
  report.file = name;
  Warnings warn(report.warnings);
  PolygonSoup soup;
  Welder weld(soup);
  soup.triangles.reserve(n);
  weld.reserve(std::size_t(n) / 2 + 16);
  FaceBuilder faces(soup, report, warn);
  std::vector<long long> corners;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + 84;
  std::size_t nonFinite = 0;
  for (std::uint32_t t = 0; t < n; ++t) {
    const unsigned char* f = data + std::size_t(t) * 50 + 12;  // skip the facet normal
    corners.clear();
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p(readFloatLE(f + 12 * k), readFloatLE(f + 12 * k + 4), readFloatLE(f + 12 * k + 8));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) finite = false;
      else corners.push_back(weld.index(p));
    }
    if (!finite) {
      ++nonFinite;
      ++report.skipped_faces;
      continue;
    }
    faces.add(corners, "facet", t);
  }
  if (nonFinite) warn.add(name + ": " + std::to_string(nonFinite) + " facets have non-finite coordinates; skipped");
  warn.finish();
  std::string().swap(bytes);  // not needed while building
  return buildMesh(std::move(soup), std::move(report));
}

Result<Mesh> parseAscii(const std::string& name, std::string bytes) {
  TextCursor in(bytes.data(), bytes.data() + bytes.size());
  LoadReport report;
  report.file = name;
  Warnings warn(report.warnings);
  PolygonSoup soup;
  Welder weld(soup);
  FaceBuilder faces(soup, report, warn);
  std::vector<long long> corners;
  bool finite = true;
  std::size_t facet = 0;
  auto flush = [&] {
    if (!corners.empty() || !finite) {
      ++facet;
      if (!finite) {
        warn.add(name + " facet " + std::to_string(facet) + ": a vertex has a non-finite or unreadable coordinate; skipped");
        ++report.skipped_faces;
      } else {
        faces.add(corners, "facet", facet);
      }
    }
    corners.clear();
    finite = true;
  };
  while (true) {
    const std::string_view t = in.token();
    if (t.empty()) break;
    if (t == "vertex") {
      glm::dvec3 p(0.0);
      if (!in.number(p.x) || !in.number(p.y) || !in.number(p.z) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        finite = false;
      else corners.push_back(weld.index(p));
    } else if (t == "endloop" || t == "endfacet" || t == "facet") {
      flush();
    }
    // "solid NAME", "normal", "outer loop", "endsolid": nothing to keep.
  }
  flush();
  warn.finish();
  std::string().swap(bytes);  // not needed while building
  return buildMesh(std::move(soup), std::move(report));
}

}  // namespace

Result<Mesh> parseStl(const std::string& name, std::string bytes) {
  if (bytes.size() >= 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
    const std::uint32_t n = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
    if (84 + 50 * std::uint64_t(n) == bytes.size()) return parseBinary(name, std::move(bytes), n);
  }
  const std::size_t start = bytes.find_first_not_of(" \t\r\n");
  if (start != std::string::npos && bytes.compare(start, 5, "solid") == 0) {
    if (std::memchr(bytes.data(), '\0', std::min<std::size_t>(bytes.size(), 4096)) == nullptr) return parseAscii(name, std::move(bytes));
  }
  if (bytes.size() >= 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + 80;
    const std::uint32_t n = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
    return Error{name + ": binary STL header says " + std::to_string(n) + " triangles (" + std::to_string(84 + 50 * std::uint64_t(n)) +
                 " bytes) but the file has " + std::to_string(bytes.size()) + " bytes: truncated or not an STL file"};
  }
  return Error{name + ": not an STL file (too short for binary STL, and it does not begin with 'solid')"};
}

}  // namespace npr
