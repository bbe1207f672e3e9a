#pragma once
// Frame size, rate and duration as asked on the command line, checked against the tool's limits.
#include <optional>
#include <string>

namespace collide::app {

struct FrameSize {
  int width_px = 1280;
  int height_px = 720;
};

// Largest frame accepted (8K UHD) and smallest that still shows a picture.
inline constexpr FrameSize kMaxFrameSize{7680, 4320};
inline constexpr FrameSize kMinFrameSize{16, 16};
inline constexpr int kMaxFps = 240;
inline constexpr double kMaxDurationS = 3600.0;

// Parses "WxH" (e.g. "1280x720"). Throws core::InputError naming the value and what is allowed.
FrameSize parseFrameSize(const std::string& text);

// Throws core::InputError unless 1 <= fps <= kMaxFps.
void checkFps(int fps);

// Throws core::InputError unless 0 < duration <= kMaxDurationS and finite. `what` names the option,
// `typed` is the value as the user typed it ("1e999", which the parser read as infinity).
void checkDuration(double duration_s, const std::string& what, const std::string& typed);

}  // namespace collide::app
