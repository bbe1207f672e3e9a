#pragma once
// H.264 video in an MP4 container, encoded in-process by libavformat + libx264 (no ffmpeg
// process), optionally with AAC sound and a mov_text subtitle stream. Frames stream through one
// at a time: memory use does not grow with video length.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

#include "output/encoded_video_sink.hpp"

namespace collide::output {

// x264's speed presets, fastest first; the app can check user input against these.
inline constexpr std::array<std::string_view, 10> kX264Presets = {
    "ultrafast", "superfast", "veryfast", "faster",   "fast",
    "medium",    "slow",      "slower",   "veryslow", "placebo"};
inline constexpr int kMaxCrf = 51;  // x264 constant rate factor range is 0..51 for 8-bit video

struct Mp4Options {
  int crf = 20;  // x264 constant rate factor, 0 (lossless) .. 51 (worst); ~18-23 looks clean
  std::string preset = "veryfast";  // one of kX264Presets
  int threads = 0;  // x264 frame threads; 0: 1.5 per core (see describe() in mp4_sink.cpp)
};

// Writes `path` as MP4 (H.264 High profile, yuv420p, BT.709 limited range, constant frame rate
// time base 1/fps, moov atom before mdat for progressive playback). N frames written give N
// frames in the file and a duration of N/fps seconds. extras.audio becomes an AAC stream (96
// kbit/s), extras.subtitles a mov_text stream (the MP4 form of captions), extras.metadata the
// file's tags (title, comment, description, ...).
//
// The video is written to a hidden temporary file beside `path` and renamed at finish();
// destroyed before finish(), the sink deletes the temporary file and leaves `path` untouched.
// Throws OutputError: odd width or height (H.264 4:2:0 needs even sizes), a preset not in
// kX264Presets or crf outside 0..kMaxCrf (the app should have rejected these), libx264 missing,
// finish() without frames, and any codec or I/O failure (message names the path and reason).
class Mp4Sink final : public EncodedVideoSink {
 public:
  explicit Mp4Sink(std::filesystem::path path, Mp4Options options = {}, MediaExtras extras = {});

 private:
  void describe(const FrameFormat& format, av::VideoSetup& setup) const override;

  Mp4Options options_;
};

}  // namespace collide::output
