// The background pass (see background_pass.h).
#include "renderer/passes/background_pass.h"

#include "renderer/gl/pass_state.h"

namespace npr {

Status drawBackground(const GpuPalette* palette, const PatternPlacement& pattern, gl::ProgramCache& programs, const gl::VertexArray& emptyVao,
                      FrameStats& stats) {
  const bool image = palette && palette->backgroundImage();
  Result<gl::ShaderProgram*> prog = programs.get(gl::QuadProgram{gl::QuadProgram::Kind::Background, image}, stats.shaderBuilds);
  if (!prog) return Error{prog.error()};
  gl::apply(gl::pass::kBackground);
  (*prog)->use();
  if (palette) palette->bindBackground(**prog, pattern);
  else (*prog)->set("uBackgroundColour", glm::vec3(1.0f));
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ++stats.drawCalls;
  return okStatus();
}

}  // namespace npr
