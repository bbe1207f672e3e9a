#include "output/encoded_video_sink.hpp"

#include <sys/prctl.h>

#include "output/av_writer.hpp"

namespace collide::output {
namespace {

struct YuvFrame final : StagedFrame {
  av::FramePtr frame;
};

}  // namespace

EncodedVideoSink::EncodedVideoSink(std::filesystem::path path, MediaExtras extras)
    : path_(std::move(path)), extras_(std::move(extras)) {}

// ~Writer deletes the temporary file unless finish() renamed it.
EncodedVideoSink::~EncodedVideoSink() = default;

std::string EncodedVideoSink::errorPrefix() const {
  return "cannot write video '" + path_.string() + "': ";
}

void EncodedVideoSink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(writer_ == nullptr && !finished_, "begin() called twice");
  COLLIDE_ASSERT(format.width_px > 0 && format.height_px > 0 && format.fps > 0,
                 "empty frame format");
  av::VideoSetup setup;
  describe(format, setup);
  // Both containers' pixel formats subsample chroma 2x2 (4:2:0).
  if (format.width_px % 2 != 0 || format.height_px % 2 != 0) {
    throw OutputError(errorPrefix() + setup.codec_name + " needs an even width and height, got " +
                      std::to_string(format.width_px) + "x" + std::to_string(format.height_px));
  }
  failed_ = true;  // until begin() completes
  format_ = format;
  // No transparent huge pages from here on: the encoder's frames (6-10 MiB each at 1080p) came in
  // whole 2 MiB pages, resident whether touched or not. Without them a render peaks lower at the
  // same CPU (bench/results.md, "Figures behind the code"). A hint: ignored where refused.
  static_cast<void>(prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0));
  writer_ = std::make_unique<av::Writer>(path_, format, setup, extras_);
  failed_ = false;
}

void EncodedVideoSink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "write() outside begin()/finish()");
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  if (failed_) throw OutputError("cannot write video '" + path_.string() + "' after an error");
  failed_ = true;  // until this frame is through
  av::convertRgba(frame, writer_->nextFrame(), path_);
  writer_->encodeFrame();
  ++frames_written_;
  failed_ = false;
}

std::unique_ptr<StagedFrame> EncodedVideoSink::newStagedFrame() {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "newStagedFrame() outside begin()/finish()");
  auto staged = std::make_unique<YuvFrame>();
  staged->frame = writer_->newVideoFrame();
  return staged;
}

// Touches only the staged frame (and reads path_), so it may run beside writeStaged().
void EncodedVideoSink::stage(const core::ImageView& frame, StagedFrame& staged,
                             const std::vector<core::ImageRect>* rects) {
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  // A staged frame's planes keep the frame converted into them last (the encoder copies a frame
  // in; nothing writes into it), so only the rectangles given need converting again.
  av::convertRgba(frame, *static_cast<YuvFrame&>(staged).frame, path_, rects);
}

void EncodedVideoSink::writeStaged(StagedFrame& staged) {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "writeStaged() outside begin()/finish()");
  if (failed_) throw OutputError("cannot write video '" + path_.string() + "' after an error");
  failed_ = true;  // until this frame is through
  writer_->encodeFrame(*static_cast<YuvFrame&>(staged).frame);
  ++frames_written_;
  failed_ = false;
}

void EncodedVideoSink::finish() {
  COLLIDE_ASSERT(writer_ != nullptr && !finished_, "finish() outside begin()");
  if (failed_) throw OutputError("cannot finish video '" + path_.string() + "' after an error");
  if (frames_written_ == 0) throw OutputError(errorPrefix() + "no frames were rendered");
  failed_ = true;
  writer_->finish();
  finished_ = true;
  failed_ = false;
  writer_.reset();  // free the codec now rather than when the sink dies
}

}  // namespace collide::output
