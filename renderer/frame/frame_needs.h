// What a frame needs before it draws, as the path, the pattern and the active features declare
// it (Feature::needs, RenderPass::needs): the frame derives its answers from these
// declarations instead of asking about features by name.
#pragma once

#include "renderer/settings/render_settings.h"

namespace npr {

struct FrameNeeds {
  // Something reads a deforming mesh's pose on the CPU (the per-triangle paths light its
  // faces there, object-space lines and strokes are found on it, the anchored pattern fits
  // samples read on it); else the GPU's pose serves every pass.
  bool cpuPose = false;
  // A pass shares the bound framebuffer's depth and stencil (the stencil path's masks writing
  // its surface buffers, the turn resolve): a window's own framebuffer cannot be shared, so the
  // window draws such frames offscreen.
  bool sharedDepth = false;
  // Something a surface pass reads is each object's own (its pattern's frame, its occlusion
  // bake, its direction field): the objects are drawn one by one, never merged
  // into batches (scene/scene_batches.h).
  bool objectSurfaces = false;
};

// What a path is asked for its needs with: the settings, and what the scene's palettes and
// models make of them.
struct NeedsQuery {
  const RenderSettings& settings;
  bool turned = false;              // some palette turns its strokes (an oriented entry and a source)
  bool softwareRasterizer = true;   // choices tuned for llvmpipe apply
  // The fewest screen pixels per front-facing triangle of any shown model (the densest).
  float fewestPixelsPerTriangle = 1e30f;
};

// Where a frame poses its deforming meshes (`--deform`). `auto` poses on the GPU, and on the
// CPU too where the frame reads the pose there (FrameNeeds::cpuPose); posing on both then skips
// the CPU copy's upload, which on a GPU costs more than the compute dispatch (an H100: the 871K
// torus's triangle path 22.5 ms posed on the CPU alone, 19.7 ms on both), while on a software
// rasterizer the dispatch runs on the CPU's own cores (llvmpipe: 1.34x against 1.71x the still
// frame), so there the CPU poses alone.
struct PoseTargets {
  bool gpu = false;
  bool cpu = false;
};
// From what the frame needs and the settings' choice (--deform).
PoseTargets poseTargets(const FrameNeeds& needs, PosePlacement deform, bool softwareRasterizer);

}  // namespace npr
