#include "output/webm_sink.hpp"

#include <thread>

#include "output/av_writer.hpp"

namespace collide::output {

WebmSink::WebmSink(std::filesystem::path path, WebmOptions options, MediaExtras extras)
    : path_(std::move(path)), options_(options), extras_(std::move(extras)) {}

WebmSink::~WebmSink() = default;

void WebmSink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(writer_ == nullptr && !finished_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0 && format.fps > 0,
                 "empty frame format");
  const std::string name = "cannot write video '" + path_.string() + "': ";
  if (format.width_px % 2 != 0 || format.height_px % 2 != 0) {
    throw OutputError(name + "VP9 4:2:0 needs an even width and height, got " +
                      std::to_string(format.width_px) + "x" + std::to_string(format.height_px));
  }
  if (options_.crf < 0 || options_.crf > kMaxVp9Crf) {
    throw OutputError(name + "crf " + std::to_string(options_.crf) + " is outside 0.." +
                      std::to_string(kMaxVp9Crf));
  }
  if (options_.speed < 0 || options_.speed > kMaxVp9Speed) {
    throw OutputError(name + "speed " + std::to_string(options_.speed) + " is outside 0.." +
                      std::to_string(kMaxVp9Speed));
  }
  failed_ = true;
  format_ = format;
  const AVPixelFormat pixels = options_.alpha ? AV_PIX_FMT_YUVA420P : AV_PIX_FMT_YUV420P;
  av::VideoSetup setup;
  setup.container = "webm";
  setup.encoder = "libvpx-vp9";
  setup.codec_name = "VP9";
  setup.pixel_format = pixels;
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  // Constant quality (crf with no bit-rate cap); "good" quality deadline with cpu-used trading
  // quality for speed; row-based multithreading so small frames still use every core.
  setup.encoder_options = {{"crf", std::to_string(options_.crf)},
                           {"b", "0"},
                           {"deadline", "good"},
                           {"cpu-used", std::to_string(options_.speed)},
                           {"row-mt", "1"},
                           {"threads", std::to_string(std::min(threads, 16u))}};
  setup.audio_encoder = "libopus";  // WebM carries Opus or Vorbis
  setup.subtitle_encoder = "webvtt";
  writer_ = std::make_unique<av::Writer>(path_, format, setup, extras_);
  converter_ =
      std::make_unique<av::RgbaConverter>(format.width_px, format.height_px, pixels, path_);
  failed_ = false;
}

void WebmSink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "write() outside begin()/finish()");
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  if (failed_) throw OutputError("cannot write video '" + path_.string() + "' after an error");
  failed_ = true;
  converter_->convert(frame, writer_->nextFrame());
  writer_->encodeFrame();
  ++frames_written_;
  failed_ = false;
}

void WebmSink::finish() {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "finish() outside begin()");
  if (failed_) throw OutputError("cannot finish video '" + path_.string() + "' after an error");
  if (frames_written_ == 0) {
    throw OutputError("cannot write video '" + path_.string() + "': no frames were rendered");
  }
  failed_ = true;
  writer_->finish();
  finished_ = true;
  failed_ = false;
  writer_.reset();
}

}  // namespace collide::output
