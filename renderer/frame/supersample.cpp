// Supersampling (see supersample.h).
#include "renderer/frame/supersample.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"
#include "renderer/programs/program_variants.h"

namespace npr {
namespace {

const gl::TextureUnit kSourceUnit = gl::claimTextureUnit();  // the supersampled frame

}  // namespace

int Supersampler::factorFor(int k, const glm::ivec4& viewport) {
  const int limit = maxFramebufferSide();
  while (k > 1 && (viewport.z * k > limit || viewport.w * k > limit)) --k;
  return std::max(k, 1);
}

Status Supersampler::run(int k, bool filter, const glm::ivec4& viewport, gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats,
                         const std::function<Status(int, const glm::ivec4&)>& draw) {
  k = factorFor(k, viewport);
  if (k <= 1 && !filter) return draw(1, viewport);
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  const glm::ivec2 size(viewport.z * k, viewport.w * k);
  // Kept between frames; made again only when the size grows (a smaller frame uses a corner).
  if (!target_ || target_->width() < size.x || target_->height() < size.y) {
    target_.reset();
    Result<OffscreenTarget> made = OffscreenTarget::create(size.x, size.y);
    if (!made) return Error{"supersampling at " + std::to_string(k) + "x: " + made.error()};
    target_ = std::move(*made);
  }
  target_->bind();
  const Status drawn = draw(k, {0, 0, size.x, size.y});
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(bound));
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  if (!drawn) return drawn;
  Result<gl::ShaderProgram*> prog =
      k > 1 ? programs.get(gl::SupersampleProgram{}, stats.shaderBuilds) : programs.get(gl::EdgeFilterProgram{}, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  gl::PassState state;
  state.scissor = true;
  gl::apply(state);
  glScissor(viewport.x, viewport.y, viewport.z, viewport.w);
  gl::bindTexture(kSourceUnit, GL_TEXTURE_2D, target_->colourTexture());
  gl::ShaderProgram& p = **prog;
  p.use();
  p.set("uSource", gl::unitIndex(kSourceUnit));
  if (k > 1) {
    p.set("uFactor", k);
  } else {
    p.set("uSize", glm::ivec2(viewport.z, viewport.w));
  }
  p.set("uOrigin", glm::vec2(viewport.x, viewport.y));
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++stats.drawCalls;
  gl::restoreDefaults();
  return okStatus();
}

}  // namespace npr
