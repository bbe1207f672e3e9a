#pragma once
// Reads a written media file back through libavformat/libavcodec: every stream's facts, the
// decoded video frames, the decoded sound and the subtitle cues.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/image.hpp"

namespace collide::output::test {

struct StreamFacts {
  std::string type;    // "video", "audio", "subtitle"
  std::string codec;   // e.g. "h264", "vp9", "gif", "aac", "opus", "mov_text", "webvtt"
  std::string format;  // pixel or sample format name
  int width = 0, height = 0;
  int sample_rate_hz = 0;
  double duration_s = 0.0;  // stream duration x time base; 0 when unknown
  double start_s = 0.0;     // first timestamp x time base
  std::map<std::string, std::string> metadata;
};

struct DecodedCue {
  double start_s = 0.0, end_s = 0.0;
  std::string text;  // as the decoder gives it (ASS dialogue for text subtitles)
};

struct MediaFacts {
  std::string container;  // libavformat demuxer name
  double duration_s = 0.0;
  std::map<std::string, std::string> metadata;
  std::vector<StreamFacts> streams;
  int video_frames = 0;           // decoded frames of the first video stream
  std::vector<core::Image> kept;  // RGBA of the frames asked for, in order
  std::string decoded_format;     // pixel format of decoded video frames
  std::vector<float> audio;       // decoded mono samples of the first audio stream
  int audio_rate_hz = 0;
  std::vector<DecodedCue> cues;  // first subtitle stream
};

// `keep_frames`: indices of video frames to convert to RGBA (alpha kept where the stream has it).
// `decoder` names a video decoder to use instead of the default (e.g. "libvpx-vp9" for alpha).
// Fails the calling test if the file cannot be opened.
MediaFacts probeMedia(const std::filesystem::path& path, const std::vector<int>& keep_frames = {},
                      const std::string& decoder = "");

const StreamFacts* findStream(const MediaFacts& facts, const std::string& type);

}  // namespace collide::output::test
