// What the end-to-end video test asks of a video file, as ffprobe would say it, built from the
// FFmpeg libraries the viewer links (so CI need not install ffmpeg's 45 packages):
//   video_probe FILE              one line: codec=h264 width=66 height=50 frames=24 pix_fmt=yuv420p fps=30/1
//   video_probe FILE N OUT.ppm    also writes frame N (from 0), decoded to RGB, as a PPM
// Exit 1 with a message when the file cannot be read or has no video stream.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "video_probe: %s\n", message.c_str());
  return 1;
}

bool writePpm(const std::string& path, AVFrame* frame) {
  SwsContext* sws = sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width, frame->height, AV_PIX_FMT_RGB24,
                                   SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
  if (!sws) return false;
  const int matrix = frame->colorspace == AVCOL_SPC_BT709 ? SWS_CS_ITU709 : SWS_CS_DEFAULT;
  sws_setColorspaceDetails(sws, sws_getCoefficients(matrix), frame->color_range == AVCOL_RANGE_JPEG, sws_getCoefficients(SWS_CS_DEFAULT), 1, 0,
                           1 << 16, 1 << 16);
  std::vector<std::uint8_t> rgb(std::size_t(frame->width) * std::size_t(frame->height) * 3);
  std::uint8_t* planes[1] = {rgb.data()};
  const int strides[1] = {frame->width * 3};
  sws_scale(sws, frame->data, frame->linesize, 0, frame->height, planes, strides);
  sws_freeContext(sws);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", frame->width, frame->height);
  const bool ok = std::fwrite(rgb.data(), 1, rgb.size(), f) == rgb.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) return fail("usage: video_probe FILE [FRAME OUT.ppm]");
  av_log_set_level(AV_LOG_ERROR);
  const int wanted = argc == 4 ? std::atoi(argv[2]) : -1;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, argv[1], nullptr, nullptr) < 0) return fail(std::string("cannot open ") + argv[1]);
  if (avformat_find_stream_info(format, nullptr) < 0) return fail("no stream information");
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index < 0) return fail("no video stream");
  AVStream* stream = format->streams[index];
  const AVCodec* codec = avcodec_find_decoder(stream->codecpar->codec_id);
  AVCodecContext* ctx = avcodec_alloc_context3(codec);
  if (!codec || !ctx || avcodec_parameters_to_context(ctx, stream->codecpar) < 0 || avcodec_open2(ctx, codec, nullptr) < 0)
    return fail("no decoder for the stream");
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  int frames = 0;
  bool written = wanted < 0;
  auto drain = [&]() {
    while (avcodec_receive_frame(ctx, frame) == 0) {
      if (frames == wanted) written = writePpm(argv[3], frame);
      ++frames;
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == index && avcodec_send_packet(ctx, packet) >= 0) drain();
    av_packet_unref(packet);
  }
  avcodec_send_packet(ctx, nullptr);
  drain();
  std::printf("codec=%s width=%d height=%d frames=%d pix_fmt=%s fps=%d/%d\n", codec->name, stream->codecpar->width, stream->codecpar->height,
              frames, av_get_pix_fmt_name(AVPixelFormat(stream->codecpar->format)), stream->avg_frame_rate.num, stream->avg_frame_rate.den);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&ctx);
  avformat_close_input(&format);
  if (!written) return fail("frame " + std::to_string(wanted) + " was not decoded");
  return 0;
}
