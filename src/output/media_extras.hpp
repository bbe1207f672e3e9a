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
  std::optional<AudioTrack> audio;   // none: a silent video without an audio stream
  std::vector<TimedText> subtitles;  // none: no subtitle stream
  // The language of the subtitle and audio streams, ISO 639-2 in both of its forms: MP4 writes the
  // terminology code ("deu", as ISO/IEC 14496-12's mdhd asks), Matroska/WebM the bibliographic
  // one ("ger", as its TrackLanguage element asks); they differ for 20 languages only.
  std::string language_terminology = "eng";
  std::string language_bibliographic = "eng";
  std::string subtitle_title = "Narration";  // the subtitle stream's name, in its language
};

}  // namespace collide::output
