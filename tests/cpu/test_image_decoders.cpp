// PNG and JPEG are decoded without OpenImageIO (stb_image, renderer/core/image_io.cpp) so the
// viewer starts without loading it. These tests hold the two decoders to the same pixels: every
// shipped palette image and assimp's test textures read through loadImage against OpenImageIO's
// own reading of the same file, PNG variants written here (grey, grey+alpha, 16-bit, palette
// with transparency), and PNGs written by writeImage read back by OpenImageIO.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/core/image_io.h"
#include "support/test_util.h"

namespace fs = std::filesystem;

namespace {

// What OpenImageIO reads, expanded to RGBA8 as loadImage does (grey to RGB, opaque when the
// file has no alpha), straight alpha.
npr::ImageRGBA8 readWithOiio(const std::string& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  EXPECT_TRUE(in) << path << ": " << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec spec = in->spec();
  const int nc = spec.nchannels;
  std::vector<float> px(size_t(spec.width) * spec.height * nc);
  EXPECT_TRUE(in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, px.data())) << path;
  npr::ImageRGBA8 out{spec.width, spec.height, std::vector<std::uint8_t>(size_t(spec.width) * spec.height * 4)};
  auto byte = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) {
    const float* s = &px[i * nc];
    for (int k = 0; k < 3; ++k) out.pixels[i * 4 + k] = byte(nc <= 2 ? s[0] : s[k]);
    out.pixels[i * 4 + 3] = byte(nc == 2 ? s[1] : (nc >= 4 ? s[3] : 1.0f));
  }
  return out;
}

struct Difference {
  int largest = 0;
  double mean = 0;
};
Difference compare(const npr::ImageRGBA8& a, const npr::ImageRGBA8& b) {
  Difference d;
  if (a.width != b.width || a.height != b.height) return {256, 256};
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const int e = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    d.largest = std::max(d.largest, e);
    d.mean += e;
  }
  d.mean /= double(std::max<size_t>(1, a.pixels.size()));
  return d;
}

std::vector<std::string> filesUnder(const fs::path& root, const std::vector<std::string>& extensions) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return out;
  for (const auto& e : fs::recursive_directory_iterator(root, ec)) {
    std::string ext = e.path().extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const std::string& want : extensions)
      if (e.is_regular_file() && ext == want) out.push_back(e.path().string());
  }
  return out;
}

}  // namespace

TEST(ImageDecoders, EveryShippedPalettePngDecodesToOpenImageIOsPixels) {
  const std::vector<std::string> files = filesUnder(fs::path(NPR_SOURCE_DIR) / "palettes", {".png"});
  ASSERT_GT(files.size(), 300u);
  int differing = 0;
  for (const std::string& f : files) {
    npr::Result<npr::ImageRGBA8> ours = npr::loadImage(f);
    ASSERT_TRUE(ours) << ours.error();
    const Difference d = compare(*ours, readWithOiio(f));
    if (d.largest != 0) ++differing, ADD_FAILURE() << f << ": differs by up to " << d.largest;
  }
  EXPECT_EQ(differing, 0) << "of " << files.size();
}

// Debian's assimp-testmodels (installed by .ci/setup): textures no one here made, JPEGs among
// them. JPEG decoders differ in their rounding (stb's IDCT and chroma upsampling against
// libjpeg-turbo's), so JPEGs are held to a mean of one level and PNGs to none.
TEST(ImageDecoders, AssimpTexturesDecodeAsOpenImageIODoes) {
  const std::vector<std::string> files = filesUnder("/usr/share/assimp/models", {".png", ".jpg", ".jpeg"});
  ASSERT_FALSE(files.empty()) << "assimp-testmodels is not installed (.ci/setup installs it)";
  int jpegs = 0, pngs = 0;
  for (const std::string& f : files) {
    npr::Result<npr::ImageRGBA8> ours = npr::loadImage(f);
    if (!ours) continue;  // some of assimp's files are deliberately broken; refusals are test_hostile_input's
    const Difference d = compare(*ours, readWithOiio(f));
    const bool jpeg = f.find(".jp") != std::string::npos || f.find(".JP") != std::string::npos;
    (jpeg ? jpegs : pngs)++;
    if (jpeg) EXPECT_LT(d.mean, 1.0) << f;
    else EXPECT_EQ(d.largest, 0) << f;
  }
  EXPECT_GT(jpegs, 0);
  EXPECT_GT(pngs, 0);
}

TEST(ImageDecoders, PngVariantsDecodeAsOpenImageIODoes) {
  npr::test::TempDir dir;
  const int w = 37, h = 23;
  struct Variant {
    const char* name;
    int channels;
    OIIO::TypeDesc type;
  };
  for (const Variant& v : {Variant{"grey8", 1, OIIO::TypeDesc::UINT8}, Variant{"greyalpha8", 2, OIIO::TypeDesc::UINT8},
                           Variant{"rgb16", 3, OIIO::TypeDesc::UINT16}, Variant{"rgba16", 4, OIIO::TypeDesc::UINT16},
                           Variant{"greyalpha16", 2, OIIO::TypeDesc::UINT16}, Variant{"rgba8", 4, OIIO::TypeDesc::UINT8}}) {
    std::vector<float> px(size_t(w) * h * v.channels);
    for (size_t i = 0; i < px.size(); ++i) px[i] = float((i * 7919) % 65536) / 65535.0f;
    const std::string path = (dir.path() / (std::string(v.name) + ".png")).string();
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(w, h, v.channels, v.type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out && out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close()) << path;
    npr::Result<npr::ImageRGBA8> ours = npr::loadImage(path);
    ASSERT_TRUE(ours) << ours.error();
    const Difference d = compare(*ours, readWithOiio(path));
    EXPECT_EQ(d.largest, 0) << v.name;
  }
}

TEST(ImageDecoders, WrittenPngsReadBackExactlyWithStraightAlpha) {
  npr::ImageRGBA8 img{61, 17, std::vector<std::uint8_t>(61 * 17 * 4)};
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = std::uint8_t((i * 131) % 256);
  npr::test::TempDir dir;
  const std::string path = (dir.path() / "written.png").string();
  ASSERT_TRUE(npr::writeImage(path, img));
  const Difference d = compare(img, readWithOiio(path));
  EXPECT_EQ(d.largest, 0);
  npr::Result<std::vector<std::uint8_t>> bytes = npr::encodePng(img);
  ASSERT_TRUE(bytes);
  EXPECT_EQ(std::string(bytes->begin(), bytes->begin() + 4), "\x89PNG");
}

// A frame large enough to be deflated in bands on several threads (png_encoder.cpp) reads back
// exactly, through OpenImageIO's libpng and zlib's checks of the stream and its Adler-32.
TEST(ImageDecoders, AFrameDeflatedInBandsReadsBackExactly) {
  npr::ImageRGBA8 img{1280, 720, std::vector<std::uint8_t>(size_t(1280) * 720 * 4)};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int k = 0; k < 4; ++k)
        img.pixels[(size_t(y) * img.width + x) * 4 + k] = std::uint8_t(k == 3 ? 255 - (x ^ y) % 7 : (x * (k + 1) + y * 3 + (x * y) % 11) % 256);
  npr::test::TempDir dir;
  const std::string path = (dir.path() / "frame.png").string();
  ASSERT_TRUE(npr::writeImage(path, img));
  const Difference d = compare(img, readWithOiio(path));
  EXPECT_EQ(d.largest, 0);
  npr::Result<npr::ImageRGBA8> ours = npr::loadImage(path);
  ASSERT_TRUE(ours) << ours.error();
  EXPECT_EQ(ours->pixels, img.pixels);
}
