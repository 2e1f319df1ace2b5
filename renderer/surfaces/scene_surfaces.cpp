// The scene's surfaces with the path (see scene_surfaces.h).
#include "renderer/surfaces/scene_surfaces.h"

#include <limits>

#include "renderer/frame/scene_palettes.h"
#include "renderer/paths/control_palette_pass.h"
#include "renderer/paths/path_table.h"

namespace npr {

SceneSurfaces::SceneSurfaces() {
  for (const PathInfo& info : renderPaths()) paths_.push_back(info.create());
}

RenderPass& SceneSurfaces::path(RenderPath p) { return *paths_[pathIndex(p)]; }
const RenderPass& SceneSurfaces::path(RenderPath p) const { return *paths_[pathIndex(p)]; }

Status SceneSurfaces::draw(FrameView& frame, const std::vector<Feature*>& active, gl::MeshOutput output, const Model* placed,
                           const PartDraw* draw) {
  active_ = &active;
  // The path may draw several objects' work together at the end (the stencil path's quads).
  RenderPass* p = draw ? nullptr : &path(frame.settings.path);
  if (p) p->beginScene();
  Status status = okStatus();
  frame.scene.forEachSurface([&](Model& m) {
    if (!status) return;
    // Nothing of it in view: no draw, and none of the path's work for it.
    if (sphereOutsideView(m.placed(frame.camera), m.mesh().radius)) {
      ++frame.stats.surfacesCulled;
      return;
    }
    status = drawModel(frame, m, output, &m != placed, draw);
  });
  if (status && !frame.scene.empty()) status = drawGround(frame, output, draw);
  if (p)
    if (Status st = p->endScene(); status && !st) status = st;
  active_ = nullptr;
  return status;
}

Status SceneSurfaces::drawModel(FrameView& view, Model& model, gl::MeshOutput output, bool placePattern, const PartDraw* draw) {
  const RenderSettings& s = view.settings;
  const CameraMatrices placed = model.placed(view.camera);
  if (output == gl::MeshOutput::Colour && placePattern) placeFor(view, &model);
  // The whole model's, for every part: the parts hide each other's back faces.
  const bool cullBackFaces = backFacesHidden(view, model, placed);
  // The model's materials, once for every part (a part keeps every material: the same rows).
  GpuMaterials& materials = model.materials();
  if (s.materials || materials.coverage()) materials.update(model.mesh(), view.lighting, view.stats);
  auto drawOne = [&](GpuMesh& gpu, TriangleShadingCache& triangles, const GpuPalette* palette, float detail) {
    FrameContext frame{placed, view.viewport, s, view.lighting, gpu, model.mesh(), materials, palette, pattern_, triangles, view.programs,
                       view.stats, view.emptyVao, output};
    frame.sceneView = view.camera.view;
    frame.turnResolve = turnResolveFor(view, palette, output);
    frame.cullBackFaces = cullBackFaces;
    frame.axisDetail = detail;
    return draw ? (*draw)(view, &model, frame) : drawPart(view, &model, frame);
  };
  const GpuPalette* main = view.paletteOf(model);
  const ToneSlotScope toneSlot(model, view.palettes);  // its own tone range's matchers while it draws
  if (model.parts().empty() || !s.materials) return drawOne(model.gpu(), model.triangles(), main, model.detail());
  // One draw of the path per palette, each over its part of the model; depth testing across
  // the parts keeps the nearest surface, whichever part is drawn first.
  for (auto& part : model.parts())
    if (Status st = drawOne(part->gpu, part->triangles, part->palette ? part->palette : main, part->detail.value_or(model.detail())); !st)
      return st;
  return okStatus();
}

// The ground plane with the path's own pass (or `draw`), after the models (--ground).
Status SceneSurfaces::drawGround(FrameView& view, gl::MeshOutput output, const PartDraw* draw) {
  if (!view.settings.ground || !view.palette) return okStatus();
  Model* ground = view.scene.ground();
  if (!ground) return okStatus();
  // The ground has no materials of its own: lit with the lighting state's material.
  RenderSettings plain = view.settings;
  plain.materials = false;
  FrameContext frame{view.camera, view.viewport,  plain,       view.lighting,       ground->gpu(), ground->mesh(), ground->materials(),
                     view.palette, pattern_,      ground->triangles(), view.programs, view.stats,    view.emptyVao,  output};
  frame.sceneView = view.camera.view;
  const ToneSlotScope toneSlot(*ground, view.palettes);  // its tones set apart from the objects'
  return draw ? (*draw)(view, nullptr, frame) : drawPart(view, nullptr, frame);
}

Status SceneSurfaces::drawPart(FrameView& view, const Model* model, FrameContext& frame) {
  for (Feature* f : *active_) f->shade(view, model, frame);
  // Set before the path draws: a path that defers its work to the scene's end (the stencil
  // path) must not, where these are drawn over each surface as it is drawn.
  if (frame.settings.controlPalettes) {
    frame.shadowPalette = view.palettes.control(ControlParameter::Shadow);
    frame.occlusionPalette = view.palettes.control(ControlParameter::Occlusion);
  }
  if (Status st = path(frame.settings.path).draw(frame); !st) return st;
  return frame.settings.controlPalettes ? drawControlPalettes(frame, frame.settings.path) : okStatus();
}

void SceneSurfaces::placeFor(const FrameView& view, Model* model) {
  const CameraMatrices placed = model ? model->placed(view.camera) : view.camera;
  pixelsPerFrontTriangle_ = model ? model->pixelsPerFrontTriangle(placed, view.viewport) : std::numeric_limits<float>::infinity();
  placePattern(pattern_, model ? &model->patterns() : nullptr, pixelsPerFrontTriangle_, placed, view.settings, view.viewport,
               glm::vec2(view.frameOffset), view.stats);
}

TurnResolvePass* SceneSurfaces::turnResolveFor(const FrameView& view, const GpuPalette* palette, gl::MeshOutput output) {
  const RenderSettings& s = view.settings;
  if (!path(s.path).resolvesTurns() || output != gl::MeshOutput::Colour || !palette ||
      !turnResolveWanted(s, palette->oriented(pattern_), pattern_.mapping() == gl::PatternMapping::Object, view.softwareRasterizer,
                         pixelsPerFrontTriangle_))
    return nullptr;
  ++view.stats.surfaceBuffers;
  return &turnResolve_;
}

bool SceneSurfaces::backFacesHidden(const FrameView& view, const Model& model, const CameraMatrices& placed) {
  const bool hidden = view.settings.tuning.cullHiddenBackFaces && model.mesh().closed && !model.mesh().seeThrough &&
                      glm::determinant(glm::mat3(model.transform())) > 0.0f && sphereBeyondNearPlane(placed, model.sceneRadius());
  view.stats.backFacesCulled = view.stats.backFacesCulled || hidden;
  return hidden;
}

}  // namespace npr
