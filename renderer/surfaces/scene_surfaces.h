// The scene's surfaces, drawn with the frame's render path: every shown model (small static
// ones merged into batches: scene/scene_batches.h), each of its per-material parts with its
// own palette, then the ground, each part with the active features' share (Feature::shade)
// and the control-image palettes over it; a model or batch wholly outside the view is skipped. Owns the paths
// (paths/, one per row of the path table), the turn resolve they may leave turned lookups to,
// and the pattern placement of the model being drawn.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/result.h"
#include "renderer/features/feature.h"
#include "renderer/frame/frame_view.h"
#include "renderer/paths/turn_resolve_pass.h"
#include "renderer/paths/render_pass.h"
#include "renderer/patterns/pattern_placement.h"

namespace npr {

class SceneSurfaces {
 public:
  SceneSurfaces();
  RenderPass& path(RenderPath p);
  const RenderPass& path(RenderPath p) const;

  // What each part is drawn with instead of the path (a frame of stroke angles, say).
  using PartDraw = std::function<Status(FrameView&, const Model*, FrameContext&)>;
  // The surfaces with the path, or `draw`. Colour frames place each model's pattern first but
  // for `placed`'s (done: placeFor).
  [[nodiscard]] Status draw(FrameView& frame, const std::vector<Feature*>& active, gl::MeshOutput output, const Model* placed,
                            const PartDraw* draw = nullptr);
  // pattern() for `model` (null: none) seen through the frame's camera.
  void placeFor(const FrameView& frame, Model* model);
  // How the palettes' textures lie on the model drawn last (FrameView::pattern refers to it).
  PatternPlacement& pattern() { return pattern_; }
  const PatternPlacement& pattern() const { return pattern_; }

 private:
  Status drawModel(FrameView& frame, Model& model, gl::MeshOutput output, bool placePattern, const PartDraw* draw);
  Status drawGround(FrameView& frame, gl::MeshOutput output, const PartDraw* draw);
  // One part of the scene (a model, a per-material part, the ground) with the active features'
  // share: the path, then the control-image palettes over it.
  Status drawPart(FrameView& frame, const Model* model, FrameContext& part);
  // The turn resolve, where a mesh pass of this palette leaves its turned lookups to it, else null.
  TurnResolvePass* turnResolveFor(const FrameView& frame, const GpuPalette* palette, gl::MeshOutput output);
  // Whether this model's mesh passes may drop back faces (FrameContext::cullBackFaces); noted in
  // the frame's stats.
  bool backFacesHidden(const FrameView& frame, const Model& model, const CameraMatrices& placed);

  std::vector<std::unique_ptr<RenderPass>> paths_;  // by pathIndex()
  TurnResolvePass turnResolve_;
  PatternPlacement pattern_;
  float pixelsPerFrontTriangle_ = 0.0f;  // the model placed last: its density on screen
  const std::vector<Feature*>* active_ = nullptr;  // the frame's, during draw()
};

}  // namespace npr
