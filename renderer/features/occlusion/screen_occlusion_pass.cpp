// Screen-space ambient occlusion (see screen_occlusion_pass.h).
#include "renderer/features/occlusion/screen_occlusion_pass.h"

#include <algorithm>
#include <cmath>

#include "renderer/gl/pass_state.h"
#include "renderer/programs/program_variants.h"
#include "renderer/gl/texture_units.h"
#include "renderer/passes/geometry_pass.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kScreenOcclusionUnit = gl::claimTextureUnit();  // the frame's (blurred) estimate, and its passes' inputs
const gl::TextureUnit kScreenOcclusionDepthUnit = gl::claimTextureUnit();  // the frame's depth
const gl::TextureUnit kScreenOcclusionNormalsUnit = gl::claimTextureUnit();  // the frame's normals
}  // namespace
namespace {

constexpr int kKernelSize = 16;  // samples per pixel (screen_occlusion.frag's KERNEL_SIZE)

// Points in the unit hemisphere around +z: directions cosine-weighted (a disc sampled evenly,
// lifted onto the hemisphere: Malley's method, so the estimate weighs directions as the bake
// does), at distances crowding toward the centre, where occluders matter most.
std::vector<glm::vec3> hemisphereKernel(int n) {
  std::vector<glm::vec3> k;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double r = std::sqrt((i + 0.5) / n), a = golden * i;
    const glm::dvec3 d(r * std::cos(a), r * std::sin(a), std::sqrt(std::max(0.0, 1.0 - r * r)));
    const double t = double((i * 5) % n + 1) / n;  // distances spread over the kernel's order
    k.push_back(glm::vec3(d * (0.15 + 0.85 * t * t)));
  }
  return k;
}

}  // namespace

Status ScreenOcclusionPass::draw(const std::vector<PlacedMesh>& meshes, const CameraMatrices& camera, float radius, const glm::ivec4& viewport,
                                 gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats) {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  // Half the viewport's resolution (a quarter of the pixels): occlusion varies slowly, and the
  // frame reads it back filtered.
  const glm::ivec2 size = glm::max(glm::ivec2(viewport.z, viewport.w) / 2, glm::ivec2(1));
  if (geometry_.resize(size, GL_RGBA16F)) ++stats.bufferUploads;
  if (raw_.resize(size, GL_R16F)) ++stats.bufferUploads;
  if (blurred_.resize(size, GL_RG32F)) ++stats.bufferUploads;  // occlusion, linear depth
  if (kernel_.empty()) kernel_ = hemisphereKernel(kKernelSize);
  Status status = okStatus();
  auto restore = [&] {
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  };
  // (1) what the frame shows: normals and depth
  geometry_.bindAndClear();
  for (const PlacedMesh& m : meshes)
    if (status) status = drawGeometry(m, GeometryOutput::EyeNormal, programs, stats);
  const std::string kernel = "KERNEL_SIZE " + std::to_string(kKernelSize);
  Result<gl::ShaderProgram*> estimate = programs.get(gl::FeatureProgram{"fullscreen.vert", "screen_occlusion.frag", {kernel}}, stats.shaderBuilds);
  Result<gl::ShaderProgram*> blur = programs.get(gl::FeatureProgram{"fullscreen.vert", "screen_occlusion.frag", {kernel, "BLUR"}}, stats.shaderBuilds);
  if (status && !estimate) status = Error{estimate.error()};
  if (status && !blur) status = Error{blur.error()};
  if (!status) {
    restore();
    return status;
  }
  gl::apply(gl::pass::kBackground);
  glBindVertexArray(emptyVao.id());
  gl::bindTexture(kScreenOcclusionDepthUnit, GL_TEXTURE_2D, geometry_.depth());
  // (2) the estimate
  raw_.bindAndClear();
  gl::ShaderProgram& e = **estimate;
  e.use();
  gl::bindTexture(kScreenOcclusionNormalsUnit, GL_TEXTURE_2D, geometry_.colour());
  e.set("uNormals", gl::unitIndex(kScreenOcclusionNormalsUnit));
  e.set("uDepth", gl::unitIndex(kScreenOcclusionDepthUnit));
  e.set("uOrigin", glm::ivec2(0));
  const glm::mat4& P = camera.projection;
  e.set("uProjectionXY", glm::vec4(P[0][0], P[1][1], P[2][0], P[2][1]));
  e.set("uProjection", glm::vec2(P[2][2], P[3][2]));
  e.set("uSize", glm::vec2(size));
  e.set("uRadius", radius);
  e.setArray("uKernel", kernel_.data(), int(kernel_.size()));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // (3) the blur
  blurred_.bindAndClear();
  gl::ShaderProgram& b = **blur;
  b.use();
  gl::bindTexture(kScreenOcclusionUnit, GL_TEXTURE_2D, raw_.colour());
  b.set("uOcclusion", gl::unitIndex(kScreenOcclusionUnit));
  b.set("uDepth", gl::unitIndex(kScreenOcclusionDepthUnit));
  b.set("uOrigin", glm::ivec2(0));
  b.set("uProjection", glm::vec2(camera.projection[2][2], camera.projection[3][2]));
  glDrawArrays(GL_TRIANGLES, 0, 3);
  stats.drawCalls += 2;
  restore();
  return okStatus();
}

void ScreenOcclusionPass::bind(gl::ShaderProgram& p, const glm::ivec4& viewport) const {
  gl::bindTexture(kScreenOcclusionUnit, GL_TEXTURE_2D, blurred_.colour());
  p.set("uScreenOcclusion", gl::unitIndex(kScreenOcclusionUnit));
  // Window pixel -> the half-resolution texture's texels.
  const glm::vec2 scale = glm::vec2(blurred_.size()) / glm::vec2(std::max(viewport.z, 1), std::max(viewport.w, 1));
  p.set("uScreenOcclusionFrame", glm::vec4(viewport.x, viewport.y, scale.x, scale.y));
}

}  // namespace npr
