// Faces into triangles, and a soup into a Mesh (see polygon_soup.h).
#include "renderer/mesh/polygon_soup.h"

#include <algorithm>
#include <cmath>

#include "renderer/mesh/mesh_builder.h"

namespace npr {
namespace {
constexpr std::size_t kMaxWarnings = 50;
}  // namespace

bool PolygonSoup::addVertex(const glm::dvec3& v) {
  const bool finite = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
  vertices.push_back(finite ? v : glm::dvec3(0.0));
  vertexValid.push_back(finite ? 1 : 0);
  return finite;
}

void Warnings::add(std::string w) {
  if (out_.size() < kMaxWarnings) out_.push_back(std::move(w));
  else ++dropped_;
}

void Warnings::finish() {
  if (dropped_) out_.push_back("... and " + std::to_string(dropped_) + " more warnings");
  dropped_ = 0;
}

bool FaceBuilder::add(std::vector<long long>& corners, const char* unit, std::size_t number) {
  auto where = [&] { return report_.file + " " + unit + " " + std::to_string(number); };
  const long long count = static_cast<long long>(soup_.vertices.size());
  face_.clear();
  for (long long c : corners) {
    if (c < 0 || c >= count) {
      warn_.add(where() + ": face references vertex " + std::to_string(c + 1) + " but only " + std::to_string(count) +
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
  }
  // A corner named twice in a row ("f 1 2 2 3", a common export glitch) adds nothing: drop the
  // repeat, keep the rest of the face, and count it. OpenMesh would assert on it.
  const std::size_t before = face_.size();
  face_.erase(std::unique(face_.begin(), face_.end()), face_.end());
  while (face_.size() > 1 && face_.front() == face_.back()) face_.pop_back();
  if (face_.size() != before) ++report_.repeated_corner_faces;
  if (face_.size() < 3) {
    warn_.add(where() + (before >= 3 ? ": face names fewer than 3 different vertices; skipped" : ": face has fewer than 3 vertices; skipped"));
    ++report_.skipped_faces;
    return false;
  }
  if (face_.size() == 3) {
    soup_.triangles.push_back({face_[0], face_[1], face_[2]});
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
    soup_.triangles.push_back({face_[static_cast<std::size_t>(tri[k])], face_[static_cast<std::size_t>(tri[k + 1])],
                               face_[static_cast<std::size_t>(tri[k + 2])]});
  return true;
}

Result<Mesh> buildMesh(PolygonSoup soup, LoadReport report) {
  if (soup.triangles.empty())
    return Error{report.file + ": contains no faces (" + std::to_string(soup.vertices.size()) +
                 " vertices, but no face that could be used); nothing to draw"};
  Mesh m;
  m.report = std::move(report);
  std::vector<glm::vec3> verts = normalizePositions(soup.vertices, &soup.vertexValid, m.report);
  soup.vertices = {};
  soup.vertexValid = {};
  buildTriMesh(std::move(verts), std::move(soup.triangles), m);
  if (m.indices.empty())
    return Error{m.report.file + ": every face is degenerate (names one vertex more than once); nothing to draw"};
  return m;
}

}  // namespace npr
