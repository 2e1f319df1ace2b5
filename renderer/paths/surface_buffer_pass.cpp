// The stencil path's per-pixel buffers (see surface_buffer_pass.h).
#include "renderer/paths/surface_buffer_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kPatternCoordinatesUnit = gl::claimTextureUnit();  // the stencil path's per-pixel object-space pattern coordinates
const gl::TextureUnit kStrokeAnglesUnit = gl::claimTextureUnit();  // the stencil path's per-pixel hatching angles
}  // namespace
namespace {

Status drawMesh(FrameContext& f, const gl::MeshProgram& variant, bool pattern) {
  Result<gl::ShaderProgram*> prog = f.program(variant);
  if (!prog) return Error{prog.error()};
  gl::apply(f.meshPass(gl::pass::kMesh));
  (*prog)->use();
  setMeshTransform(**prog, f.camera);
  if (pattern) f.palette->bindPattern(**prog, f.pattern);
  else f.palette->bindStrokeSource(**prog, f.pattern);
  f.gpuMesh.drawAll();
  ++f.stats.drawCalls;
  return okStatus();
}

}  // namespace

Status drawStrokeAngles(FrameContext& f) {
  gl::MeshProgram variant;
  variant.shading = gl::MeshShading::StrokeAngle;
  variant.stroke = f.strokeSource();
  return drawMesh(f, variant, false);
}

bool SurfaceBufferPass::resize(const glm::ivec2& size, FrameStats& stats) {
  const bool angles = content_ == Content::StrokeAngles;
  // Pattern coordinates grow with zoom (texels per object unit): full floats, the octave packed
  // into the first (shaders/pattern.glsl).
  if (!target_.resize(size, angles ? GL_RG16F : GL_RG32F)) return false;
  ++stats.bufferUploads;
  return true;
}

GLuint SurfaceBufferPass::output(const glm::ivec4& viewport, FrameStats& stats) {
  resize({viewport.x + viewport.z, viewport.y + viewport.w}, stats);
  return target_.colour();
}

Status SurfaceBufferPass::draw(FrameContext& f, const glm::ivec4& meshRect) {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const glm::ivec4& vp = f.viewport;
  const bool angles = content_ == Content::StrokeAngles;
  resize({vp.z, vp.w}, f.stats);
  target_.bind();
  const glm::ivec4 r = glm::clamp(meshRect, glm::ivec4(0), glm::ivec4(vp.z, vp.w, vp.z, vp.w));
  if (r.z <= r.x || r.w <= r.y) {  // nothing of the mesh on screen: nothing to read
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    glViewport(vp.x, vp.y, vp.z, vp.w);
    return okStatus();
  }
  gl::apply(gl::pass::kClearViewport);
  glScissor(r.x, r.y, r.z - r.x, r.w - r.y);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  Status st = okStatus();
  if (angles) {
    st = drawStrokeAngles(f);
  } else {
    gl::MeshProgram variant;
    variant.shading = gl::MeshShading::PatternCoordinate;
    variant.palette = f.paletteVariant();
    variant.palette->orientBins = 0;
    variant.palette->filtered = false;
    st = drawMesh(f, variant, true);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(vp.x, vp.y, vp.z, vp.w);
  glScissor(vp.x, vp.y, vp.z, vp.w);
  return st;
}

void SurfaceBufferPass::bind(gl::ShaderProgram& p, const glm::ivec2& origin) const {
  const bool angles = content_ == Content::StrokeAngles;
  const gl::TextureUnit unit = angles ? kStrokeAnglesUnit : kPatternCoordinatesUnit;
  gl::bindTexture(unit, GL_TEXTURE_2D, target_.colour());
  p.set(angles ? "uStrokeAngles" : "uPatternCoordinates", gl::unitIndex(unit));
  p.set("uViewportOrigin", origin);
}

}  // namespace npr
