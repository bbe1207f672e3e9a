#include "video_probe.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <cstdint>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>

namespace collide::test {
namespace {

// Position of the first top-level MP4 box of `type`, or -1. Boxes are [size:4][type:4][payload].
long long topLevelBoxOffset(const std::string& path, const std::string& type) {
  std::ifstream file(path, std::ios::binary);
  long long offset = 0;
  unsigned char header[16];
  while (file.read(reinterpret_cast<char*>(header), 8)) {
    std::uint64_t size =
        (std::uint64_t{header[0]} << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
    const std::string box(reinterpret_cast<char*>(header) + 4, 4);
    if (box == type) return offset;
    if (size == 1) {  // 64-bit size follows the type
      if (!file.read(reinterpret_cast<char*>(header + 8), 8)) break;
      size = 0;
      for (int i = 8; i < 16; ++i) size = (size << 8) | header[i];
    }
    if (size < 8) break;
    offset += static_cast<long long>(size);
    file.seekg(offset);
  }
  return -1;
}

struct Decoder {
  std::unique_ptr<AVFormatContext, std::function<void(AVFormatContext*)>> format;
  std::unique_ptr<AVCodecContext, std::function<void(AVCodecContext*)>> codec;
  int stream = -1;
};

Decoder openDecoder(const std::string& path) {
  AVFormatContext* raw = nullptr;
  if (avformat_open_input(&raw, path.c_str(), nullptr, nullptr) < 0) {
    throw std::runtime_error("cannot open " + path);
  }
  Decoder d;
  d.format = {raw, [](AVFormatContext* f) { avformat_close_input(&f); }};
  if (avformat_find_stream_info(raw, nullptr) < 0)
    throw std::runtime_error("no stream info: " + path);
  const AVCodec* codec = nullptr;
  d.stream = av_find_best_stream(raw, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  if (d.stream < 0 || !codec) throw std::runtime_error("no video stream: " + path);
  d.codec = {avcodec_alloc_context3(codec), [](AVCodecContext* c) { avcodec_free_context(&c); }};
  avcodec_parameters_to_context(d.codec.get(), raw->streams[d.stream]->codecpar);
  if (avcodec_open2(d.codec.get(), codec, nullptr) < 0)
    throw std::runtime_error("no decoder: " + path);
  return d;
}

// Feeds every packet and calls `on_frame` for each decoded frame; stops early when it returns
// false.
void decodeAll(Decoder& d, const std::function<bool(const AVFrame&)>& on_frame) {
  std::unique_ptr<AVPacket, std::function<void(AVPacket*)>> packet(
      av_packet_alloc(), [](AVPacket* p) { av_packet_free(&p); });
  std::unique_ptr<AVFrame, std::function<void(AVFrame*)>> frame(
      av_frame_alloc(), [](AVFrame* f) { av_frame_free(&f); });
  bool more = true;
  auto drain = [&] {
    while (more && avcodec_receive_frame(d.codec.get(), frame.get()) == 0) more = on_frame(*frame);
  };
  while (more && av_read_frame(d.format.get(), packet.get()) >= 0) {
    if (packet->stream_index == d.stream) {
      avcodec_send_packet(d.codec.get(), packet.get());
      drain();
    }
    av_packet_unref(packet.get());
  }
  avcodec_send_packet(d.codec.get(), nullptr);
  drain();
}

}  // namespace

VideoProbe probeVideo(const std::string& path) {
  Decoder d = openDecoder(path);
  const AVStream* stream = d.format->streams[d.stream];
  VideoProbe probe;
  probe.container = d.format->iformat->name;
  probe.codec = avcodec_get_name(stream->codecpar->codec_id);
  const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(stream->codecpar->format));
  probe.pixel_format = pix ? pix : "";
  probe.width = stream->codecpar->width;
  probe.height = stream->codecpar->height;
  probe.stream_duration_s = stream->duration * av_q2d(stream->time_base);
  probe.frame_rate = av_q2d(stream->avg_frame_rate);
  decodeAll(d, [&](const AVFrame&) {
    ++probe.decoded_frames;
    return true;
  });
  const long long moov = topLevelBoxOffset(path, "moov"), mdat = topLevelBoxOffset(path, "mdat");
  probe.moov_before_mdat = moov >= 0 && mdat >= 0 && moov < mdat;
  return probe;
}

core::Image decodeVideoFrame(const std::string& path, int index) {
  Decoder d = openDecoder(path);
  core::Image image;
  int seen = 0;
  decodeAll(d, [&](const AVFrame& frame) {
    if (seen++ < index) return true;
    image = core::Image(frame.width, frame.height);
    SwsContext* sws = sws_getContext(
        frame.width, frame.height, static_cast<AVPixelFormat>(frame.format), frame.width,
        frame.height, AV_PIX_FMT_RGBA, SWS_BILINEAR, nullptr, nullptr, nullptr);
    std::uint8_t* planes[1] = {image.data()};
    const int strides[1] = {4 * frame.width};
    sws_scale(sws, frame.data, frame.linesize, 0, frame.height, planes, strides);
    sws_freeContext(sws);
    return false;
  });
  if (image.width() == 0)
    throw std::runtime_error(path + ": has no frame " + std::to_string(index));
  return image;
}

}  // namespace collide::test
