#include "output/media_probe.hpp"

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <memory>

namespace collide::output::test {
namespace {

std::map<std::string, std::string> tags(const AVDictionary* dictionary) {
  std::map<std::string, std::string> result;
  const AVDictionaryEntry* tag = nullptr;
  while ((tag = av_dict_get(dictionary, "", tag, AV_DICT_IGNORE_SUFFIX)) != nullptr) {
    result[tag->key] = tag->value;
  }
  return result;
}

core::Image toRgba(const AVFrame& frame) {
  core::Image image(frame.width, frame.height);
  SwsContext* sws = sws_getContext(
      frame.width, frame.height, static_cast<AVPixelFormat>(frame.format), frame.width,
      frame.height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr, nullptr, nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  // Back with the matrices the sinks used: BT.709, limited-range YUV to full-range RGB.
  sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
  std::uint8_t* dst[4] = {image.data(), nullptr, nullptr, nullptr};
  const int dst_stride[4] = {4 * frame.width, 0, 0, 0};
  sws_scale(sws, frame.data, frame.linesize, 0, frame.height, dst, dst_stride);
  sws_freeContext(sws);
  return image;
}

void appendSamples(const AVFrame& frame, std::vector<float>& out) {
  // Mono: planar and packed layouts are the same; take channel 0 of anything else.
  const int channels = frame.ch_layout.nb_channels;
  for (int i = 0; i < frame.nb_samples; ++i) {
    switch (frame.format) {
      case AV_SAMPLE_FMT_FLTP:
        out.push_back(reinterpret_cast<const float*>(frame.data[0])[i]);
        break;
      case AV_SAMPLE_FMT_FLT:
        out.push_back(reinterpret_cast<const float*>(frame.data[0])[i * channels]);
        break;
      case AV_SAMPLE_FMT_S16P:
        out.push_back(reinterpret_cast<const std::int16_t*>(frame.data[0])[i] / 32768.0f);
        break;
      case AV_SAMPLE_FMT_S16:
        out.push_back(reinterpret_cast<const std::int16_t*>(frame.data[0])[i * channels] /
                      32768.0f);
        break;
      default:
        ADD_FAILURE() << "unexpected sample format " << frame.format;
        return;
    }
  }
}

struct CodecFree {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
using CodecPtr = std::unique_ptr<AVCodecContext, CodecFree>;

CodecPtr openDecoder(const AVStream& stream, const std::string& name) {
  const AVCodec* decoder = name.empty() ? avcodec_find_decoder(stream.codecpar->codec_id)
                                        : avcodec_find_decoder_by_name(name.c_str());
  if (decoder == nullptr) {
    ADD_FAILURE() << "no decoder for stream " << stream.index;
    return nullptr;
  }
  CodecPtr codec(avcodec_alloc_context3(decoder));
  avcodec_parameters_to_context(codec.get(), stream.codecpar);
  codec->pkt_timebase = stream.time_base;
  codec->thread_count = 1;
  EXPECT_EQ(avcodec_open2(codec.get(), decoder, nullptr), 0);
  return codec;
}

}  // namespace

MediaFacts probeMedia(const std::filesystem::path& path, const std::vector<int>& keep_frames,
                      const std::string& decoder_name) {
  MediaFacts facts;
  av_log_set_level(AV_LOG_ERROR);  // decoders' banners are noise in a test log
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
    ADD_FAILURE() << "cannot open " << path;
    return facts;
  }
  avformat_find_stream_info(format, nullptr);
  facts.container = format->iformat->name;
  facts.duration_s = static_cast<double>(format->duration) / AV_TIME_BASE;
  facts.metadata = tags(format->metadata);
  int video = -1, audio = -1, subtitle = -1;
  std::vector<CodecPtr> codecs(format->nb_streams);
  for (unsigned i = 0; i < format->nb_streams; ++i) {
    const AVStream& stream = *format->streams[i];
    const AVCodecParameters& par = *stream.codecpar;
    StreamFacts s;
    s.type = av_get_media_type_string(par.codec_type);
    s.codec = avcodec_get_name(par.codec_id);
    if (par.codec_type == AVMEDIA_TYPE_VIDEO) {
      const char* name = av_get_pix_fmt_name(static_cast<AVPixelFormat>(par.format));
      s.format = name != nullptr ? name : "";
      if (video < 0) video = static_cast<int>(i);
    } else if (par.codec_type == AVMEDIA_TYPE_AUDIO) {
      const char* name = av_get_sample_fmt_name(static_cast<AVSampleFormat>(par.format));
      s.format = name != nullptr ? name : "";
      if (audio < 0) audio = static_cast<int>(i);
    } else if (par.codec_type == AVMEDIA_TYPE_SUBTITLE && subtitle < 0) {
      subtitle = static_cast<int>(i);
    }
    s.width = par.width;
    s.height = par.height;
    s.sample_rate_hz = par.sample_rate;
    if (stream.duration != AV_NOPTS_VALUE) {
      s.duration_s = static_cast<double>(stream.duration) * av_q2d(stream.time_base);
    }
    if (stream.start_time != AV_NOPTS_VALUE) {
      s.start_s = static_cast<double>(stream.start_time) * av_q2d(stream.time_base);
    }
    s.metadata = tags(stream.metadata);
    facts.streams.push_back(s);
  }
  if (video >= 0) codecs[video] = openDecoder(*format->streams[video], decoder_name);
  if (audio >= 0) codecs[audio] = openDecoder(*format->streams[audio], "");
  if (subtitle >= 0) codecs[subtitle] = openDecoder(*format->streams[subtitle], "");

  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  auto receive = [&](int index) {
    AVCodecContext* codec = codecs[index].get();
    while (avcodec_receive_frame(codec, frame) == 0) {
      if (index == video) {
        facts.decoded_format = av_get_pix_fmt_name(static_cast<AVPixelFormat>(frame->format));
        if (std::find(keep_frames.begin(), keep_frames.end(), facts.video_frames) !=
            keep_frames.end()) {
          facts.kept.push_back(toRgba(*frame));
        }
        ++facts.video_frames;
      } else {
        facts.audio_rate_hz = frame->sample_rate;
        appendSamples(*frame, facts.audio);
      }
      av_frame_unref(frame);
    }
  };
  while (av_read_frame(format, packet) == 0) {
    const int index = packet->stream_index;
    if ((index == video || index == audio) && codecs[index] != nullptr) {
      avcodec_send_packet(codecs[index].get(), packet);
      receive(index);
    } else if (index == subtitle && codecs[index] != nullptr) {
      AVSubtitle sub{};
      int got = 0;
      const double tb = av_q2d(format->streams[index]->time_base);
      if (avcodec_decode_subtitle2(codecs[index].get(), &sub, &got, packet) >= 0 && got) {
        DecodedCue cue;
        cue.start_s = static_cast<double>(packet->pts) * tb;
        cue.end_s = static_cast<double>(packet->pts + packet->duration) * tb;
        for (unsigned r = 0; r < sub.num_rects; ++r) {
          if (sub.rects[r]->ass != nullptr) cue.text += sub.rects[r]->ass;
        }
        facts.cues.push_back(cue);
        avsubtitle_free(&sub);
      }
    }
    av_packet_unref(packet);
  }
  for (const int index : {video, audio}) {
    if (index >= 0 && codecs[index] != nullptr) {
      avcodec_send_packet(codecs[index].get(), nullptr);
      receive(index);
    }
  }
  av_frame_free(&frame);
  av_packet_free(&packet);
  codecs.clear();
  avformat_close_input(&format);
  return facts;
}

const StreamFacts* findStream(const MediaFacts& facts, const std::string& type) {
  for (const StreamFacts& s : facts.streams) {
    if (s.type == type) return &s;
  }
  return nullptr;
}

}  // namespace collide::output::test
