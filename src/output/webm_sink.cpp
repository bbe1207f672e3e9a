#include "output/webm_sink.hpp"

#include <algorithm>
#include <thread>

#include "output/av_writer.hpp"

namespace collide::output {
namespace {

constexpr int kRealtimeCrfOffset = 8;

}  // namespace

WebmSink::WebmSink(std::filesystem::path path, WebmOptions options, MediaExtras extras)
    : EncodedVideoSink(std::move(path), std::move(extras)), options_(options) {}

void WebmSink::describe(const FrameFormat&, av::VideoSetup& setup) const {
  if (options_.crf < 0 || options_.crf > kMaxVp9Crf) {
    throw OutputError(errorPrefix() + "crf " + std::to_string(options_.crf) + " is outside 0.." +
                      std::to_string(kMaxVp9Crf));
  }
  if (options_.speed < 0 || options_.speed > kMaxVp9Speed) {
    throw OutputError(errorPrefix() + "speed " + std::to_string(options_.speed) +
                      " is outside 0.." + std::to_string(kMaxVp9Speed));
  }
  setup.container = "webm";
  setup.encoder = "libvpx-vp9";
  setup.codec_name = "VP9";
  setup.pixel_format = options_.alpha ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P;
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  // Constant quality (crf with no bit-rate cap); libvpx's "realtime" deadline with cpu-used
  // trading quality for speed; row-based multithreading so small frames still use every core.
  // Realtime costs a fifth of the CPU of "good" but spends more bits at the same crf, so it gets
  // crf + kRealtimeCrfOffset, which keeps files and quality about where "good" has them. No lag:
  // libvpx otherwise holds 25 frames back for its alternate reference frame, which costs memory
  // for little gain in size (both measured: bench/results.md, "Figures behind the code").
  const int crf = std::min(kMaxVp9Crf, options_.crf + kRealtimeCrfOffset);
  setup.encoder_options = {{"crf", std::to_string(crf)},
                           {"b", "0"},
                           {"deadline", "realtime"},
                           {"cpu-used", std::to_string(options_.speed)},
                           {"row-mt", "1"},
                           {"lag-in-frames", "0"},
                           {"threads", std::to_string(std::min(threads, 16u))}};
  setup.audio_encoder = "libopus";  // WebM carries Opus or Vorbis
  setup.subtitle_encoder = "webvtt";
  setup.bibliographic_language = true;  // Matroska's TrackLanguage: ISO 639-2/B
}

}  // namespace collide::output
