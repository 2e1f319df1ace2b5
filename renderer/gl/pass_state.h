// The fixed-function state of every pass, as one value per pass in one table (after bgfx's
// per-draw state): a pass applies its preset and patches nothing by hand.
#pragma once

#include <epoxy/gl.h>

namespace npr::gl {

struct PassState {
  bool depthTest = false, depthWrite = false;
  GLenum depthFunc = GL_LESS;
  bool colorWrite = true;
  // Colour blends source-over; destination alpha is kept (opaque), so read-backs stay opaque.
  bool blend = false;
  bool additive = false;  // with blend: one + one instead of source-over
  bool stencilTest = false;
  GLenum stencilFunc = GL_ALWAYS;
  int stencilRef = 1;            // the value compared and written (all 8 bits)
  GLenum stencilPass = GL_KEEP;  // op when stencil and depth pass
  bool scissor = false;
  bool programPointSize = false;
  // Depth pushed away by factor x the polygon's depth slope + units x the depth resolution
  // (shadow maps: slope-scaled bias against acne).
  float offsetFactor = 0.0f, offsetUnits = 0.0f;
  // Faces dropped by the rasterizer: GL_FRONT, GL_BACK, or 0 for none (counter-clockwise front).
  GLenum cull = 0;
};

namespace pass {
// Clears: depth (and stencil) writes on, scissored to the viewport when only part of the
// framebuffer is ours (the split view clears two viewports of one window).
inline constexpr PassState kClearTarget = [] { PassState s; s.depthWrite = true; return s; }();
inline constexpr PassState kClearViewport = [] { PassState s; s.depthWrite = true; s.scissor = true; return s; }();
// Background of every path and full-screen passes: behind everything, touches no depth.
inline constexpr PassState kBackground{};
// Mesh drawing: ordinary depth-tested drawing.
inline constexpr PassState kMesh = [] { PassState s; s.depthTest = s.depthWrite = true; return s; }();
// Mesh drawing that leaves its turned lookups to one pass per pixel (passes/turn_resolve_pass.h):
// it marks the pixels it writes in the stencil, and the resolve draws only there, clearing them.
inline constexpr PassState kMeshMarked = [] {
  PassState s;
  s.depthTest = s.depthWrite = s.stencilTest = true;
  s.stencilPass = GL_REPLACE;
  return s;
}();
inline constexpr PassState kTurnResolve = [] {
  PassState s;
  s.stencilTest = s.scissor = true;
  s.stencilFunc = GL_EQUAL;
  s.stencilPass = GL_ZERO;
  return s;
}();
// Stencil path, per bucket: (1) the bucket's triangles mark visible pixels in the stencil,
inline constexpr PassState kStencilMask = [] {
  PassState s;
  s.depthTest = s.depthWrite = true;
  s.colorWrite = false;
  s.stencilTest = true;
  s.stencilPass = GL_REPLACE;
  return s;
}();
// (2) the background where marked, (3) the palette layer blended over it, clearing the mark.
inline constexpr PassState kStencilBackground = [] {
  PassState s;
  s.stencilTest = s.scissor = true;
  s.stencilFunc = GL_EQUAL;
  return s;
}();
inline constexpr PassState kStencilLayer = [] {
  PassState s;
  s.blend = s.stencilTest = s.scissor = true;
  s.stencilFunc = GL_EQUAL;
  s.stencilPass = GL_ZERO;
  return s;
}();
// Control-image palettes over a path's surface: only where the path left exactly this depth
// (every mesh pass computes gl_Position invariantly), blended by the parameter, no depth write.
inline constexpr PassState kControlPalette = [] {
  PassState s;
  s.depthTest = s.blend = true;
  s.depthFunc = GL_EQUAL;
  return s;
}();
// Feature lines: depth-tested against the model (LEQUAL, so lines on its surface pass) but
// writing no depth, blended.
inline constexpr PassState kLines = [] {
  PassState s;
  s.depthTest = s.blend = true;
  s.depthFunc = GL_LEQUAL;
  return s;
}();
// Textured lines: each pixel once per draw (the first fragment marks it in the stencil, cleared
// before), so the segments' overlapping caps at a chain's joints do not blend twice over a
// texture's partial coverage.
inline constexpr PassState kTexturedLines = [] {
  PassState s = kLines;
  s.stencilTest = true;
  s.stencilFunc = GL_NOTEQUAL;
  s.stencilPass = GL_REPLACE;
  return s;
}();
// Hidden lines: drawn only where the surface is in front of them (the lines are pulled towards
// the eye, so a visible line fails this test), blended, writing no depth.
inline constexpr PassState kHiddenLines = [] {
  PassState s;
  s.depthTest = s.blend = true;
  s.depthFunc = GL_GREATER;
  return s;
}();
// Hardware outlines and the charcoal rim: opaque, depth-tested LEQUAL against the front faces
// (only what sticks out past them shows), writing no depth.
inline constexpr PassState kOutline = [] {
  PassState s;
  s.depthTest = true;
  s.depthFunc = GL_LEQUAL;
  return s;
}();
// Offset outlines: back faces only, culled by the rasterizer (no geometry stage needed).
inline constexpr PassState kOutlineBackFaces = [] {
  PassState s = kOutline;
  s.cull = GL_FRONT;
  return s;
}();
// Painterly strokes: blended over the frame in a fixed order, depth-tested against the model
// (nearer surfaces hide them), writing no depth.
inline constexpr PassState kStrokes = [] {
  PassState s;
  s.depthTest = s.blend = true;
  s.depthFunc = GL_LEQUAL;
  return s;
}();
// Screen-space overlays over the frame (image-space edges): blended, no depth.
inline constexpr PassState kScreenOverlay = [] { PassState s; s.blend = true; return s; }();
// Shadow maps: depth only, slope-scaled bias (with the lookup's normal offset, shadows/).
inline constexpr PassState kShadowDepth = [] {
  PassState s;
  s.depthTest = s.depthWrite = true;
  s.colorWrite = false;
  s.offsetFactor = 2.0f;
  s.offsetUnits = 4.0f;
  return s;
}();
// Accumulation into a float target (the occlusion bake): additive, no depth.
inline constexpr PassState kAccumulate = [] { PassState s; s.blend = true; s.additive = true; return s; }();
// The light marker: a point sprite sized by the shader, over everything.
inline constexpr PassState kMarker = [] { PassState s; s.programPointSize = true; return s; }();
}  // namespace pass

// Makes GL hold `state`. Only what differs from the state applied last is sent: a scene's
// objects each apply their pass, and the stencil path two per bucket, so most of a pass state
// is already held (bench_scene counts the calls saved). Every pass writes all stencil bits: the
// mask is set whatever the preset.
void apply(const PassState& state);
// Code that changes these states with raw GL calls (a blit, a clear of part of the window, a
// test's probe) says so, and the next apply() sets every state again. A new context or
// renderer starts from here too.
void forgetAppliedState();
// restoreDefaults leaves the context as an overlay drawn after the renderer expects it (Dear
// ImGui's backend sets its own state but not the stencil mask, the bound program or the
// vertex array), and forgets the applied state, since what runs between frames may change it.
void restoreDefaults();

// GL state calls apply() sent and skipped as already held, since the process started.
struct StateTraffic {
  long long sent = 0;
  long long skipped = 0;
};
StateTraffic stateTraffic();

}  // namespace npr::gl
