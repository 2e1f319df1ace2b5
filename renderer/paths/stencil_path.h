// The `stencil` path: the original renderer's algorithm. Per-triangle CPU lighting and
// matching sort the triangles into one bucket per palette entry; then, per non-empty bucket:
// (1) its triangles mark the pixels where they are visible in the stencil (colour writes
// off, depth on), (2) a background quad and (3) the palette layer, alpha-blended, are drawn
// where marked, clearing the mark. Two savings over the original, each a setting: quads
// scissored to the bucket's screen rectangle, and empty buckets skipped. A third, also a
// setting: every bucket's mask drawn first, the stencil holding the bucket's number, then
// every bucket's quads, each pixel getting only the quads of the bucket it shows. With
// hatching orientation the layer quads turn their lookups per pixel, by angles from a buffer
// (passes/surface_buffer_pass.h) unless the angle is fixed; with the object-space pattern
// they read its coordinates from another such buffer. The masks write both as they mark when
// they are drawn first into a framebuffer whose depth-stencil can be shared.
//
// Selection outputs (tests, the benchmark) come from the triangle path: the stencil path has
// no per-pixel program that could write an entry, and its entries are the triangle path's by
// construction (a GL test asserts the two images are equal).
#pragma once

#include <vector>

#include "renderer/gl/shared_depth_framebuffer.h"
#include "renderer/paths/render_pass.h"
#include "renderer/paths/surface_buffer_pass.h"
#include "renderer/paths/triangle_path.h"

namespace npr {

class StencilPath : public RenderPass {
 public:
  Status draw(FrameContext& frame) override;
  // A scene's objects that can share them (canShare) are lit as they are drawn but marked and
  // covered together at the end: each bucket's quads once for all of them, instead of once per
  // object (bench_scene: 256 objects drew 256 times the quads of one mesh).
  void beginScene() override;
  [[nodiscard]] Status endScene() override;
  // The surface buffers (the stroke angle from the field or the light, the object pattern)
  // are written by the masks into the framebuffer's shared depth-stencil.
  void needs(const NeedsQuery& query, FrameNeeds& needs) const override;
  void prepareScene(FrameView& frame) override;

 private:
  // What an object's draw leaves for endScene: its FrameContext's contents, the references
  // made pointers (they outlive the scene's loop; the camera placed for it is copied).
  struct Shared {
    CameraMatrices camera;
    glm::ivec4 viewport;
    const RenderSettings* settings;
    const LightingState* lighting;
    const GpuMesh* gpuMesh;
    const Mesh* mesh;
    const GpuMaterials* materials;
    const GpuPalette* palette;
    PatternPlacement pattern;
    TriangleShadingCache* triangles;
    gl::ProgramCache* programs;
    FrameStats* stats;
    const gl::VertexArray* emptyVao;
    bool cullBackFaces;
  };
  bool canShare(const FrameContext& frame) const;
  // Masks and quads for one object or several drawn as one; the first gives the frame-wide state.
  Status drawBuckets(const std::vector<FrameContext*>& objects);

  bool sceneOpen_ = false;
  std::vector<Shared> shared_;
  TrianglePath selection_;
  SurfaceBufferPass strokeAngles_{SurfaceBufferPass::Content::StrokeAngles};
  SurfaceBufferPass patternCoordinates_{SurfaceBufferPass::Content::PatternCoordinates};
  gl::SharedDepthFramebuffer maskTarget_;
};

}  // namespace npr
