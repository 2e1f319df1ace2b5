// Applying pass states (see pass_state.h).
#include "renderer/gl/pass_state.h"

#include <optional>
#include <utility>

namespace npr::gl {

namespace {

// What GL holds of the pass state, as the last apply() set it; none: unknown, set everything.
// Every field is sent when it differs, enabled or not (a blend function while blending is off
// is harmless), so the copy mirrors GL exactly.
std::optional<PassState> g_heldState;
StateTraffic g_stateTraffic;

// Sends `set` when the field differs from what GL holds (or nothing is known).
template <class Field, class Set>
void sendIfChanged(bool all, Field& held, const Field& wanted, Set set) {
  if (all || held != wanted) {
    set();
    held = wanted;
    ++g_stateTraffic.sent;
  } else {
    ++g_stateTraffic.skipped;
  }
}

void setCapability(GLenum capability, bool on) { on ? glEnable(capability) : glDisable(capability); }

}  // namespace

StateTraffic stateTraffic() { return g_stateTraffic; }

void forgetAppliedState() { g_heldState.reset(); }

void apply(const PassState& s) {
  const bool all = !g_heldState;
  if (all) {
    g_heldState.emplace();
    glStencilMask(0xFF);
    glFrontFace(GL_CCW);
  }
  PassState& h = *g_heldState;
  sendIfChanged(all, h.depthTest, s.depthTest, [&] { setCapability(GL_DEPTH_TEST, s.depthTest); });
  sendIfChanged(all, h.depthFunc, s.depthFunc, [&] { glDepthFunc(s.depthFunc); });
  sendIfChanged(all, h.depthWrite, s.depthWrite, [&] { glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE); });
  sendIfChanged(all, h.colorWrite, s.colorWrite, [&] {
    const GLboolean c = s.colorWrite ? GL_TRUE : GL_FALSE;
    glColorMask(c, c, c, c);
  });
  sendIfChanged(all, h.blend, s.blend, [&] { setCapability(GL_BLEND, s.blend); });
  sendIfChanged(all, h.additive, s.additive, [&] {
    if (s.additive) glBlendFunc(GL_ONE, GL_ONE);
    else glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  });
  sendIfChanged(all, h.stencilTest, s.stencilTest, [&] { setCapability(GL_STENCIL_TEST, s.stencilTest); });
  // The function and its reference go in one call: held as one pair.
  std::pair<GLenum, int> func{h.stencilFunc, h.stencilRef};
  sendIfChanged(all, func, std::pair<GLenum, int>{s.stencilFunc, s.stencilRef}, [&] { glStencilFunc(s.stencilFunc, s.stencilRef, 0xFF); });
  h.stencilFunc = func.first;
  h.stencilRef = func.second;
  sendIfChanged(all, h.stencilPass, s.stencilPass, [&] { glStencilOp(GL_KEEP, GL_KEEP, s.stencilPass); });
  sendIfChanged(all, h.scissor, s.scissor, [&] { setCapability(GL_SCISSOR_TEST, s.scissor); });
  sendIfChanged(all, h.programPointSize, s.programPointSize, [&] { setCapability(GL_PROGRAM_POINT_SIZE, s.programPointSize); });
  sendIfChanged(all, h.cull, s.cull, [&] {
    setCapability(GL_CULL_FACE, s.cull != 0);
    if (s.cull != 0) glCullFace(s.cull);
  });
  std::pair<float, float> offset{h.offsetFactor, h.offsetUnits};
  sendIfChanged(all, offset, std::pair<float, float>{s.offsetFactor, s.offsetUnits}, [&] {
    setCapability(GL_POLYGON_OFFSET_FILL, s.offsetFactor != 0.0f || s.offsetUnits != 0.0f);
    glPolygonOffset(s.offsetFactor, s.offsetUnits);
  });
  h.offsetFactor = offset.first;
  h.offsetUnits = offset.second;
}

void restoreDefaults() {
  apply(pass::kBackground);
  glBindVertexArray(0);
  glUseProgram(0);
  forgetAppliedState();
}

}  // namespace npr::gl
