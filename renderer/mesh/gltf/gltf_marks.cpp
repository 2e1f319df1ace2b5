// The glTF reader: POINTS and LINES, LINE_LOOP and LINE_STRIP primitives as the soup's marks
// (PolygonSoup::dots and segments), which the viewer draws as dots and as strokes of the line
// style (f3d and most viewers draw them; refusing them lost a wireframe's or a point set's
// part of a scene). Marks have no material and no normal; they are placed as the primitive's
// vertices are, and a deforming mesh's are left out (they would not follow its pose).
#include "renderer/mesh/gltf/gltf_reader.h"

namespace npr::gltf {

Status GltfReader::marks(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& where, Target& t) {
  const auto morphs = [&] {
    if (t.mesh < 0 || t.mesh >= static_cast<int>(m_.meshes.size())) return false;
    for (const tinygltf::Primitive& p : m_.meshes[static_cast<std::size_t>(t.mesh)].primitives)
      if (!p.targets.empty()) return true;
    return false;
  };
  if (mode_ == Mode::Objects && (t.skin >= 0 || morphs())) {
    ++skippedPrimitives_;
    return okStatus();
  }
  const auto pos = prim.attributes.find("POSITION");
  if (pos == prim.attributes.end()) return fail(where + " has no POSITION");
  Result<AccessorView> positions = accessor(pos->second, where + " POSITION", {TINYGLTF_TYPE_VEC3});
  if (!positions) return Error{positions.error()};
  Result<std::optional<AccessorView>> read = this->indices(prim, where);
  if (!read) return Error{read.error()};
  const std::optional<AccessorView>& indices = *read;
  const std::size_t corners = indices ? indices->count : positions->count;
  const std::uint64_t made = prim.mode == TINYGLTF_MODE_POINTS ? corners
                             : prim.mode == TINYGLTF_MODE_LINE ? corners / 2
                             : prim.mode == TINYGLTF_MODE_LINE_LOOP ? (corners >= 2 ? corners : 0)
                                                                    : (corners >= 2 ? corners - 1 : 0);
  sceneMarks_ += made;
  if (sceneMarks_ > kMaxSceneMarks)
    return fail("the scene makes more than " + std::to_string(kMaxSceneMarks) + " points and line segments (its meshes instanced by its nodes)");
  // A corner's placed position; none for an index past the positions or a non-finite one.
  std::size_t bad = 0;
  auto at = [&](std::size_t k) -> std::optional<glm::dvec3> {
    const std::uint64_t i = indices ? indices->index(k) : k;
    if (i >= positions->count) return std::nullopt;
    const glm::dvec4 p = world * glm::dvec4(positions->component(i, 0), positions->component(i, 1), positions->component(i, 2), 1.0);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
    return glm::dvec3(p);
  };
  PolygonSoup& soup = t.soup;
  if (prim.mode == TINYGLTF_MODE_POINTS) {
    soup.dots.reserve(soup.dots.size() + corners);
    for (std::size_t k = 0; k < corners; ++k) {
      if (const std::optional<glm::dvec3> p = at(k)) soup.dots.push_back(*p);
      else ++bad;
    }
  } else {
    auto segment = [&](std::size_t a, std::size_t b) {
      const std::optional<glm::dvec3> p = at(a), q = at(b);
      if (!p || !q) {
        ++bad;
        return;
      }
      soup.segments.push_back(*p);
      soup.segments.push_back(*q);
    };
    soup.segments.reserve(soup.segments.size() + 2 * made);
    if (prim.mode == TINYGLTF_MODE_LINE) {
      for (std::size_t k = 0; k + 1 < corners; k += 2) segment(k, k + 1);
    } else {
      for (std::size_t k = 0; k + 1 < corners; ++k) segment(k, k + 1);
      if (prim.mode == TINYGLTF_MODE_LINE_LOOP && corners >= 2) segment(corners - 1, 0);
    }
  }
  if (bad > 0)
    warn_.add(name_ + ": " + where + ": " + std::to_string(bad) + (prim.mode == TINYGLTF_MODE_POINTS ? " point(s)" : " line segment(s)") +
              " with an index past its " + std::to_string(positions->count) + " positions or a non-finite position; skipped");
  return okStatus();
}

}  // namespace npr::gltf
