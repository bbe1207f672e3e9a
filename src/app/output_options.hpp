#pragma once
// Command-line options about what is written and how: format, quality, sound, captions,
// transparency, progress. Registered by `render` and `still`; checked against the output kind.
#include <CLI/CLI.hpp>
#include <string>

#include "app/render_settings.hpp"
#include "output/output_target.hpp"

namespace collide::app {

// Defaults a GIF gets when --fps or --size are not given: small and smooth enough for slides.
inline constexpr int kGifDefaultFps = 25;
// GIF delays are whole centiseconds and browsers show 0 or 1 cs as 10 cs: 2 cs, 50 fps, is the
// shortest delay that plays as written.
inline constexpr int kMaxGifFps = 50;
inline constexpr FrameSize kGifDefaultSize{640, 360};
inline constexpr int kDefaultMp4Quality = 20;   // x264 crf
inline constexpr int kDefaultWebmQuality = 32;  // libvpx crf

struct VideoOutputOptions {
  std::string format;                     // --format: mp4, webm, gif, frames; empty: from the path
  int quality = -1;                       // --quality (crf); -1: the codec's default
  CLI::Option* quality_option = nullptr;  // count() > 0 when --quality was given
  std::string preset = "veryfast";
  bool transparent = false;
  bool sound = false;
  bool captions = false;        // WebVTT beside the video
  bool srt = false;             // SubRip beside the video
  bool embed_captions = false;  // subtitle stream inside MP4/WebM
  bool quiet = false;
  bool force = false;  // --force: past the size bounds of output/output_plan.hpp

  void addTo(CLI::App& command);
  // Throws core::InputError when an option does not fit the target's kind, or is out of range,
  // or asks for a file beside a target that is not a file (stdout, a device, a FIFO).
  void check(const output::OutputTarget& target) const;
  bool wantsNarration() const { return captions || srt || embed_captions; }
};

struct VideoRequest;

// Fills `request` from the options: copies them in, chooses the progress display on `err`, and for
// a GIF applies kGifDefaultFps and kGifDefaultSize where `command` got no --fps or --size.
void applyOutputDefaults(const CLI::App& command, const VideoOutputOptions& options,
                         std::ostream& err, VideoRequest& request);

struct StillOutputOptions {
  bool transparent = false;
  bool alt_text = true;  // --no-alt-text turns it off
  void addTo(CLI::App& command);
};

}  // namespace collide::app
