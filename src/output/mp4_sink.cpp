#include "output/mp4_sink.hpp"

#include <algorithm>
#include <string>
#include <thread>

#include "output/av_writer.hpp"

namespace collide::output {
namespace {

// Whether x264 picks its AVX-512 functions here: it asks for AVX-512 F, CD, BW, DQ and VL, and an
// OS that keeps the zmm registers (__builtin_cpu_supports checks that too). And whether the CPU
// has what x264's "AVX2" names (FMA3, BMI1, BMI2, AVX2; every AVX-512 CPU has them and LZCNT).
bool x264WouldUseAvx512() {
#if defined(__x86_64__) && defined(__GNUC__)
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx2") &&
         __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
         __builtin_cpu_supports("bmi2");
#else
  return false;
#endif
}

// x264's settings beyond its preset, as x264-params; empty for none.
std::string x264Params(const std::string& preset) {
  std::string params;
  // The default preset, veryfast, looks 3 frames ahead instead of 10 and uses one B-frame instead
  // of 3, without the separate lookahead thread's extra frames: x264 holds each waiting frame at
  // full size, and these frames were most of a render's memory. Against x264's own veryfast this
  // takes less memory and CPU for files of about the same size and quality (bench/results.md,
  // "Figures behind the code"). Other presets keep x264's settings (the faster ones look ahead
  // less already; the slower ones, asked for compression, pay its memory).
  if (preset == "veryfast") params = "rc-lookahead=3:bframes=1:sync-lookahead=0";
  // x264 0.164's AVX-512 code in the macroblock tree reads memory it never wrote: the same frames
  // encoded where the heap held other leftovers (a batch worker's earlier jobs, MALLOC_PERTURB_)
  // gave other bytes; without the macroblock tree, or with its AVX2 code, they are the same
  // whatever the heap holds. So x264 stops at AVX2 (auto-detection less AVX-512), for a little
  // more CPU (bench/results.md, "Figures behind the code").
  if (x264WouldUseAvx512()) params += std::string(params.empty() ? "" : ":") + "asm=AVX2";
  return params;
}

}  // namespace

Mp4Sink::Mp4Sink(std::filesystem::path path, Mp4Options options, MediaExtras extras)
    : EncodedVideoSink(std::move(path), std::move(extras)), options_(std::move(options)) {}

void Mp4Sink::describe(const FrameFormat&, av::VideoSetup& setup) const {
  // Checked here rather than left to x264, which would also print its own complaint to stderr.
  if (std::find(kX264Presets.begin(), kX264Presets.end(), options_.preset) == kX264Presets.end()) {
    std::string allowed;
    for (const auto preset : kX264Presets)
      allowed += (allowed.empty() ? "" : ", ") + std::string(preset);
    throw OutputError(errorPrefix() + "unknown x264 preset '" + options_.preset +
                      "' (allowed: " + allowed + ")");
  }
  if (options_.crf < 0 || options_.crf > kMaxCrf) {
    throw OutputError(errorPrefix() + "crf " + std::to_string(options_.crf) + " is outside 0.." +
                      std::to_string(kMaxCrf));
  }
  setup.container = "mp4";
  setup.encoder = "libx264";
  setup.codec_name = "H.264";
  setup.pixel_format = AV_PIX_FMT_YUV420P;
  // x264's own number of frame threads, 1.5 per core: a frame thread often waits for rows of the
  // frame before it, and with one per core a core then idles (the pictures are the same; the
  // timings are in bench/results.md, "Figures behind the code"). Each frame thread holds frames of
  // its own, so render_pipeline.cpp keeps fewer frames waiting to pay for it. Fewer where the
  // caller says so (batch workers that already fill the cores).
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned threads =
      options_.threads > 0 ? static_cast<unsigned>(options_.threads) : std::max(1u, cores * 3 / 2);
  setup.encoder_options = {{"preset", options_.preset},
                           {"crf", std::to_string(options_.crf)},
                           {"threads", std::to_string(threads)}};
  const std::string params = x264Params(options_.preset);
  if (!params.empty()) setup.encoder_options.emplace_back("x264-params", params);
  // +faststart: after the last frame the muxer moves the index (moov) before the frame data
  // (mdat), so playback can start before the whole file has arrived.
  setup.muxer_options = {{"movflags", "+faststart"}};
  // A stream (FIFO, device, stdout) cannot be rewritten at the end: fragmented MP4 instead, an
  // empty index up front and each keyframe's run in its own fragment, as players stream it.
  setup.streamed_muxer_options = {{"movflags", "frag_keyframe+empty_moov+default_base_moof"}};
  setup.audio_encoder = "aac";  // FFmpeg's native AAC-LC encoder
  setup.subtitle_encoder = "mov_text";
}

}  // namespace collide::output
