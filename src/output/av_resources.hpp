#pragma once
// Private to src/output: RAII owners for libav objects and error text. Includes libav headers, so
// no public header may include this one.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/frame.h>
}

#include <filesystem>
#include <memory>
#include <string>

namespace collide::output::av {

struct CodecContextDeleter {
  void operator()(AVCodecContext* context) const { avcodec_free_context(&context); }
};
struct FrameDeleter {
  void operator()(AVFrame* frame) const { av_frame_free(&frame); }
};
struct PacketDeleter {
  void operator()(AVPacket* packet) const { av_packet_free(&packet); }
};
// Closes the output file if it is open, then frees the muxer context.
struct OutputFormatDeleter {
  void operator()(AVFormatContext* context) const;
};
struct DictionaryDeleter {
  void operator()(AVDictionary* dictionary) const { av_dict_free(&dictionary); }
};

using CodecContextPtr = std::unique_ptr<AVCodecContext, CodecContextDeleter>;
using FramePtr = std::unique_ptr<AVFrame, FrameDeleter>;
using PacketPtr = std::unique_ptr<AVPacket, PacketDeleter>;
using OutputFormatPtr = std::unique_ptr<AVFormatContext, OutputFormatDeleter>;

// libav's text for an AVERROR code (errno codes give strerror's text).
std::string errorText(int av_error);
// "<what> '<path>': <errorText>[; <advice>]", the module's one-line error form (see ioAdvice).
std::string errorMessage(const std::string& what, const std::filesystem::path& path, int av_error);

}  // namespace collide::output::av
