// Image reading, resizing and writing (see image_io.h). PNG and JPEG files of up to
// kWholeDecodePixels are decoded here with stb_image (Debian's libstb), PNGs written with zlib
// (png_encoder.h): that is every palette, texture and screenshot of a usual run, with no
// OpenImageIO loaded. Other formats, larger images (read a band at a time), posters and GIFs go
// to the OpenImageIO module, loaded on first use (image_codec_module.h).
#include "renderer/core/image_io.h"

#include <stb_image.h>
#include <stb_image_resize.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <cstring>

#include "renderer/core/colour.h"
#include "renderer/core/image_codec_module.h"
#include "renderer/core/input_file.h"
#include "renderer/core/plugin_module.h"
#include "renderer/core/png_encoder.h"

namespace npr {

Result<const ImageCodecModule*> imageCodecModule() {
  Result<const void*> table = loadModuleTable("oiio-images.so", "images in formats other than PNG and JPEG, posters and GIFs");
  if (!table) return Error{table.error()};
  return static_cast<const ImageCodecModule*>(*table);
}

namespace {

// Decoded whole here up to this many pixels (64 MiB as 8-bit RGBA); larger images are read a
// band at a time through OpenImageIO, so the full-size pixels of a huge image never exist.
constexpr double kWholeDecodePixels = 4096.0 * 4096.0;

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


bool isPng(const std::string& head) { return head.size() >= 8 && head.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0; }
bool isJpeg(const std::string& head) { return head.size() >= 3 && head.compare(0, 3, "\xff\xd8\xff") == 0; }

// A PNG or JPEG decoded whole by stb_image, handed out as rows like OpenImageIO's.
class StbRows final : public ImageRowReader {
 public:
  StbRows(int w, int h, int n, bool sixteen, void* pixels) : pixels_(pixels, &stbi_image_free), sixteen_(sixteen) {
    width = w;
    height = h;
    channels = n;
    alpha = n == 2 ? 1 : (n == 4 ? 3 : -1);
  }
  Status readRows(int y0, int y1, float* out) override {
    const size_t first = static_cast<size_t>(y0) * width * channels, count = static_cast<size_t>(y1 - y0) * width * channels;
    if (sixteen_) {
      const auto* p = static_cast<const std::uint16_t*>(pixels_.get()) + first;
      for (size_t i = 0; i < count; ++i) out[i] = p[i] / 65535.0f;
    } else {
      const auto* p = static_cast<const std::uint8_t*>(pixels_.get()) + first;
      for (size_t i = 0; i < count; ++i) out[i] = p[i] / 255.0f;
    }
    return okStatus();
  }

 private:
  std::unique_ptr<void, void (*)(void*)> pixels_;
  bool sixteen_;
};

Status checkSize(const std::string& path, int w, int h) {
  if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
    return Error{path + ": image size " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(kMaxImageSide)};
  return okStatus();
}

// The header of a PNG or JPEG through stb_image (reading only as far as it needs), when it is
// small enough to decode whole; nothing (and no error) when OpenImageIO should read it instead.
struct StbHeader {
  int width = 0, height = 0, channels = 0;
  bool sixteen = false;
};
std::optional<StbHeader> stbHeader(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return std::nullopt;
  StbHeader h;
  if (!stbi_info_from_file(f.get(), &h.width, &h.height, &h.channels)) return std::nullopt;
  if (double(h.width) * h.height > kWholeDecodePixels) return std::nullopt;
  h.sixteen = stbi_is_16_bit_from_file(f.get()) != 0;
  return h;
}

// Opens the image after the input-file checks: here when stb_image decodes it, else through
// the OpenImageIO module (formats stb does not read, huge images, and the PNG and JPEG
// variants it refuses, such as CMYK or arithmetic-coded JPEG). Only the signature is read
// before that choice, and only the header for `headerOnly`.
Result<std::unique_ptr<ImageRowReader>> openImage(const std::string& path, bool headerOnly) {
  Result<std::uintmax_t> size = checkInputFile(path, InputKind::Image);
  if (!size) return Error{size.error()};
  std::string head(8, '\0');
  {
    std::ifstream f(path, std::ios::binary);
    f.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<size_t>(std::max<std::streamsize>(0, f.gcount())));
  }
  if (isPng(head))
    if (Status png = checkPngChunks(path, *size); !png) return Error{png.error()};
  if (std::optional<StbHeader> h = isPng(head) || isJpeg(head) ? stbHeader(path) : std::nullopt) {
    if (Status s = checkSize(path, h->width, h->height); !s) return Error{s.error()};
    if (headerOnly) return std::unique_ptr<ImageRowReader>(std::make_unique<StbRows>(h->width, h->height, h->channels, h->sixteen, nullptr));
    Result<std::string> bytes = readInputFile(path, InputKind::Image);
    if (!bytes) return Error{bytes.error()};
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes->data());
    const int length = static_cast<int>(bytes->size());
    int w = 0, ht = 0, n = 0;
    void* pixels = h->sixteen ? static_cast<void*>(stbi_load_16_from_memory(data, length, &w, &ht, &n, 0))
                              : static_cast<void*>(stbi_load_from_memory(data, length, &w, &ht, &n, 0));
    if (pixels && w == h->width && ht == h->height && n >= 1 && n <= 4)
      return std::unique_ptr<ImageRowReader>(std::make_unique<StbRows>(w, ht, n, h->sixteen, pixels));
    stbi_image_free(pixels);
  }
  Result<const ImageCodecModule*> oiio = imageCodecModule();
  if (!oiio) return Error{path + ": " + oiio.error()};
  return (*oiio)->open(path);
}

std::string lowerExtension(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  if (dot == std::string::npos || path[dot] != '.') return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

Result<ImageSize> readImageSize(const std::string& path) {
  Result<std::unique_ptr<ImageRowReader>> in = openImage(path, true);
  if (!in) return Error{in.error()};
  return ImageSize{(*in)->width, (*in)->height};
}

Result<ImageRGBA8> loadImage(const std::string& path, ImageSize fit) {
  Result<std::unique_ptr<ImageRowReader>> opened = openImage(path, false);
  if (!opened) return Error{opened.error()};
  ImageRowReader& in = **opened;
  struct {
    int width, height;
  } const spec{in.width, in.height};
  const int nc = in.channels, alpha = in.alpha;
  const bool isFloat = in.isFloat;
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
  for (int y0 = 0; y0 < spec.height; y0 += rowsPerChunk) {
    const int y1 = std::min(spec.height, y0 + rowsPerChunk);
    if (Status read = in.readRows(y0, y1, buf.data()); !read) return Error{read.error()};
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
  if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide || img.width < 1 || img.height < 1)
    return Error{"resize to " + std::to_string(w) + "x" + std::to_string(h) + " refused"};
  ImageRGBA8 out{w, h, std::vector<std::uint8_t>(static_cast<size_t>(w) * h * 4)};
  // Filtered in linear light with straight alpha weighting colours (stb_image_resize).
  if (!stbir_resize_uint8_srgb(img.pixels.data(), img.width, img.height, 0, out.pixels.data(), w, h, 0, 4, 3, 0))
    return Error{"resize failed"};
  return out;
}

Status writeImage(const std::string& path, const ImageRGBA8& image) {
  if (lowerExtension(path) != "png") {
    Result<const ImageCodecModule*> oiio = imageCodecModule();
    if (!oiio) return Error{path + ": " + oiio.error()};
    return (*oiio)->write(path, image);
  }
  Result<std::vector<std::uint8_t>> png = encodePngRgba8(image);
  if (!png) return Error{path + ": " + png.error()};
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) return Error{path + ": cannot open for writing: " + std::strerror(errno)};
  f.write(reinterpret_cast<const char*>(png->data()), static_cast<std::streamsize>(png->size()));
  f.close();
  if (!f) return Error{path + ": write failed (disk full?)"};
  return okStatus();
}

Result<std::vector<std::uint8_t>> encodePng(const ImageRGBA8& image) { return encodePngRgba8(image); }

struct StripWriter::State {
  std::unique_ptr<ImageSink> sink;
};
StripWriter::StripWriter(StripWriter&&) noexcept = default;
StripWriter& StripWriter::operator=(StripWriter&&) noexcept = default;
StripWriter::~StripWriter() = default;

Result<StripWriter> StripWriter::open(const std::string& path, int width, int height) {
  Result<const ImageCodecModule*> oiio = imageCodecModule();
  if (!oiio) return Error{path + ": " + oiio.error()};
  Result<std::unique_ptr<ImageSink>> sink = (*oiio)->openStrips(path, width, height);
  if (!sink) return Error{sink.error()};
  StripWriter w;
  w.state_ = std::make_unique<State>(State{std::move(*sink)});
  return w;
}

Status StripWriter::append(const ImageRGBA8& strip) { return state_->sink->append(strip); }

struct AnimationWriter::State {
  std::unique_ptr<ImageSink> sink;
};
AnimationWriter::AnimationWriter(AnimationWriter&&) noexcept = default;
AnimationWriter& AnimationWriter::operator=(AnimationWriter&&) noexcept = default;
AnimationWriter::~AnimationWriter() = default;

Result<AnimationWriter> AnimationWriter::open(const std::string& path, int width, int height, int frames, int fps) {
  if (frames < 1 || width < 1 || height < 1) return Error{path + ": an animation needs at least one frame of at least one pixel"};
  Result<const ImageCodecModule*> oiio = imageCodecModule();
  if (!oiio) return Error{path + ": " + oiio.error()};
  Result<std::unique_ptr<ImageSink>> sink = (*oiio)->openAnimation(path, width, height, frames, fps);
  if (!sink) return Error{sink.error()};
  AnimationWriter w;
  w.state_ = std::make_unique<State>(State{std::move(*sink)});
  return w;
}

Status AnimationWriter::append(const ImageRGBA8& frame) { return state_->sink->append(frame); }

}  // namespace npr
