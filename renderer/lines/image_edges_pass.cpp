// Image-space edges (see image_edges_pass.h).
#include "renderer/lines/image_edges_pass.h"

#include <algorithm>

#include "renderer/gl/pass_state.h"
#include "renderer/gl/texture_units.h"
#include "renderer/passes/geometry_pass.h"
#include "renderer/programs/program_variants.h"

namespace npr {
namespace {
// This file's samplers' texture units (gl/texture_units.h).
const gl::TextureUnit kEdgeDepthUnit = gl::claimTextureUnit();  // the frame's depth
const gl::TextureUnit kEdgeNormalsUnit = gl::claimTextureUnit();  // the frame's normals
}  // namespace

Status ImageEdgesPass::draw(const std::vector<PlacedMesh>& meshes, const CameraMatrices& camera, const LineSettings& ls, const glm::ivec4& viewport,
                            gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats) {
  if (!ls.imageSpace) return okStatus();
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  if (target_.resize({viewport.z, viewport.w}, GL_RGBA16F)) ++stats.bufferUploads;
  // The geometry pass: normals and depth of what this frame shows.
  target_.bindAndClear();
  Status status = okStatus();
  for (const PlacedMesh& m : meshes)
    if (status) status = drawGeometry(m, GeometryOutput::EyeNormal, programs, stats);
  Result<gl::ShaderProgram*> sobel = programs.get(gl::EdgeProgram{}, stats.shaderBuilds);
  if (status && !sobel) status = Error{sobel.error()};
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  if (!status) return status;
  // The full-screen pass over the frame.
  gl::apply(gl::pass::kScreenOverlay);
  gl::ShaderProgram& p = **sobel;
  p.use();
  gl::bindTexture(kEdgeNormalsUnit, GL_TEXTURE_2D, target_.colour());
  gl::bindTexture(kEdgeDepthUnit, GL_TEXTURE_2D, target_.depth());
  p.set("uNormals", gl::unitIndex(kEdgeNormalsUnit));
  p.set("uDepth", gl::unitIndex(kEdgeDepthUnit));
  p.set("uOrigin", glm::ivec2(viewport.x, viewport.y));
  p.set("uProjection", glm::vec2(camera.projection[2][2], camera.projection[3][2]));
  p.set("uThreshold", std::max(ls.imageThreshold, 1e-3f));
  p.set("uInk", ls.silhouetteColour);
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++stats.drawCalls;
  return okStatus();
}

}  // namespace npr
