// The interface every render path implements (frame/frame_context.h has the context it is
// called with). A path draws the model into the bound framebuffer over the background the
// Renderer has drawn; it owns whatever GPU state it needs beyond the shared resources in the
// context, and sets its fixed-function state from the presets in gl/pass_state.h.
#pragma once

#include "renderer/core/result.h"
#include "renderer/frame/frame_context.h"
#include "renderer/frame/frame_needs.h"
#include "renderer/frame/frame_view.h"

namespace npr {

class RenderPass {
 public:
  virtual ~RenderPass() = default;
  [[nodiscard]] virtual Status draw(FrameContext& frame) = 0;
  // Around the draws of a scene's surfaces in one frame (not the ground-only or per-object
  // passes): a path that can draw several objects' work together defers it to endScene.
  virtual void beginScene() {}
  [[nodiscard]] virtual Status endScene() { return okStatus(); }
  // What a frame it draws needs before it draws, beyond its table row (path_table.h).
  virtual void needs(const NeedsQuery&, FrameNeeds&) const {}
  // Whether its mesh passes may leave turned lookups to the turn resolve
  // (passes/turn_resolve_pass.h), which shares the framebuffer's depth.
  virtual bool resolvesTurns() const { return false; }
  // Before a colour frame's surfaces, once per frame, with the scene's palettes ready.
  virtual void prepareScene(FrameView&) {}
};

}  // namespace npr
