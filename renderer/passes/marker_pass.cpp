// The light marker (see marker_pass.h).
#include "renderer/passes/marker_pass.h"

#include "renderer/gl/pass_state.h"
#include "renderer/programs/program_variants.h"

namespace npr {

Status drawMarker(const CameraMatrices& camera, const glm::vec3& worldPosition, const glm::vec3& colour, float pixels,
                  const glm::ivec4& viewport, gl::ProgramCache& programs, const gl::VertexArray& emptyVao, FrameStats& stats) {
  Result<gl::ShaderProgram*> prog = programs.get(gl::MarkerProgram{}, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
  gl::apply(gl::pass::kMarker);
  gl::ShaderProgram& p = **prog;
  p.use();
  p.set("uViewProjection", camera.projection * camera.view);
  p.set("uPosition", worldPosition);
  p.set("uColour", colour);
  p.set("uPointSize", pixels);
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_POINTS, 0, 1);
  gl::restoreDefaults();
  return okStatus();
}

}  // namespace npr
