// Video formats by extension, and opening an encoder through the FFmpeg module (see
// video_encoder.h; the encoder itself is video_encoder_ffmpeg.cpp).
#include "app/video/video_encoder.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "app/cli.h"
#include "renderer/core/plugin_module.h"

namespace npr {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void tellFromModule(const std::string& text) { tellUser(text); }

}  // namespace

Result<VideoFormat> videoFormatOf(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".mp4") return VideoFormat::Mp4;
  if (ext == ".webm") return VideoFormat::WebM;
  if (ext == ".gif") return VideoFormat::Gif;
  return Error{"--video: '" + path + "' names no video format I write: use .mp4 (H.264), .webm (VP9) or .gif"};
}

const char* videoFormatName(VideoFormat format) {
  switch (format) {
    case VideoFormat::Mp4: return "H.264 (MP4)";
    case VideoFormat::WebM: return "VP9 (WebM)";
    case VideoFormat::Gif: return "GIF";
  }
  return "?";
}

std::string partialFileName(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / ("." + p.stem().string() + ".partial" + p.extension().string())).string();
}

Result<std::unique_ptr<VideoEncoder>> VideoEncoder::open(const VideoSpec& spec) {
  Result<VideoFormat> format = videoFormatOf(spec.path);
  if (!format) return Error{format.error()};
  if (*format == VideoFormat::Gif) return Error{spec.path + ": GIFs are written frame by frame, not through the video encoder"};
  if (spec.width < 1 || spec.height < 1 || spec.width > 16384 || spec.height > 16384)
    return Error{spec.path + ": a video's frames must be 1 to 16384 pixels a side"};
  if (!(spec.fps >= 1.0 && spec.fps <= 1000.0)) return Error{spec.path + ": the frame rate must be 1 to 1000 frames a second"};
  if (spec.quality < 0 || spec.quality > VideoSpec::kMaxQuality)
    return Error{"--video-quality must be 0..51 (lower is better), got " + std::to_string(spec.quality)};
  const std::filesystem::path final(spec.path);
  const std::filesystem::path folder = final.parent_path().empty() ? std::filesystem::path(".") : final.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return Error{"--video: the folder '" + folder.string() + "' does not exist"};
  if (std::filesystem::is_directory(final, ec)) return Error{"--video: '" + spec.path + "' is a folder"};

  Result<const void*> table = loadModuleTable("ffmpeg-video.so", "video files (--video .mp4 and .webm)");
  if (!table) return Error{"--video: " + table.error()};
  return static_cast<const VideoEncoderModule*>(*table)->open(spec, *format == VideoFormat::Mp4, partialFileName(spec.path), &tellFromModule);
}

}  // namespace npr
