// Image reading, resizing and writing through OpenImageIO (see image_io.h).
#include "renderer/core/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <memory>

#include "renderer/core/colour.h"
#include "renderer/core/input_file.h"

namespace npr {
namespace {

// A PNG's chunks must fit in the file: libpng allocates a chunk's declared length before it
// reads it, so one bad length field in a file of a few hundred bytes cost 1.8 GB (fuzz_image).
// Walks the chunk headers (12 bytes each) without reading their data; files that are not PNG
// pass.
Status checkPngChunks(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream f(path, std::ios::binary);
  unsigned char head[8] = {};
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  if (!f.read(reinterpret_cast<char*>(head), 8) || !std::equal(head, head + 8, kSignature)) return okStatus();
  std::uintmax_t at = 8;
  while (at + 8 <= fileSize) {
    unsigned char h[8];
    f.seekg(static_cast<std::streamoff>(at));
    if (!f.read(reinterpret_cast<char*>(h), 8)) break;
    const std::uint32_t length = std::uint32_t(h[0]) << 24 | std::uint32_t(h[1]) << 16 | std::uint32_t(h[2]) << 8 | h[3];
    std::string type(reinterpret_cast<const char*>(h + 4), 4);
    for (char& c : type)
      if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    // Data and CRC after the header.
    if (std::uintmax_t(length) + 12 > fileSize - at)
      return Error{path + ": corrupt PNG: chunk '" + type + "' at byte " + std::to_string(at) + " declares " + std::to_string(length) +
                   " bytes of data, and the file has " + std::to_string(fileSize - at - std::min<std::uintmax_t>(12, fileSize - at)) +
                   " left"};
    if (type == "IEND") break;
    at += std::uintmax_t(length) + 12;
  }
  return okStatus();
}

// Opens the image after the input-file checks; returns the reader and its spec checked.
Result<std::unique_ptr<OIIO::ImageInput>> openImage(const std::string& path) {
  Result<std::uintmax_t> file = checkInputFile(path, InputKind::Image);
  if (!file) return Error{file.error()};
  if (Status png = checkPngChunks(path, *file); !png) return Error{png.error()};
  // Keep straight (unassociated) alpha: OpenImageIO would otherwise premultiply PNG and TGA
  // colours on read, and the compositing below expects straight alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) {
    std::string why = OIIO::geterror();
    if (why.empty()) why = "unsupported or corrupt image";
    return Error{path + ": cannot read image: " + why};
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide)
    return Error{path + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                 " is outside 1.." + std::to_string(kMaxImageSide)};
  if (spec.nchannels < 1 || spec.nchannels > 64) return Error{path + ": image has " + std::to_string(spec.nchannels) + " channels"};
  return in;
}

// Area weights of source columns for each output column: output x covers source
// [x * scale, (x + 1) * scale).
struct Footprint {
  std::vector<int> first;       // per output: index into taps
  std::vector<int> src;         // per tap: source index
  std::vector<float> weight;    // per tap: covered fraction of that source pixel
};

Footprint footprint(int srcSize, int outSize) {
  Footprint f;
  const double scale = double(srcSize) / outSize;
  for (int o = 0; o < outSize; ++o) {
    f.first.push_back(static_cast<int>(f.src.size()));
    const double a = o * scale, b = (o + 1) * scale;
    for (int s = static_cast<int>(a); s < srcSize && s < b; ++s) {
      const double w = std::min<double>(b, s + 1) - std::max<double>(a, s);
      if (w > 0) f.src.push_back(s), f.weight.push_back(static_cast<float>(w));
    }
  }
  f.first.push_back(static_cast<int>(f.src.size()));
  return f;
}

}  // namespace

Result<ImageSize> readImageSize(const std::string& path) {
  Result<std::unique_ptr<OIIO::ImageInput>> in = openImage(path);
  if (!in) return Error{in.error()};
  return ImageSize{(*in)->spec().width, (*in)->spec().height};
}

Result<ImageRGBA8> loadImage(const std::string& path, ImageSize fit) {
  Result<std::unique_ptr<OIIO::ImageInput>> opened = openImage(path);
  if (!opened) return Error{opened.error()};
  OIIO::ImageInput& in = **opened;
  const OIIO::ImageSpec spec = in.spec();
  const int nc = spec.nchannels;
  const int alpha = spec.alpha_channel >= 0 && spec.alpha_channel < nc ? spec.alpha_channel : (nc == 2 ? 1 : (nc >= 4 ? 3 : -1));
  const bool isFloat = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
                       spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  const int outW = std::max(1, std::min(spec.width, fit.width)), outH = std::max(1, std::min(spec.height, fit.height));
  const bool reduce = outW != spec.width || outH != spec.height;
  ImageRGBA8 img{outW, outH, std::vector<std::uint8_t>(static_cast<size_t>(outW) * outH * 4)};
  // Reduction: each source row is averaged horizontally into linear, alpha-weighted sums
  // (r a, g a, b a, a) and added to the output rows it overlaps, weighted by the overlap.
  const Footprint fx = reduce ? footprint(spec.width, outW) : Footprint{};
  const double scaleY = double(spec.height) / outH;
  std::vector<double> acc(reduce ? static_cast<size_t>(outW) * 4 * 2 : 0);  // two output rows in flight
  std::vector<float> rowSum(reduce ? static_cast<size_t>(outW) * 4 : 0);
  int accRow = 0;  // the output row in acc's first half
  const double area = scaleY * double(spec.width) / outW;  // of one output pixel, in source pixels
  auto finishRow = [&](int oy) {
    double* a = &acc[0];
    for (int x = 0; x < outW; ++x) {
      const double* s = &a[static_cast<size_t>(x) * 4];
      std::uint8_t* d = &img.pixels[(static_cast<size_t>(oy) * outW + x) * 4];
      const double cover = s[3];
      for (int k = 0; k < 3; ++k) d[k] = toByte(linearToSrgb(cover > 1e-12 ? float(s[k] / cover) : 0.0f));
      d[3] = toByte(float(cover / area));
    }
    std::copy(acc.begin() + outW * 4, acc.end(), acc.begin());
    std::fill(acc.begin() + outW * 4, acc.end(), 0.0);
  };

  const int rowsPerChunk = 64;
  std::vector<float> buf(static_cast<size_t>(spec.width) * rowsPerChunk * nc);
  std::vector<float> lin(reduce ? static_cast<size_t>(spec.width) * 4 : 0);
  // Rows are read in the file's own format into a buffer kept across chunks and converted
  // here: asked for floats, OpenImageIO allocates a conversion buffer on every call, which
  // under the sanitizers (fresh pages, poisoned and quarantined) cost seconds per palette.
  // Files whose channels differ in format are left to its conversion.
  const bool native = spec.channelformats.empty();
  std::vector<unsigned char> raw(native ? spec.scanline_bytes(true) * rowsPerChunk : 0);
  for (int y0 = 0; y0 < spec.height; y0 += rowsPerChunk) {
    const int y1 = std::min(spec.height, y0 + rowsPerChunk);
    const bool read = native ? in.read_scanlines(0, 0, y0 + spec.y, y1 + spec.y, 0, 0, nc, OIIO::TypeDesc::UNKNOWN, raw.data()) &&
                                   OIIO::convert_pixel_values(spec.format, raw.data(), OIIO::TypeDesc::FLOAT, buf.data(),
                                                              (y1 - y0) * spec.width * nc)
                             : in.read_scanlines(0, 0, y0 + spec.y, y1 + spec.y, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data());
    if (!read) {
      std::string why = in.geterror();
      return Error{path + ": image data could not be read (truncated or corrupt): " + (why.empty() ? "read failed" : why)};
    }
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const float* s = &buf[(static_cast<size_t>(y - y0) * spec.width + x) * nc];
        float rgb[3];
        if (nc <= 2) rgb[0] = rgb[1] = rgb[2] = s[0];
        else for (int k = 0; k < 3; ++k) rgb[k] = s[k];
        const float a = alpha >= 0 ? std::clamp(s[alpha], 0.0f, 1.0f) : 1.0f;
        if (reduce) {
          float* l = &lin[static_cast<size_t>(x) * 4];
          for (int k = 0; k < 3; ++k) {
            const float v = std::isfinite(rgb[k]) ? std::clamp(rgb[k], 0.0f, 1.0f) : 0.0f;
            l[k] = (isFloat ? v : srgbToLinear(v)) * a;
          }
          l[3] = std::isfinite(a) ? a : 0.0f;
          continue;
        }
        if (isFloat) for (float& v : rgb) v = linearToSrgb(v);  // float images hold linear light
        std::uint8_t* d = &img.pixels[(static_cast<size_t>(y) * spec.width + x) * 4];
        for (int k = 0; k < 3; ++k) d[k] = toByte(rgb[k]);
        d[3] = toByte(a);
      }
      if (!reduce) continue;
      for (int x = 0; x < outW; ++x) {
        float sum[4] = {0, 0, 0, 0};
        for (int t = fx.first[x]; t < fx.first[x + 1]; ++t)
          for (int k = 0; k < 4; ++k) sum[k] += lin[static_cast<size_t>(fx.src[t]) * 4 + k] * fx.weight[t];
        for (int k = 0; k < 4; ++k) rowSum[static_cast<size_t>(x) * 4 + k] = sum[k];
      }
      // Source row y covers [y, y + 1) and output row o covers [o * scaleY, (o + 1) * scaleY).
      const double top = y, bottom = y + 1.0;
      for (int o = accRow; o <= accRow + 1 && o < outH; ++o) {
        const double w = std::min(bottom, (o + 1) * scaleY) - std::max(top, o * scaleY);
        if (w <= 0) continue;
        double* a = &acc[static_cast<size_t>(o - accRow) * outW * 4];
        for (size_t k = 0; k < rowSum.size(); ++k) a[k] += rowSum[k] * w;
      }
      while (accRow < outH && bottom >= (accRow + 1) * scaleY - 1e-9) finishRow(accRow++);
    }
  }
  if (reduce)
    while (accRow < outH) finishRow(accRow++);
  return img;
}

Result<ImageRGBA8> resizeImage(const ImageRGBA8& img, int w, int h) {
  OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf src(spec, const_cast<std::uint8_t*>(img.pixels.data()));
  OIIO::ImageBuf dst = OIIO::ImageBufAlgo::resize(src, "", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, 4));
  if (dst.has_error()) return Error{"resize failed: " + dst.geterror()};
  ImageRGBA8 out{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  dst.get_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, 4), OIIO::TypeDesc::UINT8, out.pixels.data());
  return out;
}


Status writeImage(const std::string& path, const ImageRGBA8& image) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels carry straight alpha
  // zlib level 3, not OpenImageIO's 6: a 1280x720 frame is written 65 ms sooner (563 -> 500 ms
  // file to PNG, the bunny headless), 8% larger.
  spec.attribute("png:compressionLevel", 3);
  if (!out->open(path, spec)) return Error{path + ": cannot open for writing: " + out->geterror()};
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) return Error{path + ": write failed: " + out->geterror()};
  if (!out->close()) return Error{path + ": close failed: " + out->geterror()};
  return okStatus();
}

Result<std::vector<std::uint8_t>> encodePng(const ImageRGBA8& image) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput proxy(bytes);
  auto out = OIIO::ImageOutput::create("png");
  if (!out) return Error{"PNG encoder unavailable: " + OIIO::geterror()};
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->set_ioproxy(&proxy) || !out->open("memory.png", spec) || !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) ||
      !out->close())
    return Error{"PNG encoding failed: " + out->geterror()};
  return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
}

struct StripWriter::State {
  std::string path;
  std::unique_ptr<OIIO::ImageOutput> out;
  int width = 0, height = 0, row = 0;
};

StripWriter::StripWriter(StripWriter&&) noexcept = default;
StripWriter& StripWriter::operator=(StripWriter&&) noexcept = default;
StripWriter::~StripWriter() {
  if (state_ && state_->out) state_->out->close();
}

Result<StripWriter> StripWriter::open(const std::string& path, int width, int height) {
  StripWriter w;
  w.state_ = std::make_unique<State>();
  State& s = *w.state_;
  s.path = path;
  s.width = width;
  s.height = height;
  s.out = OIIO::ImageOutput::create(path);
  if (!s.out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!s.out->open(path, spec)) return Error{path + ": cannot open for writing: " + s.out->geterror()};
  return w;
}

Status StripWriter::append(const ImageRGBA8& strip) {
  State& s = *state_;
  if (!s.out || strip.width != s.width || s.row + strip.height > s.height) return Error{s.path + ": a strip that does not fit the image"};
  if (!s.out->write_scanlines(s.row, s.row + strip.height, 0, OIIO::TypeDesc::UINT8, strip.pixels.data()))
    return Error{s.path + ": write failed: " + s.out->geterror()};
  s.row += strip.height;
  if (s.row == s.height) {
    const bool closed = s.out->close();
    s.out.reset();
    if (!closed) return Error{s.path + ": close failed"};
  }
  return okStatus();
}

struct AnimationWriter::State {
  std::string path;
  std::unique_ptr<OIIO::ImageOutput> out;
  OIIO::ImageSpec spec;
  int frames = 0, written = 0;
};

AnimationWriter::AnimationWriter(AnimationWriter&&) noexcept = default;
AnimationWriter& AnimationWriter::operator=(AnimationWriter&&) noexcept = default;
AnimationWriter::~AnimationWriter() {
  if (state_ && state_->out) state_->out->close();
}

Result<AnimationWriter> AnimationWriter::open(const std::string& path, int width, int height, int frames, int fps) {
  if (frames < 1 || width < 1 || height < 1) return Error{path + ": an animation needs at least one frame of at least one pixel"};
  AnimationWriter w;
  w.state_ = std::make_unique<State>();
  State& s = *w.state_;
  s.path = path;
  s.frames = frames;
  s.out = OIIO::ImageOutput::create(path);
  if (!s.out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  if (frames > 1 && !(s.out->supports("multiimage") && s.out->supports("appendsubimage")))
    return Error{path + ": " + s.out->format_name() + " files hold one image; use .gif for an animation"};
  s.spec = OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::UINT8);
  s.spec.attribute("oiio:UnassociatedAlpha", 1);
  s.spec.attribute("FramesPerSecond", OIIO::TypeRational, std::vector<int>{fps, 1}.data());
  s.spec.attribute("oiio:LoopCount", 0);  // loop forever
  const std::vector<OIIO::ImageSpec> specs(static_cast<size_t>(frames), s.spec);
  if (!s.out->open(path, frames, specs.data())) return Error{path + ": cannot open for writing: " + s.out->geterror()};
  return w;
}

Status AnimationWriter::append(const ImageRGBA8& frame) {
  State& s = *state_;
  if (s.written >= s.frames) return Error{s.path + ": more frames than the animation was opened for"};
  if (frame.width != s.spec.width || frame.height != s.spec.height) return Error{s.path + ": a frame of another size"};
  if (s.written > 0 && !s.out->open(s.path, s.spec, OIIO::ImageOutput::AppendSubimage))
    return Error{s.path + ": cannot add frame " + std::to_string(s.written) + ": " + s.out->geterror()};
  if (!s.out->write_image(OIIO::TypeDesc::UINT8, frame.pixels.data())) return Error{s.path + ": write failed: " + s.out->geterror()};
  if (++s.written == s.frames) {
    const bool closed = s.out->close();
    if (!closed) return Error{s.path + ": close failed: " + s.out->geterror()};
    s.out.reset();
  }
  return okStatus();
}

}  // namespace npr
