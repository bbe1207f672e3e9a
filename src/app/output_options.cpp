#include "app/output_options.hpp"

#include <algorithm>

#include "app/render_pipeline.hpp"
#include "core/error.hpp"
#include "output/mp4_sink.hpp"
#include "output/webm_sink.hpp"

namespace collide::app {

void VideoOutputOptions::addTo(CLI::App& command) {
  command.add_option("--format", format,
                     "Output format when the path does not say: mp4, webm, gif or frames");
  quality_option =
      command.add_option("--quality", quality,
                         "Constant quality (crf), lower is better: MP4 0-51 (default 20), "
                         "WebM 0-63 (default 32)");
  command.add_option("--preset", preset,
                     "Encoder speed: ultrafast, superfast, veryfast (default), faster, fast, "
                     "medium, slow, slower, veryslow (slower: smaller files)");
  command.add_flag("--transparent", transparent,
                   "Transparent background: WebM (VP9 alpha), GIF or PNG frames");
  command.add_flag("--sound", sound,
                   "A click at each collision, louder for harder impacts: AAC in MP4, Opus in "
                   "WebM");
  command.add_flag("--captions", captions,
                   "Narration captions in a WebVTT file beside the video (NAME.vtt)");
  command.add_flag("--srt", srt, "Narration captions in a SubRip file beside the video (NAME.srt)");
  command.add_flag("--embed-captions", embed_captions,
                   "Narration as a subtitle stream inside the MP4 or WebM");
  command.add_flag("-q,--quiet", quiet, "No progress display on stderr");
  command.add_flag("--force", force,
                   "Write the video even if it would be larger than 10 GB or than the free "
                   "space left for it");
}

void VideoOutputOptions::check(const output::OutputTarget& target) const {
  const output::OutputKind kind = target.kind;
  // Side files are named after the output: a device, FIFO or stdout has no name to go by.
  for (const auto& [asked, option] : {std::pair{captions, "--captions"}, std::pair{srt, "--srt"}}) {
    if (asked && target.streamed) {
      throw core::InputError(std::string(option) + ": -o '" + target.path +
                             "' is not a file to put a caption file beside; allowed: a file "
                             "path for -o, or --embed-captions");
    }
  }
  const bool video = kind == output::OutputKind::kMp4 || kind == output::OutputKind::kWebm;
  const std::string what = output::kindName(kind);
  if (quality_option != nullptr && quality_option->count() > 0) {
    if (!video) throw core::InputError("--quality: applies to MP4 and WebM, not " + what);
    const int most = kind == output::OutputKind::kMp4 ? output::kMaxCrf : output::kMaxVp9Crf;
    if (quality < 0 || quality > most) {
      throw core::InputError("--quality: " + std::to_string(quality) + ": allowed for " + what +
                             ": 0 to " + std::to_string(most) + " (lower is better)");
    }
  }
  if (std::find(output::kX264Presets.begin(), output::kX264Presets.end(), preset) ==
      output::kX264Presets.end()) {
    std::string allowed;
    for (const auto name : output::kX264Presets) {
      allowed += (allowed.empty() ? "" : ", ") + std::string(name);
    }
    throw core::InputError("--preset: '" + preset + "': allowed: " + allowed);
  }
  if (transparent && kind == output::OutputKind::kMp4) {
    throw core::InputError(
        "--transparent: H.264 MP4 has no alpha channel; allowed with .webm, .gif or PNG frames");
  }
  if (sound && !video) {
    throw core::InputError("--sound: " + what + " has no sound; allowed with .mp4 or .webm");
  }
  if (embed_captions && !video) {
    throw core::InputError("--embed-captions: " + what +
                           " has no subtitle stream; allowed with .mp4 or .webm (use --captions "
                           "for a file beside it)");
  }
}

void applyOutputDefaults(const CLI::App& command, const VideoOutputOptions& options,
                         std::ostream& err, VideoRequest& request) {
  request.options = options;
  request.progress = core::chooseProgressStyle(err, options.quiet);
  request.progress_stream = &err;
  if (request.target.kind != output::OutputKind::kGif) return;
  if (command.get_option("--fps")->count() == 0) request.fps = kGifDefaultFps;
  if (command.get_option("--size")->count() == 0) request.size = kGifDefaultSize;
}

void StillOutputOptions::addTo(CLI::App& command) {
  command.add_flag("--transparent", transparent, "Transparent background (PNG alpha)");
  command.add_flag("!--no-alt-text", alt_text,
                   "Do not write the alt-text file NAME.alt.txt beside the image");
}

}  // namespace collide::app
