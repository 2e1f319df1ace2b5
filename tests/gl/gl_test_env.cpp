// GL test environment (see gl_test_env.h). Provides main(): creates the context first.
#include "gl/gl_test_env.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <type_traits>

#include "renderer/core/image_io.h"
#include "renderer/gl/gl_debug.h"
#include "renderer/gl/headless_context.h"
#include "renderer/gl/shader_program.h"
#include "support/test_util.h"

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

namespace {
// Runs `draw` into a fresh w x h target (cleared to zero unless it is the image render, which
// draws its own background) and reads it back.
template <class Image>
Image renderInto(int w, int h, bool clear, const std::function<Status(const glm::ivec4&)>& draw) {
  constexpr bool floats = std::is_same_v<Image, ImageRGBA32F>;
  auto t = OffscreenTarget::create(w, h, floats ? OffscreenTarget::Format::RGBA32F : OffscreenTarget::Format::RGBA8);
  EXPECT_TRUE(t) << t.error();
  if (!t) return {};
  if (clear) t->clear(glm::vec4(0.0f));
  else t->bind();
  const Status st = draw({0, 0, w, h});
  EXPECT_TRUE(st) << st.error();
  if constexpr (floats) return t->readRGBA32F();
  else return t->readRGBA8();
}
}  // namespace

ImageRGBA8 renderImage(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h) {
  return renderInto<ImageRGBA8>(w, h, false, [&](const glm::ivec4& vp) { return r.render(cam, s, vp); });
}

ImageRGBA8 renderEntries(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h) {
  return renderInto<ImageRGBA8>(w, h, true, [&](const glm::ivec4& vp) { return r.render(cam, s, vp, FrameOutput::Entry); });
}

ImageRGBA32F renderGeometry(Renderer& r, const CameraMatrices& cam, FrameOutput output, int w, int h) {
  return renderInto<ImageRGBA32F>(w, h, true, [&](const glm::ivec4& vp) { return r.render(cam, RenderSettings{}, vp, output == FrameOutput::EyePosition ? FrameOutput::EyePosition : FrameOutput::EyeNormal); });
}

ImageRGBA32F renderStrokeAngles(Renderer& r, const CameraMatrices& cam, const RenderSettings& s, int w, int h) {
  return renderInto<ImageRGBA32F>(w, h, true, [&](const glm::ivec4& vp) { return r.render(cam, s, vp, FrameOutput::StrokeAngles); });
}

int countDiffering(const ImageRGBA8& a, const ImageRGBA8& b) {
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4)
    if (a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] || a.pixels[i + 2] != b.pixels[i + 2]) ++n;
  return n;
}

void RendererFixture::SetUp() {
  auto made = Renderer::create();
  ASSERT_TRUE(made) << made.error();
  r = std::move(*made);
  applyDefaultMaterial(r->lighting());
  const float pos[4] = {2.0f, 2.5f, 3.0f, 1.0f};
  r->lighting().setModelView(testCamera(1.0f).view);
  ASSERT_TRUE(r->lighting().Lightfv(GL_LIGHT0, GL_POSITION, pos));
}

CameraMatrices testCamera(float aspect, float yaw, float pitch) {
  OrbitCamera c(yaw, pitch, 3.0f);
  c.frame(1.0f);
  return c.matrices(aspect);
}

std::string sourcePath(const std::string& relative) { return std::string(NPR_SOURCE_DIR) + "/" + relative; }

Palette texelIndexPalette() {
  auto spell = [](int size, std::uint8_t level, int step) {
    ImageRGBA8 img{size, size, std::vector<std::uint8_t>(std::size_t(size) * size * 4)};
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        std::uint8_t* t = &img.pixels[(std::size_t(j) * size + i) * 4];
        t[0] = std::uint8_t(i * step), t[1] = std::uint8_t(j * step), t[2] = level, t[3] = 255;
      }
    return img;
  };
  PaletteEntry e;
  e.image = spell(64, 0, 4);
  e.mips = {spell(32, 255, 8)};
  Palette p;
  p.entries = {e};
  return p;
}

Palette greyRamp(int n) {
  Palette p;
  p.name = "ramp" + std::to_string(n);
  for (int i = 0; i < n; ++i) {
    PaletteEntry e;
    const float g = n == 1 ? 0.5f : 1.0f - float(i) / float(n - 1);
    e.image = ImageRGBA8{4, 4, std::vector<std::uint8_t>(64)};
    for (size_t k = 0; k < 64; k += 4) {
      e.image.pixels[k] = e.image.pixels[k + 1] = e.image.pixels[k + 2] = std::uint8_t(std::lround(g * 255));
      e.image.pixels[k + 3] = 255;
    }
    e.average = glm::vec3(g);
    e.intensity = 3 * g;
    p.entries.push_back(std::move(e));
  }
  return p;
}

void expectGolden(const std::string& name, const ImageRGBA8& img, double failFraction, double meanDiff) {
  const std::string golden = sourcePath("tests/golden/" + name + ".png");
  if (const char* u = std::getenv("NPR_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    ASSERT_TRUE(writeImage(golden, img));
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing: run with NPR_UPDATE_GOLDEN=1 to create it";
  OIIO::ImageBuf expected(golden);
  OIIO::ImageBuf actual(OIIO::ImageSpec(img.width, img.height, 4, OIIO::TypeDesc::UINT8), const_cast<std::uint8_t*>(img.pixels.data()));
  ASSERT_EQ(expected.spec().width, img.width);
  ASSERT_EQ(expected.spec().height, img.height);
  const auto cmp = OIIO::ImageBufAlgo::compare(actual, expected, 2.0f / 255.0f, 1.0f / 255.0f);
  const double failed = double(cmp.nfail) / (double(img.width) * img.height);
  const bool ok = failed <= failFraction && cmp.meanerror <= meanDiff;
  EXPECT_TRUE(ok) << name << ": " << cmp.nfail << " pixels differ by more than 2/255 (" << failed * 100 << "%, limit "
                  << failFraction * 100 << "%), mean difference " << cmp.meanerror << " (limit " << meanDiff << "), max "
                  << cmp.maxerror << "; actual and diff images in " << test::outputPath("");
  if (!ok) {
    (void)writeImage(test::outputPath(name + "-actual.png"), img);
    OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(actual, expected);
    diff = OIIO::ImageBufAlgo::mul(diff, 4.0f);
    diff.write(test::outputPath(name + "-diff.png"));
  }
}

Palette shippedPalette(const std::string& name) {
  auto p = loadPalette(sourcePath("palettes/" + name + "/" + name + ".palette"));
  EXPECT_TRUE(p) << p.error();
  return p ? std::move(*p) : Palette{};
}

}  // namespace npr::test

#if defined(__SANITIZE_ADDRESS__)
// Mesa unloads its driver before LeakSanitizer reports, so the driver's own allocations show
// up as leaks "from an unknown module" that no suppression can name. Leak checking stays on
// for the CPU tier; the GL tier relies on ASan's other checks.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  // NPR_GPU picks the device as it does for the viewer (the reference images are llvmpipe's).
  auto gpu = npr::gpuRequestFromEnvironment();
  if (!gpu) {
    std::fprintf(stderr, "%s\n", gpu.error().c_str());
    return 1;
  }
  auto ctx = npr::HeadlessContext::create(true, *gpu);
  if (!ctx) {
    std::fprintf(stderr, "cannot create the headless OpenGL context: %s\n", ctx.error().c_str());
    return 1;  // a GL test program without GL fails; it never skips silently
  }
  std::fprintf(stderr, "GL: %s\n", (*ctx)->info().line().c_str());
  npr::gl::setStrictUniforms(true);  // a misspelled uniform fails the test like a GL error
  ::testing::UnitTest::GetInstance()->listeners().Append(new npr::test::GlErrorCheck);
  return RUN_ALL_TESTS();
}
