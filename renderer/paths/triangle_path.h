// The `triangle` path: the stencil path's per-triangle choice (CPU lighting at each
// triangle's centroid, CPU matching) in one pass. It draws the same bucketed index buffer,
// one draw per non-empty bucket with the entry as a uniform; its image equals the stencil
// path's. (Reading a per-triangle entry by gl_PrimitiveID instead cost llvmpipe about 30%
// more vertex work on the 871K mesh.)
#pragma once

#include "renderer/paths/render_pass.h"

namespace npr {

// Both per-triangle paths' entries and buckets for this frame: lit on the CPU, or (settings'
// triangleLighting; by default when shadows are on) lit and matched on the GPU and read back
// (shading/gpu_triangle_lighting.h). The mesh's own materials stay on the CPU.
[[nodiscard]] Status updateTriangleShading(FrameContext& frame);

class TrianglePath : public RenderPass {
 public:
  Status draw(FrameContext& frame) override;
  bool resolvesTurns() const override { return true; }
  void prepareScene(FrameView& frame) override;
};

}  // namespace npr
