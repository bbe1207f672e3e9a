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
  // crf + kRealtimeCrfOffset: measured on worked-example (1080p) and billiards-break (720p) at the
  // default crf 32, files 5 % larger and 17 % smaller, SSIM 0.9925 and 0.9942 against the frames
  // (bench/results.md). No lag: libvpx otherwise holds 25 frames back for its alternate reference
  // frame (720p worked-example and billiards-break: peak RSS 283 -> 227 and 294 -> 230 MiB, files
  // 2.9 % and 4.1 % larger, SSIM 0.9986 and 0.9958 against the lagged files).
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
