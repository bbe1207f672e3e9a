#pragma once
// What a video file may carry besides its pictures: container tags, a sound track and timed text.
// Plain data, handed to a sink by the app; the sink encodes them in its container's own way.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace collide::output {

// Mono sound: samples in [-1, 1] at sample_rate_hz, starting at the first frame's time.
struct AudioTrack {
  int sample_rate_hz = 48000;
  std::vector<float> samples;
};

// One caption: text shown from start_s to end_s (seconds of video time, end > start). Lines are
// separated by '\n'.
struct TimedText {
  double start_s = 0.0;
  double end_s = 0.0;
  std::string text;
};

struct MediaExtras {
  // Container tags such as {"title", ...}, {"comment", ...}, {"description", ...}.
  std::map<std::string, std::string> metadata;
  std::optional<AudioTrack> audio;        // none: a silent video without an audio stream
  std::vector<TimedText> subtitles;       // none: no subtitle stream
  std::string subtitle_language = "eng";  // ISO 639-2 code of the subtitle stream
};

}  // namespace collide::output
