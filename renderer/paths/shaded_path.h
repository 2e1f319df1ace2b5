// The single-pass paths that light on the GPU: one draw of the whole mesh with mesh.frag
// specialised for the shading, the lights in use and the palette's layout.
//   vertex        lit per vertex, matched per pixel
//   pixel         lit and matched per pixel
//   smooth        lit per pixel, the two entries that bracket the tone blended
//   reference     the plain lit colour (Phong, or Gouraud with --gouraud), no palette
//   lit-textured  the benchmark's floor: the lit colour times one palette fetch
#pragma once

#include "renderer/paths/render_pass.h"

namespace npr {

class ShadedPath : public RenderPass {
 public:
  enum class Kind { Vertex, Pixel, Smooth, Reference, LitTextured };
  explicit ShadedPath(Kind kind) : kind_(kind) {}
  Status draw(FrameContext& frame) override;
  bool resolvesTurns() const override { return kind_ == Kind::Vertex || kind_ == Kind::Pixel || kind_ == Kind::Smooth; }

 private:
  Kind kind_;
};

}  // namespace npr
