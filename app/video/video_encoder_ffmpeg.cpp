// The FFmpeg module (ffmpeg-video.so): video files through FFmpeg's libraries (see
// video_encoder.h), built apart so the viewer loads FFmpeg only for --video (plugin_module.h).
#include "app/video/video_encoder.h"

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <filesystem>
#include <mutex>
#include <thread>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace npr {
namespace {

std::string averror(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}


// FFmpeg's own messages at warning level and above, through the app's one way of telling the
// user (escaped, prefixed), handed over when the module is used; its progress chatter (x264's
// statistics) is left out.
void (*tell)(const std::string&) = nullptr;
extern "C" void ffmpegLog(void* context, int level, const char* format, va_list args) {
  if (level > AV_LOG_WARNING) return;
  char line[1024];
  int prefix = 1;
  av_log_format_line2(context, level, format, args, line, sizeof line, &prefix);
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (!text.empty() && tell) tell("FFmpeg: " + text);
}

// Frames queued ahead of the encoder: enough to ride out a slow frame, few enough that a
// 4K run holds under 100 MB of them.
constexpr std::size_t kQueuedFrames = 3;

struct EncoderState {
  VideoSpec spec;
  std::string partial;
  int paddedWidth = 0, paddedHeight = 0;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* yuv = nullptr;
  AVPacket* packet = nullptr;
  bool fileOpen = false, finished = false;
  std::vector<std::uint8_t> padded;  // an odd-sized frame with its last row and column repeated
  std::int64_t nextPts = 0;

  std::thread worker;
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<ImageRGBA8> queue;
  bool closing = false, aborting = false;
  std::string error;  // the worker's first failure

  ~EncoderState() {
    if (worker.joinable()) {
      {
        std::lock_guard<std::mutex> lock(mutex);
        closing = aborting = true;
      }
      changed.notify_all();
      worker.join();
    }
    if (fileOpen) avio_closep(&format->pb);
    if (format) avformat_free_context(format);
    avcodec_free_context(&codec);
    sws_freeContext(sws);
    av_frame_free(&yuv);
    av_packet_free(&packet);
    if (!finished && !partial.empty()) {
      std::error_code ec;
      std::filesystem::remove(partial, ec);
    }
  }

  // Sends `frame` (null: the end) and writes every packet the codec has ready.
  std::string encode(AVFrame* frame) {
    if (int r = avcodec_send_frame(codec, frame); r < 0) return "encoding failed: " + averror(r);
    for (;;) {
      const int r = avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return {};
      if (r < 0) return "encoding failed: " + averror(r);
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      const int w = av_interleaved_write_frame(format, packet);
      av_packet_unref(packet);
      if (w < 0) return "writing failed: " + averror(w);
    }
  }

  std::string convertAndEncode(const ImageRGBA8& image) {
    const std::uint8_t* rgba = image.pixels.data();
    int stride = image.width * 4;
    if (paddedWidth != image.width || paddedHeight != image.height) {
      const std::size_t row = std::size_t(paddedWidth) * 4;
      for (int y = 0; y < paddedHeight; ++y) {
        const std::uint8_t* from = rgba + std::size_t(std::min(y, image.height - 1)) * std::size_t(stride);
        std::uint8_t* to = padded.data() + std::size_t(y) * row;
        std::memcpy(to, from, std::size_t(stride));
        if (paddedWidth > image.width) std::memcpy(to + stride, to + stride - 4, 4);
      }
      rgba = padded.data();
      stride = int(row);
    }
    if (int r = av_frame_make_writable(yuv); r < 0) return "out of memory: " + averror(r);
    const std::uint8_t* planes[1] = {rgba};
    const int strides[1] = {stride};
    sws_scale(sws, planes, strides, 0, paddedHeight, yuv->data, yuv->linesize);
    yuv->pts = nextPts++;
    return encode(yuv);
  }

  void run() {
    for (;;) {
      ImageRGBA8 image;
      {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return !queue.empty() || closing; });
        if (aborting) return;
        if (queue.empty()) break;  // closing, everything encoded
        image = std::move(queue.front());
        queue.pop_front();
      }
      changed.notify_all();
      std::string failure;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error.empty()) continue;  // drop the rest: append() reports the failure
      }
      failure = convertAndEncode(image);
      if (!failure.empty()) {
        std::lock_guard<std::mutex> lock(mutex);
        error = failure;
      }
    }
    std::string failure;
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error.empty()) return;
    }
    failure = encode(nullptr);  // the frames the codec still holds
    if (!failure.empty()) {
      std::lock_guard<std::mutex> lock(mutex);
      error = failure;
    }
  }
};

class FfmpegEncoder final : public VideoEncoder {
 public:
  explicit FfmpegEncoder(std::unique_ptr<EncoderState> state) : state_(std::move(state)) {}
  Status append(ImageRGBA8 frame) override;
  Status finish() override;

 private:
  std::unique_ptr<EncoderState> state_;
};

// `spec` has been checked by VideoEncoder::open, which names the partial file.
Result<std::unique_ptr<VideoEncoder>> openEncoder(const VideoSpec& spec, bool mp4, const std::string& partial,
                                                  void (*tellUser)(const std::string&)) {
  tell = tellUser;
  static std::once_flag logging;
  std::call_once(logging, [] { av_log_set_callback(ffmpegLog); });

  auto s = std::make_unique<EncoderState>();
  s->spec = spec;
  s->paddedWidth = spec.width + (spec.width & 1);
  s->paddedHeight = spec.height + (spec.height & 1);
  if (s->paddedWidth != spec.width || s->paddedHeight != spec.height) s->padded.resize(std::size_t(s->paddedWidth) * std::size_t(s->paddedHeight) * 4);

  // The codec first: a build of FFmpeg without it is said before anything is written.
  const char* codecName = mp4 ? "libx264" : "libvpx-vp9";
  const AVCodec* codec = avcodec_find_encoder_by_name(codecName);
  if (!codec) codec = avcodec_find_encoder(mp4 ? AV_CODEC_ID_H264 : AV_CODEC_ID_VP9);
  if (!codec)
    return Error{spec.path + ": this system's FFmpeg has no " + (mp4 ? "H.264" : "VP9") + " encoder (" + codecName +
                 "); try " + (mp4 ? ".webm" : ".mp4") + " or .gif"};

  s->partial = partial;

  if (int r = avformat_alloc_output_context2(&s->format, nullptr, mp4 ? "mp4" : "webm", s->partial.c_str()); r < 0 || !s->format)
    return Error{spec.path + ": cannot set up the container: " + averror(r)};
  s->stream = avformat_new_stream(s->format, nullptr);
  s->codec = avcodec_alloc_context3(codec);
  s->yuv = av_frame_alloc();
  s->packet = av_packet_alloc();
  if (!s->stream || !s->codec || !s->yuv || !s->packet) return Error{spec.path + ": out of memory setting up the encoder"};

  const AVRational rate = av_d2q(spec.fps, 1001000);
  AVCodecContext& c = *s->codec;
  c.width = s->paddedWidth;
  c.height = s->paddedHeight;
  c.pix_fmt = AV_PIX_FMT_YUV420P;
  c.framerate = rate;
  c.time_base = av_inv_q(rate);
  c.colorspace = AVCOL_SPC_BT709;
  c.color_primaries = AVCOL_PRI_BT709;
  c.color_trc = AVCOL_TRC_BT709;
  c.color_range = AVCOL_RANGE_MPEG;
  c.bit_rate = 0;  // constant quality
  if (s->format->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  if (mp4) {
    av_dict_set(&options, "crf", std::to_string(spec.quality).c_str(), 0);
    // x264's "faster": a 60-frame 1080p crosshatch turntable on two cores wrote 23.5 frames a
    // second against medium's 15.8, for 3% more bits and 0.25 dB less (docs/video.md).
    av_dict_set(&options, "preset", "faster", 0);
  } else {
    // VP9's constant quality runs 0..63: the same place on its scale.
    av_dict_set(&options, "crf", std::to_string((spec.quality * 63 + 25) / 51).c_str(), 0);
    av_dict_set(&options, "deadline", "good", 0);
    av_dict_set(&options, "cpu-used", "4", 0);
    av_dict_set(&options, "row-mt", "1", 0);
  }
  const int opened = avcodec_open2(s->codec, codec, &options);
  av_dict_free(&options);
  if (opened < 0) return Error{spec.path + ": the " + codecName + " encoder refused the settings: " + averror(opened)};
  if (int r = avcodec_parameters_from_context(s->stream->codecpar, s->codec); r < 0)
    return Error{spec.path + ": cannot set up the stream: " + averror(r)};
  s->stream->time_base = c.time_base;
  s->stream->avg_frame_rate = rate;

  s->yuv->format = c.pix_fmt;
  s->yuv->width = c.width;
  s->yuv->height = c.height;
  if (int r = av_frame_get_buffer(s->yuv, 0); r < 0) return Error{spec.path + ": out of memory for a frame: " + averror(r)};
  s->sws = sws_getContext(c.width, c.height, AV_PIX_FMT_RGBA, c.width, c.height, AV_PIX_FMT_YUV420P,
                          SWS_BICUBIC | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
  if (!s->sws) return Error{spec.path + ": cannot set up the colour conversion"};
  // Full-range sRGB pixels to BT.709 video levels, as the stream says it is.
  sws_setColorspaceDetails(s->sws, sws_getCoefficients(SWS_CS_ITU709), 1, sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);

  if (int r = avio_open(&s->format->pb, s->partial.c_str(), AVIO_FLAG_WRITE); r < 0)
    return Error{"--video: cannot write '" + s->partial + "' (" + averror(r) + ")"};
  s->fileOpen = true;
  AVDictionary* header = nullptr;
  if (mp4) av_dict_set(&header, "movflags", "+faststart", 0);  // the index first: plays while it downloads
  const int written = avformat_write_header(s->format, &header);
  av_dict_free(&header);
  if (written < 0) return Error{spec.path + ": cannot write the header: " + averror(written)};

  EncoderState* state = s.get();
  s->worker = std::thread([state] { state->run(); });
  return std::unique_ptr<VideoEncoder>(std::make_unique<FfmpegEncoder>(std::move(s)));
}

Status FfmpegEncoder::append(ImageRGBA8 frame) {
  EncoderState& s = *state_;
  if (frame.width != s.spec.width || frame.height != s.spec.height || frame.pixels.size() != std::size_t(frame.width) * std::size_t(frame.height) * 4)
    return Error{s.spec.path + ": a frame of another size than the video's"};
  std::unique_lock<std::mutex> lock(s.mutex);
  s.changed.wait(lock, [&] { return s.queue.size() < kQueuedFrames || !s.error.empty(); });
  if (!s.error.empty()) return Error{s.spec.path + ": " + s.error};
  s.queue.push_back(std::move(frame));
  lock.unlock();
  s.changed.notify_all();
  return okStatus();
}

Status FfmpegEncoder::finish() {
  EncoderState& s = *state_;
  if (s.finished) return okStatus();
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    s.closing = true;
  }
  s.changed.notify_all();
  s.worker.join();
  if (!s.error.empty()) return Error{s.spec.path + ": " + s.error};
  if (int r = av_write_trailer(s.format); r < 0) return Error{s.spec.path + ": cannot finish the file: " + averror(r)};
  s.fileOpen = false;
  if (int r = avio_closep(&s.format->pb); r < 0) return Error{s.spec.path + ": cannot close the file: " + averror(r)};
  std::error_code ec;
  std::filesystem::rename(s.partial, s.spec.path, ec);
  if (ec) return Error{"--video: cannot rename '" + s.partial + "' to '" + s.spec.path + "' (" + ec.message() + ")"};
  s.finished = true;
  return okStatus();
}

const VideoEncoderModule kTable{openEncoder};

}  // namespace
}  // namespace npr

extern "C" __attribute__((visibility("default"))) const char* npr_module_stamp() { return NPR_MODULE_STAMP; }
extern "C" __attribute__((visibility("default"))) const void* npr_module_table() { return &npr::kTable; }
