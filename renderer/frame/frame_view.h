// What the frame's steps see of the frame being drawn: the camera, settings and viewport, the
// scene and its palettes and lighting, the pattern placement, and the shared GPU resources.
// The features (features/feature.h) and the paths' scene preparation (paths/render_pass.h)
// read it; FrameContext (frame_context.h) is what one surface pass of one part sees.
#pragma once

#include <functional>
#include <string>

#include "renderer/core/camera.h"
#include "renderer/core/frame_stats.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/gl/program_cache.h"
#include "renderer/lighting/lighting_state.h"
#include "renderer/palette/gpu_palette.h"
#include "renderer/palette/palette_set.h"
#include "renderer/patterns/pattern_placement.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/render_settings.h"

namespace npr {

struct FrameView {
  const CameraMatrices& camera;  // the scene's
  const RenderSettings& settings;
  glm::ivec4 viewport;
  bool colour;  // a picture (else a selection for tests and the benchmark: no passes over it)
  Scene& scene;
  const LightingState& lighting;
  const PaletteSet& palettes;
  const GpuPalette* palette;  // the main one; null when none is loaded
  // How the palettes' textures lie on the model drawn last (patterns/pattern_placement.h): set
  // per model as each is drawn, so the passes over the frame read the last one's.
  const PatternPlacement& pattern;
  gl::ProgramCache& programs;
  FrameStats& stats;
  const gl::VertexArray& emptyVao;  // full-screen passes make their vertices in the shader
  // Long work in one frame (the occlusion bake) may report how far it got.
  const std::function<void(const std::string&, double)>& progress;
  double workBudgetMs;  // how long such work may take per frame (0: to the end now)
  glm::ivec2 frameOffset;   // where the viewport sits in the whole frame (a poster's tile)
  bool softwareRasterizer;  // GL_RENDERER names llvmpipe or the like: choices tuned for it apply

  // The palette `model`'s surfaces are drawn with where no material palette applies.
  const GpuPalette* paletteOf(const Model& model) const { return model.palette() ? model.palette() : palette; }
};

}  // namespace npr
