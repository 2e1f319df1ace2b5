// The `stencil` path: the original renderer's algorithm. Per-triangle CPU lighting and
// matching sort the triangles into one bucket per palette entry; then, per non-empty bucket:
// (1) its triangles mark the pixels where they are visible in the stencil (colour writes
// off, depth on), (2) a background quad and (3) the palette layer, alpha-blended, are drawn
// where marked, clearing the mark. Two savings over the original, each a setting: quads
// scissored to the bucket's screen rectangle, and empty buckets skipped. With hatching
// orientation the layer quads turn their lookups per pixel, by angles drawn first into a
// buffer (passes/surface_buffer_pass.h) unless the angle is fixed; with the object-space
// pattern they read its coordinates from another such buffer.
//
// Selection outputs (tests, the benchmark) come from the triangle path: the stencil path has
// no per-pixel program that could write an entry, and its entries are the triangle path's by
// construction (a GL test asserts the two images are equal).
#pragma once

#include "renderer/paths/render_pass.h"
#include "renderer/passes/surface_buffer_pass.h"
#include "renderer/paths/triangle_path.h"

namespace npr {

class StencilPath : public RenderPass {
 public:
  Status draw(FrameContext& frame) override;

 private:
  TrianglePath selection_;
  SurfaceBufferPass strokeAngles_{SurfaceBufferPass::Content::StrokeAngles};
  SurfaceBufferPass patternCoordinates_{SurfaceBufferPass::Content::PatternCoordinates};
};

}  // namespace npr
