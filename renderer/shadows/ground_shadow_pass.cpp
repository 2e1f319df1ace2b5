// The ground plane's shadow texture (see ground_shadow_pass.h).
#include "renderer/shadows/ground_shadow_pass.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"
#include "renderer/programs/program_variants.h"
#include "renderer/gl/texture_units.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kGroundShadowsUnit = gl::claimTextureUnit();  // the ground plane's visibility per light
}  // namespace

Status GroundShadowPass::update(const ShadowMaps& maps, const Mesh& ground, unsigned groundVersion, gl::ProgramCache& programs,
                                const gl::VertexArray& emptyVao, FrameStats& stats) {
  // Every redraw of the maps counts a generation (a light gone or added included): nothing new,
  // nothing to do, every frame the light stays.
  if (maps.generation() == mapsGeneration_ && groundVersion == groundVersion_) return okStatus();
  ready_ = false;
  auto settled = [&] {  // this generation is done with (a failure above it is tried again)
    mapsGeneration_ = maps.generation();
    groundVersion_ = groundVersion;
    return okStatus();
  };
  const std::vector<glm::vec4> keys = maps.lightKeys();
  if (maps.layers() == 0 || keys.empty() || int(keys.size()) > kMaxLights || ground.positions.empty()) return settled();
  glm::vec3 lo(ground.positions.front()), hi(lo);
  for (const glm::vec3& p : ground.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  rect_ = glm::vec4(lo.x, lo.z, hi.x, hi.z);
  Result<gl::ShaderProgram*> prog = programs.get(gl::GroundShadowProgram{int(keys.size()), maps.layers()}, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  GLint target = 0;
  GLint viewport[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  glGetIntegerv(GL_VIEWPORT, viewport);
  if (target_.resize({kSize, kSize}, GL_RGBA8)) {
    ++stats.bufferUploads;
    sampled_ = gl::createTexture();
    glBindTexture(GL_TEXTURE_2D, sampled_.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kSize, kSize);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  target_.bindAndClear();
  gl::apply(gl::pass::kBackground);
  gl::ShaderProgram& p = **prog;
  p.use();
  maps.bind(p, glm::mat4(1.0f));  // the identity view: shadows.glsl in model space
  p.set("uGroundRect", rect_);
  p.set("uGroundY", lo.y);
  p.set("uSize", glm::vec2(kSize));
  p.setArray("uLightKey", keys.data(), int(keys.size()));
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++stats.drawCalls;
  glCopyImageSubData(target_.colour(), GL_TEXTURE_2D, 0, 0, 0, 0, sampled_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, kSize, kSize, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  ready_ = true;
  return settled();
}

void GroundShadowPass::bind(gl::ShaderProgram& p) const {
  gl::bindTexture(kGroundShadowsUnit, GL_TEXTURE_2D, sampled_.id());
  p.set("uGroundShadows", gl::unitIndex(kGroundShadowsUnit));
  // Model x, z -> the texture's coordinates: (xz - origin) * scale.
  const glm::vec2 extent = glm::max(glm::vec2(rect_.z - rect_.x, rect_.w - rect_.y), glm::vec2(1e-12f));
  p.set("uGroundShadowFrame", glm::vec4(rect_.x, rect_.y, 1.0f / extent.x, 1.0f / extent.y));
}

}  // namespace npr
