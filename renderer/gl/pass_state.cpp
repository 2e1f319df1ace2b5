// Applying pass states (see pass_state.h).
#include "renderer/gl/pass_state.h"

namespace npr::gl {

void apply(const PassState& s) {
  s.depthTest ? glEnable(GL_DEPTH_TEST) : glDisable(GL_DEPTH_TEST);
  glDepthFunc(s.depthFunc);
  glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
  const GLboolean c = s.colorWrite ? GL_TRUE : GL_FALSE;
  glColorMask(c, c, c, c);
  if (s.blend && s.additive) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  } else if (s.blend) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  } else {
    glDisable(GL_BLEND);
  }
  glStencilMask(0xFF);
  if (s.stencilTest) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(s.stencilFunc, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, s.stencilPass);
  } else {
    glDisable(GL_STENCIL_TEST);
  }
  s.scissor ? glEnable(GL_SCISSOR_TEST) : glDisable(GL_SCISSOR_TEST);
  s.programPointSize ? glEnable(GL_PROGRAM_POINT_SIZE) : glDisable(GL_PROGRAM_POINT_SIZE);
  if (s.cull != 0) {
    glEnable(GL_CULL_FACE);
    glCullFace(s.cull);
    glFrontFace(GL_CCW);
  } else {
    glDisable(GL_CULL_FACE);
  }
  if (s.offsetFactor != 0.0f || s.offsetUnits != 0.0f) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(s.offsetFactor, s.offsetUnits);
  } else {
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
}

void restoreDefaults() {
  apply(pass::kBackground);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace npr::gl
