#pragma once
// VP9 video in a WebM container (libvpx through libavcodec), optionally with transparency (VP9's
// alpha channel), Opus sound and a WebVTT subtitle stream. Browsers play it in <video>; with
// alpha it overlays slides and web pages.
#include <filesystem>

#include "output/encoded_video_sink.hpp"

namespace collide::output {

inline constexpr int kMaxVp9Crf = 63;   // libvpx quantizer range for VP9
inline constexpr int kMaxVp9Speed = 8;  // libvpx cpu-used: 0 slowest and best .. 8 fastest

struct WebmOptions {
  int crf = 32;   // VP9 constant quality, 0 (best) .. 63 (worst), on the scale of libvpx's "good"
                  // deadline (the realtime encoder used gets crf + 8); ~31-35 looks clean at 720p
  int speed = 6;  // libvpx cpu-used, 0..8: 6 keeps up with real time at 720p on 2 cores
  bool alpha = false;  // keep the frames' alpha: yuva420p, the WebM AlphaMode flag set
};

// Writes `path` as WebM (VP9 profile 0, yuv420p or yuva420p, BT.709 limited range, time base
// 1/fps). N frames written give N frames and a duration of N/fps seconds. Written to a temporary
// file and renamed at finish(), like every sink. Throws OutputError: options out of range, odd
// size (4:2:0), libvpx missing, finish() without frames, any codec or I/O failure.
class WebmSink final : public EncodedVideoSink {
 public:
  explicit WebmSink(std::filesystem::path path, WebmOptions options = {}, MediaExtras extras = {});

 private:
  void describe(const FrameFormat& format, av::VideoSetup& setup) const override;

  WebmOptions options_;
};

}  // namespace collide::output
