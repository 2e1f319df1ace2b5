// GL test environment (see gl_test_env.h). Provides main(): creates the context first.
#include "gl/gl_test_env.h"

#include <cstdio>

#include "renderer/gl/gl_debug.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/shader_program.h"

namespace npr::test {

void GlErrorCheck::OnTestEnd(const ::testing::TestInfo& info) {
  const int errors = gl::checkErrors(info.name());
  if (errors > 0) {
    std::string all;
    for (const auto& m : gl::errorMessages()) all += "\n  " + m;
    ADD_FAILURE() << errors << " OpenGL error(s) during " << info.name() << ":" << all;
    gl::resetErrors();
  }
}

ImageRGBA8 renderImage(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h) {
  auto t = OffscreenTarget::create(w, h);
  EXPECT_TRUE(t) << t.error();
  if (!t) return {};
  t->bind();
  const Status st = r.render(cam, s, {0, 0, w, h});
  EXPECT_TRUE(st) << st.error();
  return t->readRGBA8();
}

ImageRGBA8 renderEntries(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h) {
  auto t = OffscreenTarget::create(w, h);
  EXPECT_TRUE(t) << t.error();
  if (!t) return {};
  t->clear(glm::vec4(0.0f));
  const Status st = r.renderSelection(cam, s, SelectionOutput::Entry, {0, 0, w, h});
  EXPECT_TRUE(st) << st.error();
  return t->readRGBA8();
}

ImageRGBA32F renderBlend(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h) {
  auto t = OffscreenTarget::create(w, h, OffscreenTarget::Format::RGBA32F);
  EXPECT_TRUE(t) << t.error();
  if (!t) return {};
  t->clear(glm::vec4(0.0f));
  const Status st = r.renderSelection(cam, s, SelectionOutput::Blend, {0, 0, w, h});
  EXPECT_TRUE(st) << st.error();
  return t->readRGBA32F();
}

ImageRGBA32F renderGeometry(Renderer& r, const CameraMatrices& cam, GeometryOutput output, int w, int h) {
  auto t = OffscreenTarget::create(w, h, OffscreenTarget::Format::RGBA32F);
  EXPECT_TRUE(t) << t.error();
  if (!t) return {};
  t->clear(glm::vec4(0.0f));
  const Status st = r.renderGeometry(cam, output, {0, 0, w, h});
  EXPECT_TRUE(st) << st.error();
  return t->readRGBA32F();
}

CameraMatrices testCamera(float aspect, float yaw, float pitch) {
  OrbitCamera c(yaw, pitch, 3.0f);
  c.frame(1.0f);
  return c.matrices(aspect);
}

std::string sourcePath(const std::string& relative) { return std::string(NPR_SOURCE_DIR) + "/" + relative; }

}  // namespace npr::test

#if defined(__SANITIZE_ADDRESS__)
// Mesa unloads its driver before LeakSanitizer reports, so the driver's own allocations show
// up as leaks "from an unknown module" that no suppression can name. Leak checking stays on
// for the CPU tier; the GL tier relies on ASan's other checks.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  auto ctx = npr::HeadlessContext::create(true);
  if (!ctx) {
    std::fprintf(stderr, "cannot create the headless OpenGL context: %s\n", ctx.error().c_str());
    return 1;  // a GL test program without GL fails; it never skips silently
  }
  std::fprintf(stderr, "GL: %s\n", (*ctx)->description().c_str());
  npr::gl::setStrictUniforms(true);  // a misspelled uniform fails the test like a GL error
  ::testing::UnitTest::GetInstance()->listeners().Append(new npr::test::GlErrorCheck);
  return RUN_ALL_TESTS();
}
