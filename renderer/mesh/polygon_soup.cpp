// Faces into triangles, and a soup into a Mesh (see polygon_soup.h).
#include "renderer/mesh/polygon_soup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "renderer/mesh/mesh_builder.h"
#include "renderer/core/printable.h"

namespace npr {
namespace {
constexpr std::size_t kMaxWarnings = 50;
constexpr std::size_t kShownPerKind = 3;

struct CornerKey {
  std::uint32_t vertex;
  std::int32_t texcoord;
  std::uint16_t material;
  bool operator==(const CornerKey& o) const { return vertex == o.vertex && texcoord == o.texcoord && material == o.material; }
};
struct CornerHash {
  std::size_t operator()(const CornerKey& k) const {
    return (std::size_t(k.vertex) * 0x9E3779B97F4A7C15ull) ^ (std::size_t(std::uint32_t(k.texcoord)) * 0xC2B2AE3D27D4EB4Full) ^
           (std::size_t(k.material) * 0x165667B19E3779F9ull);
  }
};

// Makes every attribute per vertex: a file vertex used with two texture coordinates, or by
// faces of two materials (whose colours must not blend across the edge), becomes one vertex
// per combination. Rewrites the soup's vertices, colours, texture coordinates and triangles;
// returns for each new vertex the file vertex it came from (they share a normal).
std::vector<std::uint32_t> splitVertices(PolygonSoup& soup) {
  std::unordered_map<CornerKey, std::uint32_t, CornerHash> ids;
  ids.reserve(soup.vertices.size() + soup.vertices.size() / 4);
  std::vector<std::uint32_t> source;
  std::vector<glm::dvec3> vertices;
  std::vector<char> valid;
  std::vector<glm::vec3> colours;
  std::vector<glm::vec2> texcoords;
  std::vector<float> deform;
  const std::size_t width = soup.deform.empty() ? 0 : soup.deformWidth();
  const bool tex = soup.tracksTexcoords && !soup.texcoords.empty();
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = static_cast<std::uint32_t>(soup.triangles[t][static_cast<std::size_t>(k)]);
      const int tc = tex ? soup.triangleTexcoords[t][static_cast<std::size_t>(k)] : -1;
      const std::uint16_t mat = soup.tracksMaterials ? soup.triangleMaterials[t] : 0;
      auto [it, inserted] = ids.emplace(CornerKey{v, tc, mat}, static_cast<std::uint32_t>(vertices.size()));
      if (inserted) {
        source.push_back(v);
        vertices.push_back(soup.vertices[v]);
        valid.push_back(soup.vertexValid[v]);
        if (!soup.colours.empty()) colours.push_back(soup.colours[v]);
        if (tex) texcoords.push_back(tc >= 0 ? soup.texcoords[static_cast<std::size_t>(tc)] : glm::vec2(0.0f));
        if (width) deform.insert(deform.end(), soup.deform.begin() + std::ptrdiff_t(v * width), soup.deform.begin() + std::ptrdiff_t((v + 1) * width));
      }
      soup.triangles[t][static_cast<std::size_t>(k)] = static_cast<int>(it->second);
    }
  }
  soup.vertices = std::move(vertices);
  soup.vertexValid = std::move(valid);
  soup.colours = std::move(colours);
  soup.texcoords = std::move(texcoords);
  soup.deform = std::move(deform);
  soup.triangleTexcoords = {};
  return source;
}

}  // namespace

bool PolygonSoup::addVertex(const glm::dvec3& v) {
  const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  vertices.push_back(finite ? v : glm::dvec3(0.0));
  vertexValid.push_back(finite ? 1 : 0);
  return finite;
}

namespace {
thread_local bool allWarnings = false;
}  // namespace

WarningDetail::WarningDetail(bool all) : before_(allWarnings) { allWarnings = all || before_; }
WarningDetail::~WarningDetail() { allWarnings = before_; }
bool WarningDetail::all() { return allWarnings; }

void Warnings::add(std::string w) {
  if (allWarnings) {
    if (out_.size() < WarningDetail::kAllWarningsCap) out_.push_back(printableMessage(w));
    else ++dropped_;
    return;
  }
  // The kind: what follows the place ("line 12: ", "mesh 3 primitive 0 face 12: ").
  const std::size_t colon = w.rfind(": ");
  std::string kind = colon == std::string::npos ? w : w.substr(colon + 2);
  auto it = std::find_if(kinds_.begin(), kinds_.end(), [&](const auto& k) { return k.first == kind; });
  if (it == kinds_.end()) {
    kinds_.emplace_back(std::move(kind), 0);
    it = kinds_.end() - 1;
  }
  // Warnings quote files (names, statements): escaped here, once, for every reader.
  if (++it->second <= kShownPerKind && out_.size() < kMaxWarnings) out_.push_back(printableMessage(w));
  else if (it->second <= kShownPerKind) ++dropped_;
}

void Warnings::finish() {
  for (const auto& [kind, count] : kinds_)
    if (count > kShownPerKind)
      out_.push_back(printableMessage("... and " + std::to_string(count - kShownPerKind) + " more like this (" + std::to_string(count) + " in all): " + kind));
  if (dropped_) out_.push_back("... and " + std::to_string(dropped_) + " more warnings");
  kinds_.clear();
  dropped_ = 0;
}

bool FaceBuilder::add(std::vector<long long>& corners, const char* unit, std::size_t number) {
  static const std::vector<int> none;
  return add(corners, none, 0, unit, number);
}

bool FaceBuilder::add(std::vector<long long>& corners, const std::vector<int>& texcoords, std::uint16_t material,
                      const char* unit, std::size_t number) {
  auto where = [&] { return report_.file + " " + unit + " " + std::to_string(number); };
  const long long count = static_cast<long long>(soup_.vertices.size());
  face_.clear();
  faceTex_.clear();
  const bool hasTex = !texcoords.empty() && texcoords.size() == corners.size();
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const long long c = corners[k];
    if (c < 0 || c >= count) {
      // One-based in the message; unsigned for the largest index a file can write (found by
      // fuzz_off: c + 1 overflowed).
      const std::string number1 = c >= 0 ? std::to_string(static_cast<unsigned long long>(c) + 1ULL) : std::to_string(c + 1);
      warn_.add(where() + ": face references vertex " + number1 + " but only " + std::to_string(count) +
                " vertices are defined; face skipped");
      ++report_.skipped_faces;
      return false;
    }
    if (!soup_.vertexValid[static_cast<std::size_t>(c)]) {
      warn_.add(where() + ": face uses an invalid vertex; face skipped");
      ++report_.skipped_faces;
      return false;
    }
    face_.push_back(static_cast<int>(c));
    faceTex_.push_back(hasTex ? texcoords[k] : -1);
  }
  // A corner named twice in a row ("f 1 2 2 3", a common export glitch) adds nothing: drop the
  // repeat, keep the rest of the face, and count it. OpenMesh would assert on it.
  const std::size_t before = face_.size();
  std::size_t kept = 0;
  for (std::size_t k = 0; k < face_.size(); ++k) {
    if (kept > 0 && face_[k] == face_[kept - 1]) continue;
    face_[kept] = face_[k];
    faceTex_[kept] = faceTex_[k];
    ++kept;
  }
  face_.resize(kept);
  faceTex_.resize(kept);
  while (face_.size() > 1 && face_.front() == face_.back()) {
    face_.pop_back();
    faceTex_.pop_back();
  }
  if (face_.size() != before) ++report_.repeated_corner_faces;
  if (face_.size() < 3) {
    warn_.add(where() + (before >= 3 ? ": face names fewer than 3 different vertices; skipped" : ": face has fewer than 3 vertices; skipped"));
    ++report_.skipped_faces;
    return false;
  }
  // A texture coordinate index out of range drops the face's texture coordinates (warned by the parser).
  const long long nt = static_cast<long long>(soup_.texcoords.size());
  bool texOk = hasTex;
  for (int t : faceTex_) texOk = texOk && t >= 0 && t < nt;
  auto emit = [&](std::size_t a, std::size_t b, std::size_t c) {
    soup_.triangles.push_back({face_[a], face_[b], face_[c]});
    if (soup_.tracksTexcoords)
      soup_.triangleTexcoords.push_back(texOk ? std::array<int, 3>{faceTex_[a], faceTex_[b], faceTex_[c]} : std::array<int, 3>{-1, -1, -1});
    if (soup_.tracksMaterials) soup_.triangleMaterials.push_back(material);
  };
  if (face_.size() == 3) {
    emit(0, 1, 2);
    return true;
  }
  ++report_.polygons_triangulated;
  poly_.clear();
  for (int i : face_) poly_.push_back(soup_.vertices[static_cast<std::size_t>(i)]);
  if (budget_.exhausted() && !budgetWarned_) {
    warn_.add(where() + ": polygons too large to ear-clip within the loader's time budget; this and later polygons are fanned");
    budgetWarned_ = true;
  }
  const std::vector<int> tri = triangulatePolygon(poly_, budget_);
  for (std::size_t k = 0; k + 2 < tri.size(); k += 3)
    emit(static_cast<std::size_t>(tri[k]), static_cast<std::size_t>(tri[k + 1]), static_cast<std::size_t>(tri[k + 2]));
  return true;
}

std::vector<PolygonSoup> splitSoup(PolygonSoup soup, const std::vector<std::uint32_t>& group, std::size_t groups) {
  std::vector<PolygonSoup> out(groups);
  struct Maps {
    std::unordered_map<int, int> vertex, texcoord, material, texture;
  };
  std::vector<Maps> maps(groups);
  const bool tex = soup.tracksTexcoords && soup.triangleTexcoords.size() == soup.triangles.size();
  const bool mats = soup.tracksMaterials && soup.triangleMaterials.size() == soup.triangles.size();
  for (std::size_t t = 0; t < soup.triangles.size() && t < group.size(); ++t) {
    const std::size_t g = group[t];
    if (g >= groups) continue;
    PolygonSoup& s = out[g];
    Maps& m = maps[g];
    std::array<int, 3> tri{};
    for (std::size_t k = 0; k < 3; ++k) {
      const int v = soup.triangles[t][k];
      auto [it, added] = m.vertex.emplace(v, static_cast<int>(s.vertices.size()));
      if (added) {
        s.vertices.push_back(soup.vertices[static_cast<std::size_t>(v)]);
        s.vertexValid.push_back(soup.vertexValid[static_cast<std::size_t>(v)]);
        if (!soup.colours.empty()) s.colours.push_back(soup.colours[static_cast<std::size_t>(v)]);
      }
      tri[k] = it->second;
    }
    s.triangles.push_back(tri);
    // Every triangle of a group is pushed here, so the per-triangle arrays stay in step.
    if (tex) {
      s.tracksTexcoords = true;
      std::array<int, 3> tc{-1, -1, -1};
      for (std::size_t k = 0; k < 3; ++k) {
        const int c = soup.triangleTexcoords[t][k];
        if (c < 0) continue;
        auto [it, added] = m.texcoord.emplace(c, static_cast<int>(s.texcoords.size()));
        if (added) s.texcoords.push_back(soup.texcoords[static_cast<std::size_t>(c)]);
        tc[k] = it->second;
      }
      s.triangleTexcoords.push_back(tc);
    }
    if (mats) {
      s.tracksMaterials = true;
      const int from = soup.triangleMaterials[t];
      auto [it, added] = m.material.emplace(from, static_cast<int>(s.materials.size()));
      if (added) {
        MeshMaterial mat = soup.materials[static_cast<std::size_t>(from)];
        for (int* map : {&mat.diffuseMap, &mat.opacityMap}) {
          if (*map < 0) continue;
          auto [tt, tAdded] = m.texture.emplace(*map, static_cast<int>(s.textures.size()));
          if (tAdded) s.textures.push_back(soup.textures[static_cast<std::size_t>(*map)]);
          *map = tt->second;
        }
        s.materials.push_back(std::move(mat));
      }
      s.triangleMaterials.push_back(static_cast<std::uint16_t>(it->second));
    }
  }
  return out;
}

namespace {
// The soup's vertices normalised (mesh_builder.h) together with its marks, which count in the
// bounds; the marks' normalised positions go to `m`.
std::vector<glm::vec3> normalizeWithMarks(PolygonSoup& soup, Mesh& m) {
  const std::size_t nv = soup.vertices.size(), dots = soup.dots.size();
  soup.vertices.insert(soup.vertices.end(), soup.dots.begin(), soup.dots.end());
  soup.vertices.insert(soup.vertices.end(), soup.segments.begin(), soup.segments.end());
  soup.vertexValid.resize(soup.vertices.size(), 1);  // marks are finite (the readers keep only those)
  std::vector<glm::vec3> verts = normalizePositions(soup.vertices, &soup.vertexValid, m.report);
  m.dots.assign(verts.begin() + std::ptrdiff_t(nv), verts.begin() + std::ptrdiff_t(nv + dots));
  m.segments.assign(verts.begin() + std::ptrdiff_t(nv + dots), verts.end());
  verts.resize(nv);
  soup.vertices = {};
  soup.vertexValid = {};
  soup.dots = {};
  soup.segments = {};
  return verts;
}
}  // namespace

Result<Mesh> buildMesh(PolygonSoup soup, LoadReport report) {
  if (soup.triangles.empty() && soup.dots.empty() && soup.segments.empty())
    return Error{report.file + ": contains no faces (" + std::to_string(soup.vertices.size()) +
                 " vertices, but no face that could be used); nothing to draw"};
  Mesh m;
  m.report = std::move(report);
  const bool appearance = soup.tracksTexcoords || soup.tracksMaterials || !soup.colours.empty() || !soup.deform.empty();
  if (!appearance) {
    std::vector<glm::vec3> verts = normalizeWithMarks(soup, m);
    buildTriMesh(std::move(verts), std::move(soup.triangles), m);
  } else {
    std::vector<std::uint32_t> split = splitVertices(soup);
    std::vector<glm::vec3> verts = normalizeWithMarks(soup, m);
    std::vector<std::uint32_t> vertexOrigin, faceOrigin;
    buildTriMesh(std::move(verts), std::move(soup.triangles), m, &vertexOrigin, &faceOrigin);
    const std::size_t nv = m.positions.size(), nf = m.indices.size() / 3;
    // Split vertices share their file vertex's normal; the copies made for faces the halfedge
    // structure refused keep their own (a face glued back to back to another, say, would
    // cancel its neighbour's normal), as they do in a mesh without an appearance.
    const std::size_t splitCount = split.size();
    std::uint32_t files = 0;
    for (std::uint32_t s : split) files = std::max(files, s + 1);
    m.sourceVertex.resize(nv);
    for (std::size_t i = 0; i < nv; ++i)
      m.sourceVertex[i] = i < splitCount ? split[i] : files + static_cast<std::uint32_t>(i - splitCount);
    if (!soup.colours.empty()) {
      m.colours.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) m.colours[i] = soup.colours[vertexOrigin[i]];
    }
    if (!soup.texcoords.empty()) {
      m.texcoords.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) m.texcoords[i] = soup.texcoords[vertexOrigin[i]];
    }
    if (const std::size_t width = soup.deformWidth(); width > 0 && soup.deform.size() >= width * (soup.deform.size() / width)) {
      MeshDeformation& d = m.deformation;
      const float scale = static_cast<float>(m.report.original_scale);  // file units to the mesh's
      if (soup.skinned) {
        d.joints.resize(nv);
        d.weights.resize(nv);
      }
      d.targetPositions.assign(soup.morphTargets, std::vector<glm::vec3>(nv));
      d.targetNormals.assign(soup.morphTargets, std::vector<glm::vec3>(nv));
      for (std::size_t i = 0; i < nv; ++i) {
        const float* v = &soup.deform[std::size_t(vertexOrigin[i]) * width];
        if (soup.skinned) {
          d.joints[i] = glm::u16vec4(v[0], v[1], v[2], v[3]);
          d.weights[i] = glm::vec4(v[4], v[5], v[6], v[7]);
          v += 8;
        }
        for (std::size_t t = 0; t < soup.morphTargets; ++t, v += 6) {
          d.targetPositions[t][i] = scale * glm::vec3(v[0], v[1], v[2]);
          d.targetNormals[t][i] = glm::vec3(v[3], v[4], v[5]);
        }
      }
    }
    if (!soup.materials.empty()) {
      m.faceMaterials.resize(nf);
      for (std::size_t f = 0; f < nf; ++f) m.faceMaterials[f] = soup.tracksMaterials ? soup.triangleMaterials[faceOrigin[f]] : 0;
      m.materials = std::move(soup.materials);
      m.textures = std::move(soup.textures);
    }
  }
  if (m.indices.empty() && !m.hasMarks())
    return Error{m.report.file + ": every face is degenerate (names one vertex more than once); nothing to draw"};
  return m;
}

}  // namespace npr
