// Features as modules: what a frame may be drawn with beyond the path itself (shadows,
// occlusion, painterly strokes, lines, the depth cue, ...). Each feature is one folder under
// features/ and one row of the feature table (feature_table.cpp); the frame (renderer.cpp)
// is a loop over the active ones. A feature says whether this frame needs it, prepares what
// the surfaces read (maps, bakes, screen buffers), hands each surface pass its share, and
// draws its passes over the surfaces.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/core/result.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/render_settings.h"
#include "renderer/scene/scene.h"

namespace npr {

struct FrameContext;

// What a feature sees of the frame being drawn.
struct FrameView {
  const CameraMatrices& camera;  // the scene's
  const RenderSettings& settings;
  glm::ivec4 viewport;
  bool colour;  // a picture (else a selection for tests and the benchmark: no passes over it)
  Scene& scene;
  const LightingState& lighting;
  const GpuPalette* palette;  // the main one; null when none is loaded
  // How the palettes' textures lie on the model drawn last (patterns/pattern_placement.h): set
  // per model as each is drawn, so the passes over the frame read the last one's.
  const PatternPlacement& pattern;
  gl::ProgramCache& programs;
  FrameStats& stats;
  const gl::VertexArray& emptyVao;  // full-screen passes make their vertices in the shader
  std::function<Model*()> ground;   // the ground plane's model, built on demand (--ground)
  // Long work in one frame (the occlusion bake) may report how far it got.
  const std::function<void(const std::string&, double)>& progress;
  double workBudgetMs;  // how long such work may take per frame (0: to the end now)
};

class Feature {
 public:
  virtual ~Feature() = default;
  virtual const char* name() const = 0;
  // Whether this frame needs the feature; inactive features are never called.
  virtual bool active(const FrameView& frame) const = 0;
  // Before the frame's clear (shadow maps, bakes).
  [[nodiscard]] virtual Status prepare(FrameView&) { return okStatus(); }
  // After the clear, before the surfaces (buffers of what the frame shows).
  [[nodiscard]] virtual Status afterClear(FrameView&) { return okStatus(); }
  // Its share of a surface pass of `model` (null: the ground): what the pass reads.
  virtual void shade(const FrameView&, const Model*, FrameContext&) {}
  // Passes over the surfaces (lines, strokes, fades), in the table's order; colour frames only.
  [[nodiscard]] virtual Status drawOver(FrameView&) { return okStatus(); }
};

// The feature table, in the order the frame calls them.
std::vector<std::unique_ptr<Feature>> makeFeatures();

}  // namespace npr
