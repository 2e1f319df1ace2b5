// The turn resolve (see turn_resolve_pass.h).
#include "renderer/paths/turn_resolve_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kTurnBufferUnit = gl::claimTextureUnit();  // a mesh pass's stroke angle and entry per pixel
}  // namespace

namespace {
// Below this many pixels per front-facing triangle, on a software rasterizer, the triangle,
// vertex, pixel and smooth paths turn their lookups once per pixel after the mesh pass. Measured with
// the viewer, headless, 1280x720, triangle path, --orient curvature, orbiting, resolved against
// in the mesh pass, three alternated runs: icosphere-7 (2 pixels a triangle) 8-14% faster,
// icosphere-6 (8) 8-11% faster, icosphere-5 (32) even (-9% to +9%), icosphere-4 (128) 11-24%
// slower, the bunny (178) 13-22% slower. On a GPU the mesh pass wins at every density: an H100
// (tests/bench/gpu_check.sh, bench_frames --turn-placements, 1920x1080) drew the 871K torus
// (1.4 pixels a triangle) 0.1-0.2 ms faster (about 10%) with the turn in the mesh pass than
// resolved, and the bunny 0.1-0.2 ms faster too; so only a software rasterizer resolves.
constexpr float kResolveTurnPixels = 16.0f;
}  // namespace

bool resolveTurnAutomatically(bool softwareRasterizer, float pixelsPerFrontTriangle) {
  return softwareRasterizer && pixelsPerFrontTriangle < kResolveTurnPixels;
}

bool turnResolveWanted(const RenderSettings& s, bool turned, bool objectPattern, bool softwareRasterizer, float pixelsPerFrontTriangle) {
  if (!turned || objectPattern) return false;
  const TurnPlacement where = s.tuning.turnPlacement;
  return where == TurnPlacement::Resolved || (where == TurnPlacement::Auto && resolveTurnAutomatically(softwareRasterizer, pixelsPerFrontTriangle));
}

bool TurnResolvePass::begin(FrameContext& f, bool blend) {
  const glm::ivec4& vp = f.viewport;
  gl::TextureTarget& buffer = blend ? blend_ : one_;
  // Sized to the framebuffer's pixels, written and read at their own coordinates. Full floats:
  // the angle read back is the one the mesh pass found, so the picture is the in-place turn's.
  if (buffer.resize({vp.x + vp.z, vp.y + vp.w}, blend ? GL_RGBA32F : GL_RG32F)) ++f.stats.bufferUploads;
  blending_ = blend;
  return target_.bind({buffer.colour(), 0});
}

Status TurnResolvePass::resolve(FrameContext& f) {
  target_.restore();
  gl::TurnResolveProgram variant{f.paletteVariant(), blending_};
  variant.palette.toneThreshold = variant.palette.toneThreshold && blending_;  // only a blend has two levels to choose from
  variant.palette.patternPerVertex = true;  // three vertices for the whole screen: interpolating always pays
  Result<gl::ShaderProgram*> prog = f.program(variant);
  if (!prog) return Error{prog.error()};
  gl::ShaderProgram& p = **prog;
  const glm::ivec4& vp = f.viewport;
  gl::apply(gl::pass::kTurnResolve);
  glScissor(vp.x, vp.y, vp.z, vp.w);
  p.use();
  f.bindPalette(p);
  gl::bindTexture(kTurnBufferUnit, GL_TEXTURE_2D, (blending_ ? blend_ : one_).colour());
  p.set("uTurnBuffer", gl::unitIndex(kTurnBufferUnit));
  p.set("uBufferOrigin", glm::ivec2(0));
  glBindVertexArray(f.emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++f.stats.drawCalls;
  return okStatus();
}

}  // namespace npr
