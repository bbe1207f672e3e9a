// The entry point of collide-video.so, the module that holds everything linked to libavcodec and
// libavformat (see video_sinks.hpp).
#include "output/codec_log.hpp"
#include "output/gif_sink.hpp"
#include "output/mp4_sink.hpp"
#include "output/video_sinks.hpp"
#include "output/webm_sink.hpp"

extern "C" __attribute__((visibility("default"))) collide::output::FrameSink*
collide_make_video_sink(const collide::output::VideoSinkRequest& request,
                        collide::output::CodecLogLevel log_level) {
  using namespace collide::output;
  static_assert(std::is_same_v<decltype(&collide_make_video_sink), MakeVideoSinkEntry>);
  setCodecLogLevel(log_level);
  switch (request.format) {
    case VideoFormat::kMp4:
      return new Mp4Sink(request.path, request.mp4, request.extras);
    case VideoFormat::kWebm:
      return new WebmSink(request.path, request.webm, request.extras);
    case VideoFormat::kGif:
      return new GifSink(request.path, request.gif);
  }
  return nullptr;
}
