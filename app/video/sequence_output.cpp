// A sequence's outputs (see sequence_output.h).
#include "app/video/sequence_output.h"

#include <cmath>
#include <filesystem>
#include <vector>

#include "app/camera_animation.h"
#include "app/cli.h"

namespace npr {

// A GIF written under its partial name, renamed when its last frame is in.
struct SequenceOutput::Partial {
  std::string path, partial;
  std::optional<AnimationWriter> writer;
  bool finished = false;
  ~Partial() {
    writer.reset();  // closes the file before it is removed
    if (!finished) {
      std::error_code ec;
      std::filesystem::remove(partial, ec);
    }
  }
};

SequenceOutput::SequenceOutput(SequenceOutput&&) noexcept = default;
SequenceOutput& SequenceOutput::operator=(SequenceOutput&&) noexcept = default;
SequenceOutput::~SequenceOutput() = default;

Result<SequenceOutput> SequenceOutput::open(const SequenceTargets& t) {
  SequenceOutput out;
  out.targets_ = t;
  std::string gif = t.gif;
  if (!t.video.empty()) {
    Result<VideoFormat> format = videoFormatOf(t.video);
    if (!format) return Error{format.error()};
    if (*format == VideoFormat::Gif) {
      gif = t.video;
    } else {
      Result<std::unique_ptr<VideoEncoder>> encoder = VideoEncoder::open({t.video, t.width, t.height, t.fps, t.videoQuality});
      if (!encoder) return Error{encoder.error()};
      out.video_ = std::move(*encoder);
    }
  }
  if (!gif.empty()) {
    const std::filesystem::path folder = std::filesystem::path(gif).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) return Error{"the folder '" + folder.string() + "' for '" + gif + "' does not exist"};
    auto partial = std::make_unique<Partial>();
    partial->path = gif;
    partial->partial = partialFileName(gif);
    // GIF frame delays are in hundredths of a second: the nearest whole frame rate.
    Result<AnimationWriter> w = AnimationWriter::open(partial->partial, t.width, t.height, t.frames, int(std::lround(t.fps)));
    if (!w) return Error{w.error()};
    partial->writer = std::move(*w);
    out.gif_ = std::move(partial);
  }
  return out;
}

bool SequenceOutput::wantsPixels() const { return !targets_.framesFolder.empty() || gif_ || video_; }

Status SequenceOutput::add(ImageRGBA8 image, int frame) {
  if (!targets_.framesFolder.empty())
    if (Status s = writeImage(frameFileName(targets_.framesFolder, frame), image); !s) return s;
  if (gif_)
    if (Status s = gif_->writer->append(image); !s) return s;
  if (video_)
    if (Status s = video_->append(std::move(image)); !s) return s;
  ++written_;
  return okStatus();
}

Status SequenceOutput::finish() {
  if (!targets_.framesFolder.empty()) tellUser(std::to_string(written_) + " frame(s) written to " + targets_.framesFolder);
  if (gif_) {
    gif_->writer.reset();  // the last append closed it; an unfinished one is closed here
    std::error_code ec;
    std::filesystem::rename(gif_->partial, gif_->path, ec);
    if (ec) return Error{"cannot rename '" + gif_->partial + "' to '" + gif_->path + "' (" + ec.message() + ")"};
    gif_->finished = true;
    tellUser("animation written to " + gif_->path);
  }
  if (video_) {
    if (Status s = video_->finish(); !s) return s;
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(targets_.video, ec);
    char size[32];
    std::snprintf(size, sizeof size, "%.1f MB", ec ? 0.0 : double(bytes) / 1e6);
    tellUser("video written to " + targets_.video + " (" + std::to_string(written_) + " frames, " +
             videoFormatName(*videoFormatOf(targets_.video)) + ", " + size + ")");
  }
  return okStatus();
}

}  // namespace npr
