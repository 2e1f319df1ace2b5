// The OpenImageIO module (oiio-images.so): every image format OpenImageIO reads or writes, for
// what image_io.cpp does not decode itself. Built as a module so the viewer links OpenImageIO
// only when a file needs it (plugin_module.h). The caller has already checked the file
// (input_file.h) and, for PNG, its chunk lengths.
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

#include "renderer/core/image_codec_module.h"
#include "renderer/core/image_io.h"

namespace npr {
namespace {

class OiioRows final : public ImageRowReader {
 public:
  OiioRows(std::unique_ptr<OIIO::ImageInput> in, std::string path) : in_(std::move(in)), path_(std::move(path)) {
    const OIIO::ImageSpec& spec = in_->spec();
    width = spec.width;
    height = spec.height;
    channels = spec.nchannels;
    alpha = spec.alpha_channel >= 0 && spec.alpha_channel < channels ? spec.alpha_channel : (channels == 2 ? 1 : (channels >= 4 ? 3 : -1));
    isFloat = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF ||
              spec.format.basetype == OIIO::TypeDesc::DOUBLE;
  }

  Status readRows(int y0, int y1, float* out) override {
    const OIIO::ImageSpec& spec = in_->spec();
    // Rows are read in the file's own format into a buffer kept across calls and converted
    // here: asked for floats, OpenImageIO allocates a conversion buffer on every call, which
    // under the sanitizers (fresh pages, poisoned and quarantined) cost seconds per palette.
    // Files whose channels differ in format are left to its conversion.
    const bool native = spec.channelformats.empty();
    bool read = false;
    if (native) {
      raw_.resize(spec.scanline_bytes(true) * static_cast<size_t>(y1 - y0));
      read = in_->read_scanlines(0, 0, y0 + spec.y, y1 + spec.y, 0, 0, channels, OIIO::TypeDesc::UNKNOWN, raw_.data()) &&
             OIIO::convert_pixel_values(spec.format, raw_.data(), OIIO::TypeDesc::FLOAT, out, (y1 - y0) * width * channels);
    } else {
      read = in_->read_scanlines(0, 0, y0 + spec.y, y1 + spec.y, 0, 0, channels, OIIO::TypeDesc::FLOAT, out);
    }
    if (read) return okStatus();
    const std::string why = in_->geterror();
    return Error{path_ + ": image data could not be read (truncated or corrupt): " + (why.empty() ? "read failed" : why)};
  }

 private:
  std::unique_ptr<OIIO::ImageInput> in_;
  std::string path_;
  std::vector<unsigned char> raw_;
};

Result<std::unique_ptr<ImageRowReader>> openImage(const std::string& path) {
  // Keep straight (unassociated) alpha: OpenImageIO would otherwise premultiply PNG and TGA
  // colours on read, and the compositing after it expects straight alpha.
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
    return Error{path + ": image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is outside 1.." +
                 std::to_string(kMaxImageSide)};
  if (spec.nchannels < 1 || spec.nchannels > 64) return Error{path + ": image has " + std::to_string(spec.nchannels) + " channels"};
  return std::unique_ptr<ImageRowReader>(std::make_unique<OiioRows>(std::move(in), path));
}

OIIO::ImageSpec rgba8Spec(int width, int height) {
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels carry straight alpha
  return spec;
}

Status writeImage(const std::string& path, const ImageRGBA8& image) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  const OIIO::ImageSpec spec = rgba8Spec(image.width, image.height);
  if (!out->open(path, spec)) return Error{path + ": cannot open for writing: " + out->geterror()};
  if (!out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) return Error{path + ": write failed: " + out->geterror()};
  if (!out->close()) return Error{path + ": close failed: " + out->geterror()};
  return okStatus();
}

class Strips final : public ImageSink {
 public:
  Strips(std::unique_ptr<OIIO::ImageOutput> out, std::string path, int width, int height)
      : out_(std::move(out)), path_(std::move(path)), width_(width), height_(height) {}
  ~Strips() override {
    if (out_) out_->close();
  }
  Status append(const ImageRGBA8& strip) override {
    if (!out_ || strip.width != width_ || row_ + strip.height > height_) return Error{path_ + ": a strip that does not fit the image"};
    if (!out_->write_scanlines(row_, row_ + strip.height, 0, OIIO::TypeDesc::UINT8, strip.pixels.data()))
      return Error{path_ + ": write failed: " + out_->geterror()};
    row_ += strip.height;
    if (row_ == height_) {
      const bool closed = out_->close();
      out_.reset();
      if (!closed) return Error{path_ + ": close failed"};
    }
    return okStatus();
  }

 private:
  std::unique_ptr<OIIO::ImageOutput> out_;
  std::string path_;
  int width_, height_, row_ = 0;
};

Result<std::unique_ptr<ImageSink>> openStrips(const std::string& path, int width, int height) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  if (!out->open(path, rgba8Spec(width, height))) return Error{path + ": cannot open for writing: " + out->geterror()};
  return std::unique_ptr<ImageSink>(std::make_unique<Strips>(std::move(out), path, width, height));
}

class Frames final : public ImageSink {
 public:
  Frames(std::unique_ptr<OIIO::ImageOutput> out, std::string path, OIIO::ImageSpec spec, int frames)
      : out_(std::move(out)), path_(std::move(path)), spec_(std::move(spec)), frames_(frames) {}
  ~Frames() override {
    if (out_) out_->close();
  }
  Status append(const ImageRGBA8& frame) override {
    if (written_ >= frames_) return Error{path_ + ": more frames than the animation was opened for"};
    if (frame.width != spec_.width || frame.height != spec_.height) return Error{path_ + ": a frame of another size"};
    if (written_ > 0 && !out_->open(path_, spec_, OIIO::ImageOutput::AppendSubimage))
      return Error{path_ + ": cannot add frame " + std::to_string(written_) + ": " + out_->geterror()};
    if (!out_->write_image(OIIO::TypeDesc::UINT8, frame.pixels.data())) return Error{path_ + ": write failed: " + out_->geterror()};
    if (++written_ == frames_) {
      const bool closed = out_->close();
      if (!closed) return Error{path_ + ": close failed: " + out_->geterror()};
      out_.reset();
    }
    return okStatus();
  }

 private:
  std::unique_ptr<OIIO::ImageOutput> out_;
  std::string path_;
  OIIO::ImageSpec spec_;
  int frames_, written_ = 0;
};

Result<std::unique_ptr<ImageSink>> openAnimation(const std::string& path, int width, int height, int frames, int fps) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return Error{path + ": cannot write this image format (" + OIIO::geterror() + ")"};
  if (frames > 1 && !(out->supports("multiimage") && out->supports("appendsubimage")))
    return Error{path + ": " + out->format_name() + " files hold one image; use .gif for an animation"};
  OIIO::ImageSpec spec = rgba8Spec(width, height);
  spec.attribute("FramesPerSecond", OIIO::TypeRational, std::vector<int>{fps, 1}.data());
  spec.attribute("oiio:LoopCount", 0);  // loop forever
  const std::vector<OIIO::ImageSpec> specs(static_cast<size_t>(frames), spec);
  if (!out->open(path, frames, specs.data())) return Error{path + ": cannot open for writing: " + out->geterror()};
  return std::unique_ptr<ImageSink>(std::make_unique<Frames>(std::move(out), path, spec, frames));
}

const ImageCodecModule kTable{openImage, writeImage, openStrips, openAnimation};

}  // namespace
}  // namespace npr

extern "C" __attribute__((visibility("default"))) const char* npr_module_stamp() { return NPR_MODULE_STAMP; }
extern "C" __attribute__((visibility("default"))) const void* npr_module_table() { return &npr::kTable; }
