// Video files from headless sequences (--video): H.264 in MP4 and VP9 in WebM through FFmpeg's
// libraries. Frames are converted and encoded on a thread of the encoder's own, behind a short
// queue, so rendering the next frame overlaps encoding the last and memory stays constant
// however long the run. The file is written under a hidden partial name beside the final one
// and renamed when it is finished: a failed or interrupted run never leaves a half-written file
// under the name asked for.
#pragma once

#include <memory>
#include <string>

#include "renderer/core/image.h"
#include "renderer/core/result.h"

namespace npr {

enum class VideoFormat { Mp4, WebM, Gif };

// The format a video path asks for by its extension (.mp4, .webm, .gif; any case), or an
// error naming the extensions there are.
[[nodiscard]] Result<VideoFormat> videoFormatOf(const std::string& path);
const char* videoFormatName(VideoFormat format);  // "H.264 (MP4)", ...

// The hidden name a file is written under until it is finished: DIR/.NAME.partial.EXT (the
// extension kept, so writers that pick a format by it still do).
std::string partialFileName(const std::string& path);

struct VideoSpec {
  std::string path;
  int width = 0, height = 0;  // the frames'; odd sizes are padded by one row or column for 4:2:0
  double fps = 30.0;
  // Constant quality on x264's CRF scale, 0 (lossless) to 51; VP9 takes it scaled to its 0..63.
  int quality = kDefaultQuality;
  // 16: line art and hatching with no visible loss at 1080p (docs/video.md has the figures).
  static constexpr int kDefaultQuality = 16;
  static constexpr int kMaxQuality = 51;
};

class VideoEncoder {
 public:
  // Opens the codec and the partial file, so that a missing codec or an unwritable folder is
  // said before any frame is rendered. MP4 and WebM only (GIFs go through AnimationWriter).
  // The encoder lives in the FFmpeg module, loaded here on first use.
  [[nodiscard]] static Result<std::unique_ptr<VideoEncoder>> open(const VideoSpec& spec);
  // An unfinished encoder stops its thread and removes the partial file.
  virtual ~VideoEncoder() = default;
  VideoEncoder() = default;
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Queues the next frame (width x height, top row first); waits while the queue is full. An
  // error the encoding thread met is returned here, or by finish().
  [[nodiscard]] virtual Status append(ImageRGBA8 frame) = 0;
  // Encodes what is queued, writes the file's index and renames it to its final name.
  [[nodiscard]] virtual Status finish() = 0;
};

// The FFmpeg module's table (ffmpeg-video.so): an H.264 (`mp4`) or VP9 encoder writing to
// `partial`; `tell` passes FFmpeg's warnings to the user.
struct VideoEncoderModule {
  Result<std::unique_ptr<VideoEncoder>> (*open)(const VideoSpec& spec, bool mp4, const std::string& partial, void (*tell)(const std::string&));
};

}  // namespace npr
