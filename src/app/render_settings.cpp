#include "app/render_settings.hpp"

#include <cmath>
#include <regex>

#include "core/error.hpp"
#include "core/typed_text.hpp"

namespace collide::app {

FrameSize parseFrameSize(const std::string& text) {
  static const std::regex kPattern(R"((\d{1,5})[xX](\d{1,5}))");
  std::smatch match;
  const std::string allowed =
      "allowed: WIDTHxHEIGHT from " + std::to_string(kMinFrameSize.width_px) + "x" +
      std::to_string(kMinFrameSize.height_px) + " to " + std::to_string(kMaxFrameSize.width_px) +
      "x" + std::to_string(kMaxFrameSize.height_px);
  if (!std::regex_match(text, match, kPattern)) {
    throw core::InputError("--size: '" + text + "': not a size; " + allowed);
  }
  const FrameSize size{std::stoi(match[1].str()), std::stoi(match[2].str())};
  if (size.width_px < kMinFrameSize.width_px || size.height_px < kMinFrameSize.height_px ||
      size.width_px > kMaxFrameSize.width_px || size.height_px > kMaxFrameSize.height_px) {
    throw core::InputError("--size: '" + text + "': out of range; " + allowed);
  }
  return size;
}

void checkFps(int fps) {
  if (fps < 1 || fps > kMaxFps) {
    throw core::InputError("--fps: " + std::to_string(fps) + ": allowed: 1 to " +
                           std::to_string(kMaxFps) + " frames per second");
  }
}

void checkDuration(double duration_s, const std::string& what, const std::string& typed) {
  if (!std::isfinite(duration_s) || duration_s <= 0.0 || duration_s > kMaxDurationS) {
    throw core::InputError(what + ": " + core::echoTyped(typed) +
                           ": allowed: more than 0 and at most " +
                           std::to_string(static_cast<int>(kMaxDurationS)) + " seconds");
  }
}

}  // namespace collide::app
