// GL tier: programs, their uniforms, the program cache and the pass states. A uniform name
// that no stage declares is reported like a GL error (so the test that triggers it fails); a
// uniform a variant compiled out is skipped quietly; the cache builds each variant once; each
// pass-state preset is what GL holds after it is applied; an off-screen target resized in the
// middle of a pass leaves that pass's bindings alone.
#include <gtest/gtest.h>

#include "gl/gl_test_env.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/offscreen_target.h"
#include "renderer/gl/pass_state.h"
#include "renderer/gl/program_cache.h"
#include "renderer/gl/shader_program.h"
#include "renderer/gl/texture_target.h"

namespace npr {
namespace {

TEST(ShaderProgram, AMisspelledUniformIsReported) {
  Result<gl::ShaderProgram> p = gl::ShaderProgram::build("marker.vert", "marker.frag", {});
  ASSERT_TRUE(p) << p.error();
  p->use();
  const int before = gl::checkErrors("before");
  p->set("uColour", glm::vec3(1.0f));
  EXPECT_EQ(gl::checkErrors("declared uniform"), before);
  p->set("uColor", glm::vec3(1.0f));  // the typo the driver would ignore
  EXPECT_EQ(gl::checkErrors("misspelled uniform"), before + 1);
  const auto messages = gl::errorMessages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.back().find("uColor"), std::string::npos) << messages.back();
  EXPECT_NE(messages.back().find("marker.vert+marker.frag"), std::string::npos) << messages.back();
  p->set("uColor", glm::vec3(1.0f));  // reported once per program and name, not per frame
  EXPECT_EQ(gl::checkErrors("again"), before + 1);
  gl::resetErrors();  // the error was this test's point
  glUseProgram(0);
}

TEST(ShaderProgram, ACompiledOutUniformIsSkippedQuietly) {
  // Without BACKGROUND_IMAGE the background quad has no uBackground sampler, but the name is
  // in its source: setting it is a no-op, as glUniform at location -1 is.
  Result<gl::ShaderProgram> p = gl::ShaderProgram::build("fullscreen.vert", "quad.frag", {"QUAD_BACKGROUND"});
  ASSERT_TRUE(p) << p.error();
  p->use();
  const int before = gl::checkErrors("before");
  p->set("uBackground", 1);
  p->set("uBackgroundColour", glm::vec3(0.5f));
  EXPECT_EQ(gl::checkErrors("after"), before);
  glUseProgram(0);
}

// A program keeps its uniforms between draws: a value set again unchanged is not sent again,
// a changed one is, and each program remembers its own.
TEST(ShaderProgram, SendsAUniformOnlyWhenItsValueChanges) {
  Result<gl::ShaderProgram> a = gl::ShaderProgram::build("marker.vert", "marker.frag", {});
  Result<gl::ShaderProgram> b = gl::ShaderProgram::build("marker.vert", "marker.frag", {});
  ASSERT_TRUE(a && b);
  const GLint locA = glGetUniformLocation(a->id(), "uColour"), locB = glGetUniformLocation(b->id(), "uColour");
  ASSERT_GE(locA, 0);
  auto held = [](const gl::ShaderProgram& p, GLint loc) {
    glm::vec3 v(-1.0f);
    glGetUniformfv(p.id(), loc, &v.x);
    return v;
  };
  a->use();
  gl::UniformTraffic t0 = gl::uniformTraffic();
  a->set("uColour", glm::vec3(0.25f, 0.5f, 0.75f));
  gl::UniformTraffic t1 = gl::uniformTraffic();
  EXPECT_EQ(t1.sent - t0.sent, 1);
  EXPECT_EQ(held(*a, locA), glm::vec3(0.25f, 0.5f, 0.75f));
  a->set("uColour", glm::vec3(0.25f, 0.5f, 0.75f));  // unchanged: not sent
  gl::UniformTraffic t2 = gl::uniformTraffic();
  EXPECT_EQ(t2.sent, t1.sent);
  EXPECT_EQ(t2.unchanged - t1.unchanged, 1);
  a->set("uColour", glm::vec3(0.25f, 0.5f, 0.8f));  // one component changed: sent
  EXPECT_EQ(gl::uniformTraffic().sent - t2.sent, 1);
  EXPECT_EQ(held(*a, locA), glm::vec3(0.25f, 0.5f, 0.8f));
  // The same value in another program is that program's first: sent, and held there.
  b->use();
  const gl::UniformTraffic t3 = gl::uniformTraffic();
  b->set("uColour", glm::vec3(0.25f, 0.5f, 0.8f));
  EXPECT_EQ(gl::uniformTraffic().sent - t3.sent, 1);
  EXPECT_EQ(held(*b, locB), glm::vec3(0.25f, 0.5f, 0.8f));
  // Back to the first program's earlier value: sent, because the program holds the newer one.
  a->use();
  a->set("uColour", glm::vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(held(*a, locA), glm::vec3(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(held(*b, locB), glm::vec3(0.25f, 0.5f, 0.8f));
  glUseProgram(0);
}

TEST(ProgramCache, BuildsEachVariantOnce) {
  gl::ProgramCache cache;
  int builds = 0;
  gl::MeshProgram pixel;
  pixel.shading = gl::MeshShading::EyeNormal;
  Result<gl::ShaderProgram*> a = cache.get(pixel, builds);
  ASSERT_TRUE(a) << a.error();
  Result<gl::ShaderProgram*> b = cache.get(pixel, builds);
  ASSERT_TRUE(b);
  EXPECT_EQ(*a, *b);
  EXPECT_EQ(builds, 1);
  pixel.shading = gl::MeshShading::EyePosition;
  Result<gl::ShaderProgram*> c = cache.get(pixel, builds);
  ASSERT_TRUE(c);
  EXPECT_NE(*a, *c);
  EXPECT_EQ(builds, 2);
}

TEST(ProgramCache, KeepsAtMostItsCapacityDroppingTheLeastRecentlyUsedBetweenFrames) {
  gl::ProgramCache cache(2);
  int builds = 0;
  gl::MeshProgram normal, position, object;  // three different programs
  normal.shading = gl::MeshShading::EyeNormal;
  position.shading = gl::MeshShading::EyePosition;
  object.shading = gl::MeshShading::EyeNormal;
  object.occlusion = true;
  // Within a frame nothing goes, whatever the count: pointers handed out stay valid.
  cache.startFrame();
  ASSERT_TRUE(cache.get(normal, builds));
  cache.startFrame();
  ASSERT_TRUE(cache.get(position, builds));
  ASSERT_TRUE(cache.get(object, builds));
  Result<gl::ShaderProgram*> stillValid = cache.get(position, builds);
  ASSERT_TRUE(stillValid);
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_EQ(builds, 3);
  // The next frame drops the one unused longest (normal); the others are kept, not rebuilt.
  cache.startFrame();
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.evictions(), 1u);
  ASSERT_TRUE(cache.get(position, builds));
  ASSERT_TRUE(cache.get(object, builds));
  EXPECT_EQ(builds, 3);
  ASSERT_TRUE(cache.get(normal, builds));
  EXPECT_EQ(builds, 4);  // built again after it went
}

TEST(ShaderProgram, ACompileErrorNamesTheFileAndVariant) {
  // PALETTE_SIZE without a value makes palette.glsl's arrays invalid.
  Result<gl::ShaderProgram> p = gl::ShaderProgram::build("mesh.vert", "mesh.frag", {"PATH_PIXEL", "PALETTE_SIZE", "MATCH_INTENSITY"});
  ASSERT_FALSE(p);
  EXPECT_NE(p.error().find("mesh.frag"), std::string::npos) << p.error();
  EXPECT_NE(p.error().find("-DPATH_PIXEL"), std::string::npos) << p.error();
  gl::resetErrors();  // the driver may report the failed compile through KHR_debug too
}

bool enabled(GLenum cap) { return glIsEnabled(cap) == GL_TRUE; }
GLint integer(GLenum what) {
  GLint v = 0;
  glGetIntegerv(what, &v);
  return v;
}

void expectApplied(const gl::PassState& s, const char* name) {
  SCOPED_TRACE(name);
  gl::apply(s);
  EXPECT_EQ(enabled(GL_DEPTH_TEST), s.depthTest);
  EXPECT_EQ(GLenum(integer(GL_DEPTH_FUNC)), s.depthFunc);
  EXPECT_EQ(integer(GL_DEPTH_WRITEMASK) != 0, s.depthWrite);
  GLboolean colour[4] = {};
  glGetBooleanv(GL_COLOR_WRITEMASK, colour);
  for (GLboolean c : colour) EXPECT_EQ(c == GL_TRUE, s.colorWrite);
  EXPECT_EQ(enabled(GL_BLEND), s.blend);
  if (s.blend && s.additive) {
    EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_ONE);
    EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_ONE);
  } else if (s.blend) {
    EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
    EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_ONE_MINUS_SRC_ALPHA);
    EXPECT_EQ(integer(GL_BLEND_SRC_ALPHA), GL_ZERO);  // destination alpha stays opaque
    EXPECT_EQ(integer(GL_BLEND_DST_ALPHA), GL_ONE);
  }
  EXPECT_EQ(enabled(GL_STENCIL_TEST), s.stencilTest);
  if (s.stencilTest) {
    EXPECT_EQ(GLenum(integer(GL_STENCIL_FUNC)), s.stencilFunc);
    EXPECT_EQ(integer(GL_STENCIL_REF), s.stencilRef);
    EXPECT_EQ(GLenum(integer(GL_STENCIL_PASS_DEPTH_PASS)), s.stencilPass);
  }
  EXPECT_EQ(enabled(GL_SCISSOR_TEST), s.scissor);
  EXPECT_EQ(enabled(GL_PROGRAM_POINT_SIZE), s.programPointSize);
  EXPECT_EQ(enabled(GL_CULL_FACE), s.cull != 0);
  if (s.cull != 0) {
    EXPECT_EQ(GLenum(integer(GL_CULL_FACE_MODE)), s.cull);
  }
  EXPECT_EQ(enabled(GL_POLYGON_OFFSET_FILL), s.offsetFactor != 0.0f || s.offsetUnits != 0.0f);
  if (s.offsetFactor != 0.0f || s.offsetUnits != 0.0f) {
    GLfloat factor = 0.0f, units = 0.0f;
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &units);
    EXPECT_EQ(factor, s.offsetFactor);
    EXPECT_EQ(units, s.offsetUnits);
  }
  EXPECT_EQ(integer(GL_STENCIL_WRITEMASK) & 0xFF, 0xFF);
}

TEST(PassState, EveryPresetIsWhatGlHoldsAfterApplyingIt) {
  // A framebuffer with stencil bits: GL reports the reference clamped to them.
  auto target = OffscreenTarget::create(4, 4);
  ASSERT_TRUE(target);
  target->bind();
  // Applied in an order where each preset differs from the previous one in what it sets.
  expectApplied(gl::pass::kClearViewport, "clear viewport");
  expectApplied(gl::pass::kStencilMask, "stencil mask");
  expectApplied(gl::pass::kLines, "lines");
  expectApplied(gl::pass::kStencilLayer, "stencil layer");
  expectApplied(gl::pass::kMarker, "marker");
  expectApplied(gl::pass::kStencilBackground, "stencil background");
  expectApplied(gl::pass::kMesh, "mesh");
  expectApplied(gl::pass::kScreenOverlay, "screen overlay");
  expectApplied(gl::pass::kClearTarget, "clear target");
  expectApplied(gl::pass::kBackground, "background");
  expectApplied(gl::pass::kShadowDepth, "shadow depth");
  expectApplied(gl::pass::kAccumulate, "accumulate");
  expectApplied(gl::pass::kOutlineBackFaces, "outline back faces");
  expectApplied(gl::pass::kTexturedLines, "textured lines");
  // The stencil path's buckets differ only in their reference.
  gl::PassState marked = gl::pass::kStencilLayer;
  for (int mark : {3, 4, 1}) {
    marked.stencilRef = mark;
    expectApplied(marked, "stencil layer, another mark");
  }
  // What an overlay drawn after the renderer finds.
  gl::apply(gl::pass::kStencilLayer);
  gl::restoreDefaults();
  EXPECT_FALSE(enabled(GL_DEPTH_TEST) || enabled(GL_STENCIL_TEST) || enabled(GL_SCISSOR_TEST) || enabled(GL_BLEND));
  EXPECT_EQ(integer(GL_STENCIL_WRITEMASK) & 0xFF, 0xFF);
  EXPECT_EQ(integer(GL_CURRENT_PROGRAM), 0);
  EXPECT_EQ(integer(GL_VERTEX_ARRAY_BINDING), 0);
}

// apply() sends only what differs from the state it applied last; after raw GL changes the
// code says so (forgetAppliedState) and the next apply() sets everything again.
TEST(PassState, WhatIsHeldIsNotSentAgainUntilForgotten) {
  gl::apply(gl::pass::kMesh);
  const gl::StateTraffic t0 = gl::stateTraffic();
  gl::apply(gl::pass::kMesh);
  const gl::StateTraffic t1 = gl::stateTraffic();
  EXPECT_EQ(t1.sent, t0.sent);
  EXPECT_GT(t1.skipped, t0.skipped);
  gl::PassState layer = gl::pass::kMesh;
  layer.blend = true;  // one field differs: one call
  gl::apply(layer);
  EXPECT_EQ(gl::stateTraffic().sent - t1.sent, 1);
  glDisable(GL_DEPTH_TEST);  // behind apply()'s back
  gl::apply(layer);
  EXPECT_FALSE(enabled(GL_DEPTH_TEST));  // held as far as apply() knows: not sent
  gl::forgetAppliedState();
  expectApplied(layer, "after forgetting");
  gl::restoreDefaults();
}

// Passes resize their buffers while the caller's framebuffer is bound for drawing: the resize
// must not rebind it (nor the active unit's texture), and the target must be complete.
TEST(TextureTarget, ResizingLeavesBindingsAloneAndGivesACompleteTarget) {
  const int before = gl::checkErrors("before");
  GLuint fbo = 0, tex = 0;
  glCreateFramebuffers(1, &fbo);
  glCreateTextures(GL_TEXTURE_2D, 1, &tex);
  glTextureStorage2D(tex, 1, GL_RGBA8, 4, 4);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, tex);
  gl::TextureTarget target;
  for (const glm::ivec2 size : {glm::ivec2(37, 21), glm::ivec2(64, 48)}) {
    ASSERT_TRUE(target.resize(size, GL_RG32F));
    EXPECT_EQ(integer(GL_DRAW_FRAMEBUFFER_BINDING), GLint(fbo)) << size.x;
    EXPECT_EQ(integer(GL_READ_FRAMEBUFFER_BINDING), GLint(fbo)) << size.x;
    EXPECT_EQ(integer(GL_TEXTURE_BINDING_2D), GLint(tex)) << size.x;
    EXPECT_FALSE(target.resize(size, GL_RG32F));  // same size: nothing reallocated
    // Complete, and drawn to at its own size.
    target.bindAndClear();
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    GLint v[4] = {};
    glGetIntegerv(GL_VIEWPORT, v);
    EXPECT_EQ(glm::ivec2(v[2], v[3]), size);
    GLint w = 0;
    glGetTextureLevelParameteriv(target.colour(), 0, GL_TEXTURE_WIDTH, &w);
    EXPECT_EQ(w, size.x);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  }
  EXPECT_EQ(gl::checkErrors("texture target"), before);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &tex);
}

}  // namespace
}  // namespace npr
