#pragma once
// The encoded sinks (MP4, WebM, GIF) without linking libavcodec/libavformat into the program:
// they live in a module, collide-video.so, opened with dlopen the first time a video sink is made.
// A still, a chart, `check`, `presets` or `data` never loads FFmpeg and its hundred-odd
// dependencies, which used to be most of their start-up time.
#include <filesystem>
#include <memory>

#include "output/codec_log.hpp"
#include "output/frame_sink.hpp"
#include "output/gif_sink.hpp"
#include "output/media_extras.hpp"
#include "output/mp4_sink.hpp"
#include "output/webm_sink.hpp"

namespace collide::output {

enum class VideoFormat { kMp4, kWebm, kGif };

// Everything one video sink needs; only the options of `format` are read.
struct VideoSinkRequest {
  VideoFormat format = VideoFormat::kMp4;
  std::filesystem::path path;
  Mp4Options mp4;
  WebmOptions webm;
  GifOptions gif;
  MediaExtras extras;  // MP4 and WebM only
};

// The sink the module builds (Mp4Sink, WebmSink or GifSink), loading the module on first use.
// Throws OutputError when the module cannot be found or opened (the message names where it looked
// and why), and whatever the sink's constructor throws.
std::unique_ptr<FrameSink> makeVideoSink(VideoSinkRequest request);

// How much the codecs print (see codec_log.hpp); kept until the module loads, then applied to it.
void setVideoLogLevel(CodecLogLevel level);

// Whether this process has opened the video module (libavcodec is then mapped too).
bool videoModuleLoaded();

// The module's entry point (in collide-video.so), looked up by its C name. Returns a sink
// allocated with new; applies `log_level` to the codecs first.
using MakeVideoSinkEntry = FrameSink* (*)(const VideoSinkRequest& request, CodecLogLevel log_level);
inline constexpr const char* kMakeVideoSinkSymbol = "collide_make_video_sink";

}  // namespace collide::output
