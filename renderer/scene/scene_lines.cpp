// The scene's lines in scene space (see scene_lines.h).
#include "renderer/scene/scene_lines.h"

#include <algorithm>

namespace npr {

std::vector<FeatureLine> sceneIntersectionLines(const Scene& scene, IntersectionCounts* counts) {
  std::vector<IntersectionObject> objects;
  scene.forEach([&](const Model& m) { objects.push_back({&m.mesh(), m.transform()}); });
  return intersectionLines(objects, counts);
}

std::vector<FeatureLine> sceneFeatureLines(Scene& scene, const CameraMatrices& camera, const RenderSettings& settings,
                                           const std::function<std::uint8_t(const std::string* object)>& kindsFor, const LineSet* set,
                                           gl::ProgramCache& programs) {
  std::vector<FeatureLine> out;
  FrameStats exportStats;
  scene.forEachIncludingHidden([&](Model& m) { (void)m.applyPose(false, true, programs, exportStats); });
  auto keep = [&](std::vector<FeatureLine>& lines, const std::string* object) {
    const std::uint8_t kinds = kindsFor ? kindsFor(object) : settings.lines.drawnKinds();
    lines.erase(std::remove_if(lines.begin(), lines.end(), [&](const FeatureLine& l) { return !((kinds >> int(l.kind + 0.5f)) & 1u); }), lines.end());
  };
  scene.forEach([&](Model& m) {
    std::vector<FeatureLine> lines = m.lines().lines(m.placed(camera), settings.lines);
    keep(lines, &m.name());
    if (set && !set->materials.empty()) {
      const std::vector<MeshMaterial>& materials = m.mesh().materials;
      const auto taken = [&](std::uint16_t i) { return i < materials.size() && set->takesMaterial(materials[i].name); };
      lines.erase(std::remove_if(lines.begin(), lines.end(),
                                 [&](const FeatureLine& l) { return !taken(l.attributes.materials.x) && !taken(l.attributes.materials.y); }),
                  lines.end());
    }
    if (m.transform() != glm::mat4(1.0f)) {
      const glm::mat3 normals = glm::transpose(glm::inverse(glm::mat3(m.transform())));
      for (FeatureLine& l : lines) {
        l.a = glm::vec3(m.transform() * glm::vec4(l.a, 1.0f));
        l.b = glm::vec3(m.transform() * glm::vec4(l.b, 1.0f));
        const glm::vec3 n = normals * l.attributes.normal;
        l.attributes.normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f);
      }
    }
    out.insert(out.end(), lines.begin(), lines.end());
  });
  if (settings.lines.drawnKinds() & 16u) {
    std::vector<FeatureLine> crossings = sceneIntersectionLines(scene);
    keep(crossings, nullptr);
    out.insert(out.end(), crossings.begin(), crossings.end());
  }
  return out;
}

SceneMarks sceneMarks(const Scene& scene) {
  SceneMarks out;
  scene.forEach([&](const Model& m) {
    const Mesh& mesh = m.mesh();
    const glm::mat4& t = m.transform();
    auto place = [&](const glm::vec3& p) { return glm::vec3(t * glm::vec4(p, 1.0f)); };
    for (std::size_t i = 0; i + 1 < mesh.segments.size(); i += 2)
      out.segments.push_back({place(mesh.segments[i]), place(mesh.segments[i + 1]), float(EdgeKind::Silhouette)});
    for (const glm::vec3& d : mesh.dots) out.dots.push_back(place(d));
  });
  return out;
}

}  // namespace npr
