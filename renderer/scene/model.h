// One object of the scene: a mesh placed by a transform, and everything derived from the mesh,
// each computed the first time a frame needs it and dropped with the model: the GPU copy, the
// materials' appearance, the per-triangle shading cache, the feature edges, the hatching
// direction field, the occlusion bake, the painterly strokes' seeds, the anchored pattern's
// samples, and the parts drawn with palettes of their own (per-material palettes).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/animation/gpu_deformation.h"
#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/lines/line_pass.h"
#include "renderer/materials/gpu_materials.h"
#include "renderer/mesh/gpu_mesh.h"
#include "renderer/mesh/mesh.h"
#include "renderer/mesh/mesh_subset.h"
#include "renderer/orientation/direction_field.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/palette/tone_range.h"
#include "renderer/patterns/pattern_tracker.h"
#include "renderer/shading/triangle_shading_cache.h"
#include "renderer/shadows/occlusion_bake.h"
#include "renderer/strokes/brush_stroke_pass.h"

namespace npr {


class Model {
 public:
  // Keeps a pointer to `mesh`, which must outlive the model (or be replaced first); uploads it,
  // with its materials' appearance unless `appearance` is off (the ground has none).
  Model(const Mesh& mesh, const glm::mat4& transform, FrameStats& stats, bool appearance = true);
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // Another mesh in the same model: every derived cache dropped, its objects kept for reuse
  // (opening one file after another keeps the allocations of the first).
  void reset(const Mesh& mesh, const glm::mat4& transform, FrameStats& stats);

  // The mesh drawn: for a mesh that deforms (skins, morph targets), the model's own posed copy,
  // current on the frames that read it on the CPU (applyPose), else the last pose made there.
  const Mesh& mesh() const { return *mesh_; }
  // Gives a deforming mesh its pose: morph `weights`, and `joints` (per skin joint, the mesh's
  // rest space to its posed space), made by the next applyPose. Nothing happens for a mesh that
  // does not deform.
  void deform(const std::vector<glm::mat4>& joints, const std::vector<float>& weights);
  // Makes the pose given where the frame reads it: `onGpu` writes the vertex buffers on the GPU
  // (animation/gpu_deformation.h; with no compute shaders, or too many morph targets at once,
  // the CPU does it); `onCpu` makes mesh() the pose too, with its lighting, lines, strokes and
  // parts following, and uploads it unless the GPU wrote the buffers. What is computed once per
  // mesh (edges, the direction field itself, materials) is kept.
  [[nodiscard]] Status applyPose(bool onGpu, bool onCpu, gl::ProgramCache& programs, FrameStats& stats);
  // Whether mesh() lags the pose (only the GPU made it).
  bool cpuPoseStale() const { return cpuStale_; }
  // While mesh() lags: poses on the CPU the triangles the tone sampler reads (every `stride`-th
  // from stride / 2, palette/tone_range.h), their vertices, centroids and normals.
  void poseToneSamples(std::size_t stride);
  // Model space to the scene's (world) space.
  const glm::mat4& transform() const { return transform_; }
  void setTransform(const glm::mat4& transform) { transform_ = transform; }
  // The object's name in its file: what line sets select by (LineSet::objects).
  const std::string& name() const { return name_; }
  void setName(std::string name) { name_ = std::move(name); }
  // Its own tone range (--tone-range per-object): the tracker, the range it gives, and the
  // matcher slot its palettes fit it with (GpuPalette::updateMatcher; 0: the scene's).
  ToneRangeTracker& toneTracker() { return toneTracker_; }
  std::optional<glm::vec2> toneTarget;
  int toneSlot = 0;
  // The model's own palette, in place of the scene's main one for its surfaces (its
  // materials' palettes still win); null: none.
  const GpuPalette* palette() const { return palette_.get(); }
  GpuPalette* palette() { return palette_.get(); }
  // Shared by the models given the same palette (Scene::setPalette), and by their batch.
  const std::shared_ptr<GpuPalette>& sharedPalette() const { return palette_; }
  void setPalette(std::shared_ptr<GpuPalette> palette) { palette_ = std::move(palette); }
  // Its detail, in [0, 1]: the value a palette with `axis detail` picks its row by (palette.h).
  float detail() const { return detail_; }
  void setDetail(float detail) { detail_ = detail; }
  // The camera as this model sees it: the scene's view times the model's transform.
  CameraMatrices placed(const CameraMatrices& camera) const { return {camera.view * transform_, camera.projection}; }
  // Scene units per mesh unit: the largest axis scale of the transform.
  float scale() const;
  // The bounding sphere's radius in scene units.
  float sceneRadius() const;
  // Screen pixels per front-facing triangle seen through `placed` (the bounding disc over half
  // the triangles): how dense the mesh is on screen, which picks where patterns and turns are
  // worked out.
  float pixelsPerFrontTriangle(const CameraMatrices& placed, const glm::ivec4& viewport) const;
  // A batch of objects (scene_batches.h): each object's bounding sphere in the model's space
  // (centre, radius), whose discs pixelsPerFrontTriangle sums instead of the batch's one.
  void setMemberSpheres(std::vector<glm::vec4> spheres) { memberSpheres_ = std::move(spheres); }

  GpuMesh& gpu() { return gpu_; }
  const GpuMesh& gpu() const { return gpu_; }
  GpuMaterials& materials() { return materials_; }
  TriangleShadingCache& triangles() { return triangles_; }
  LinePass& lines() { return lines_; }
  BrushStrokePass& strokes() { return strokes_; }
  PatternTracker& patterns() { return patterns_; }
  const PatternTracker& patterns() const { return patterns_; }

  // The hatching direction field: computed and uploaded (to the parts too) the first time.
  const DirectionField& directionField(FrameStats& stats);
  const DirectionField* directionFieldIfComputed() const { return field_ ? &*field_ : nullptr; }
  // The field's directions on the mesh as drawn: carried by the pose when the mesh deforms.
  const std::vector<glm::vec3>& surfaceDirections(FrameStats& stats);
  // The occlusion bake: started the first time, advanced by `step`; uploaded when done.
  OcclusionBake* occlusionBake() { return occlusion_.get(); }
  const OcclusionBake* occlusionBake() const { return occlusion_.get(); }
  [[nodiscard]] Status startOcclusionBake();
  void occlusionBaked(FrameStats& stats);  // uploads the finished bake to the model and its parts
  const std::vector<float>* occlusionValues() const { return occlusion_ && occlusion_->done() ? &occlusion_->values() : nullptr; }

  // A part of the model drawn with one palette (null: the main one) and one detail (none: the
  // model's): its triangles (the model's vertex indices and their per-face data, no vertices:
  // mesh_subset.h), its own index buffer and per-triangle cache. It draws through the model's
  // vertex streams, materials and maps (the same table: a part keeps every material, so
  // indices stay valid). Empty when no material of the mesh has its own palette or detail.
  struct Part {
    const GpuPalette* palette = nullptr;
    std::optional<float> detail;  // what a palette with `axis detail` picks its row by
    MeshFaces faces;
    GpuMesh gpu;
    TriangleShadingCache triangles;
  };
  // Splits the model into parts by the palette each material is drawn with (`paletteOf`
  // returns null for the main palette) and its detail (`detailOf` returns none for the model's).
  template <class PaletteOf, class DetailOf>
  void splitByMaterial(PaletteOf&& paletteOf, DetailOf&& detailOf, FrameStats& stats);
  std::vector<std::unique_ptr<Part>>& parts() { return parts_; }
  const std::vector<std::unique_ptr<Part>>& parts() const { return parts_; }

 private:
  using PartKey = std::pair<const GpuPalette*, std::optional<float>>;
  void uploadParts(const std::vector<PartKey>& keys, const std::vector<std::size_t>& partOf, FrameStats& stats);

  void adopt(const Mesh& mesh);  // mesh_ and rest_ for a new mesh (a posed copy when it deforms)
  void poseOnCpu(bool upload, FrameStats& stats);

  std::vector<glm::vec4> memberSpheres_;
  const Mesh* mesh_;
  const Mesh* rest_;
  std::unique_ptr<Mesh> posed_;           // a deforming mesh's posed copy
  std::vector<glm::mat4> poseJoints_;     // the pose last given (the field is carried by it)
  std::vector<float> poseWeights_;
  std::vector<glm::vec3> posedDirections_;
  GpuDeformation gpuPose_;
  bool gpuPending_ = false;  // the vertex buffers lag the pose given
  bool cpuStale_ = false;    // mesh() lags it
  glm::mat4 transform_;
  std::string name_;
  float detail_ = 0.0f;
  std::shared_ptr<GpuPalette> palette_;
  ToneRangeTracker toneTracker_;
  GpuMesh gpu_;
  GpuMaterials materials_;
  TriangleShadingCache triangles_;
  LinePass lines_;
  BrushStrokePass strokes_;
  PatternTracker patterns_;
  std::optional<DirectionField> field_;
  std::unique_ptr<OcclusionBake> occlusion_;
  std::vector<std::unique_ptr<Part>> parts_;
};

template <class PaletteOf, class DetailOf>
void Model::splitByMaterial(PaletteOf&& paletteOf, DetailOf&& detailOf, FrameStats& stats) {
  parts_.clear();
  if (mesh_->faceMaterials.size() != mesh_->triangleCount()) return;
  // The part of each material: 0 the main palette at the model's detail, k > 0 the k-th
  // distinct pair of a material's palette and detail.
  std::vector<PartKey> keys{{nullptr, std::nullopt}};
  std::vector<std::size_t> partOf(mesh_->materials.size(), 0);
  for (std::size_t i = 0; i < mesh_->materials.size(); ++i) {
    const PartKey key{paletteOf(mesh_->materials[i].name), detailOf(mesh_->materials[i].name)};
    auto at = std::find(keys.begin(), keys.end(), key);
    if (at == keys.end()) at = keys.insert(keys.end(), key);
    partOf[i] = static_cast<std::size_t>(at - keys.begin());
  }
  if (keys.size() > 1) uploadParts(keys, partOf, stats);
}

}  // namespace npr
