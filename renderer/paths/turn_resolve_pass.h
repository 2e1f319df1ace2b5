// Turned palette lookups once per pixel instead of once per triangle's block of pixels, for
// meshes whose triangles cover about a pixel or less (the 871K torus). A CPU rasterizer shades
// a block of pixels for every triangle however few it covers, so a turn done in the mesh pass
// (the angle's steps and two lookups) is paid many times over; here the mesh pass writes each
// pixel's stroke angle and entry into a float buffer, sharing the bound framebuffer's depth and
// stencil and marking the pixels it writes, and one full-screen pass (shaders/turn_resolve.frag)
// draws the turned texels where marked. Where the framebuffer cannot be shared (the window's
// own) the mesh pass turns in place as before.
#pragma once

#include "renderer/core/result.h"
#include "renderer/gl/shared_depth_framebuffer.h"
#include "renderer/gl/texture_target.h"
#include "renderer/frame/frame_context.h"

namespace npr {

// Where TurnPlacement::Auto turns the lookups: resolved after the mesh pass on a software
// rasterizer whose model has fewer than kResolveTurnPixels pixels per front-facing triangle, in
// the mesh pass everywhere else (the figures are in turn_resolve_pass.cpp).
bool resolveTurnAutomatically(bool softwareRasterizer, float pixelsPerFrontTriangle);
// Whether a mesh pass (of a path that resolvesTurns) leaves its turned lookups to the resolve:
// where it turns them (`turned`), not for the object pattern (its coordinate comes from the
// surface, which the resolve cannot see), by the settings' choice (TurnPlacement) for a model
// of this density. The frame asks it per model, and the window ahead of the frame.
bool turnResolveWanted(const RenderSettings& settings, bool turned, bool objectPattern, bool softwareRasterizer, float pixelsPerFrontTriangle);

class TurnResolvePass {
 public:
  // Binds a buffer and the bound framebuffer's depth and stencil for a mesh pass compiled with
  // MeshProgram::deferTurn and drawn with pass::kMeshMarked; `blend`: the smooth path's, two
  // entries and a weight per pixel. False, with nothing changed, where they cannot be shared:
  // the mesh pass then turns its lookups itself.
  bool begin(FrameContext& f, bool blend);
  // Binds back the caller's framebuffer and draws the turned texels where the mesh pass wrote,
  // clearing its marks.
  [[nodiscard]] Status resolve(FrameContext& f);
  // Binds back the caller's framebuffer without drawing: a mesh pass that failed after begin().
  void cancel() const { target_.restore(); }

 private:
  // The framebuffer's size up to the viewport's far corner: RG32F (angle, entry), and RGBA32F
  // for the smooth path (half the bytes per fragment where one entry is all there is: on the
  // 871K torus the mesh pass writes many times more fragments than there are pixels).
  gl::TextureTarget one_, blend_;
  bool blending_ = false;  // which begin() bound
  gl::SharedDepthFramebuffer target_;
};

}  // namespace npr
