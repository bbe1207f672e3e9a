#include "output/mp4_sink.hpp"

#include <algorithm>

#include "output/av_writer.hpp"

namespace collide::output {

Mp4Sink::Mp4Sink(std::filesystem::path path, Mp4Options options, MediaExtras extras)
    : path_(std::move(path)), options_(std::move(options)), extras_(std::move(extras)) {}

Mp4Sink::~Mp4Sink() = default;  // ~Writer deletes the temporary file unless finish() renamed it

void Mp4Sink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(writer_ == nullptr && !finished_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0 && format.fps > 0,
                 "empty frame format");
  if (format.width_px % 2 != 0 || format.height_px % 2 != 0) {
    throw OutputError("cannot write video '" + path_.string() + "': H.264 needs an even width " +
                      "and height, got " + std::to_string(format.width_px) + "x" +
                      std::to_string(format.height_px));
  }
  // Checked here rather than left to x264, which would also print its own complaint to stderr.
  if (std::find(kX264Presets.begin(), kX264Presets.end(), options_.preset) == kX264Presets.end()) {
    std::string allowed;
    for (const auto preset : kX264Presets)
      allowed += (allowed.empty() ? "" : ", ") + std::string(preset);
    throw OutputError("cannot write video '" + path_.string() + "': unknown x264 preset '" +
                      options_.preset + "' (allowed: " + allowed + ")");
  }
  if (options_.crf < 0 || options_.crf > kMaxCrf) {
    throw OutputError("cannot write video '" + path_.string() + "': crf " +
                      std::to_string(options_.crf) + " is outside 0.." + std::to_string(kMaxCrf));
  }
  failed_ = true;  // until begin() completes
  format_ = format;
  av::VideoSetup setup;
  setup.container = "mp4";
  setup.encoder = "libx264";
  setup.codec_name = "H.264";
  setup.pixel_format = AV_PIX_FMT_YUV420P;
  setup.encoder_options = {{"preset", options_.preset}, {"crf", std::to_string(options_.crf)}};
  // +faststart: after the last frame the muxer moves the index (moov) before the frame data
  // (mdat), so playback can start before the whole file has arrived.
  setup.muxer_options = {{"movflags", "+faststart"}};
  setup.audio_encoder = "aac";  // FFmpeg's native AAC-LC encoder
  setup.subtitle_encoder = "mov_text";
  writer_ = std::make_unique<av::Writer>(path_, format, setup, extras_);
  converter_ = std::make_unique<av::RgbaConverter>(format.width_px, format.height_px,
                                                   AV_PIX_FMT_YUV420P, path_);
  failed_ = false;
}

void Mp4Sink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "write() outside begin()/finish()");
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  if (failed_) throw OutputError("cannot write video '" + path_.string() + "' after an error");
  failed_ = true;  // until this frame is through
  converter_->convert(frame, writer_->nextFrame());
  writer_->encodeFrame();
  ++frames_written_;
  failed_ = false;
}

void Mp4Sink::finish() {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "finish() outside begin()");
  if (failed_) throw OutputError("cannot finish video '" + path_.string() + "' after an error");
  if (frames_written_ == 0) {
    throw OutputError("cannot write video '" + path_.string() + "': no frames were rendered");
  }
  failed_ = true;
  writer_->finish();
  finished_ = true;
  failed_ = false;
  writer_.reset();  // free the codec now rather than when the sink dies
}

}  // namespace collide::output
