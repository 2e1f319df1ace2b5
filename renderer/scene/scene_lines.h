// The scene's lines in scene space: where its models' surfaces cross, the feature lines a frame
// shows for a camera and the files' own points and lines (for vector export), each model's
// placed by its transform.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lines/intersection_lines.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/render_settings.h"

namespace npr {

// Where the shown models' surfaces cross, as posed and placed.
std::vector<FeatureLine> sceneIntersectionLines(const Scene& scene, IntersectionCounts* counts = nullptr);

// The feature lines the frame shows for this camera, every model's in scene space, found on the
// CPU's pose (made here where only the GPU's was). `kindsFor(object)` (null: the scene's
// intersection lines; empty function: every kind `settings` draws) chooses the kinds kept for
// each object by name (bit EdgeKind); `set`, when it selects materials, keeps the lines on a
// face of one of them (LineSet::materials).
std::vector<FeatureLine> sceneFeatureLines(Scene& scene, const CameraMatrices& camera, const RenderSettings& settings,
                                           const std::function<std::uint8_t(const std::string* object)>& kindsFor, const LineSet* set,
                                           gl::ProgramCache& programs);

// The shown models' own marks (Mesh::dots and segments: a file's points and lines) in scene
// space, placed by their transforms: segments as silhouette-kind lines (the ink they are drawn
// in), dots as points.
struct SceneMarks {
  std::vector<FeatureLine> segments;
  std::vector<glm::vec3> dots;
};
SceneMarks sceneMarks(const Scene& scene);

}  // namespace npr
