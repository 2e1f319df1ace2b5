// The `triangle` path: the stencil path's per-triangle choice (CPU lighting at each
// triangle's centroid, CPU matching) in one pass. It draws the same bucketed index buffer,
// one draw per non-empty bucket with the entry as a uniform; its image equals the stencil
// path's. (Reading a per-triangle entry by gl_PrimitiveID instead cost llvmpipe about 30%
// more vertex work on the 871K mesh.)
#pragma once

#include "renderer/paths/render_pass.h"

namespace npr {

class TrianglePath : public RenderPass {
 public:
  Status draw(FrameContext& frame) override;
};

}  // namespace npr
