#pragma once
// Reads a written video back through libavformat/libavcodec for structural checks.
#include <string>

#include "core/image.hpp"

namespace collide::test {

struct VideoProbe {
  std::string container;      // e.g. "mov,mp4,m4a,3gp,3g2,mj2"
  std::string codec;          // e.g. "h264"
  std::string pixel_format;   // e.g. "yuv420p"
  int width = 0, height = 0;  // pixels
  int decoded_frames = 0;     // frames actually decoded from the stream
  double stream_duration_s = 0.0;
  double frame_rate = 0.0;  // average frames per second
  bool moov_before_mdat = false;
};

// Throws std::runtime_error naming the file if it cannot be opened or decoded.
VideoProbe probeVideo(const std::string& path);

// Decodes frame `index` (0-based) of the first video stream to RGBA8.
core::Image decodeVideoFrame(const std::string& path, int index);

}  // namespace collide::test
