#pragma once
// What the MP4 and WebM sinks share: RGBA frames converted to Y'CbCr 4:2:0 (av::convertRgba) and
// encoded through av::Writer into a temporary file that finish() renames over the target. A
// subclass only checks its options and names its container and encoders (describe()). After any
// error the sink refuses further frames, and destroyed unfinished it deletes the temporary file,
// leaving the target untouched.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "output/frame_sink.hpp"
#include "output/media_extras.hpp"

namespace collide::output {

namespace av {
class Writer;
struct VideoSetup;
}  // namespace av

class EncodedVideoSink : public FrameSink {
 public:
  ~EncodedVideoSink() override;
  EncodedVideoSink(const EncodedVideoSink&) = delete;
  EncodedVideoSink& operator=(const EncodedVideoSink&) = delete;

  // Throws OutputError: options out of range (from describe()), an odd width or height (4:2:0
  // chroma needs even sizes), a missing encoder, any codec or I/O failure.
  void begin(const FrameFormat& format) final;
  void write(const core::ImageView& frame) final;
  // Throws OutputError also when no frame was written.
  void finish() final;
  // Staged frames are the encoder's own Y'CbCr frames: stage() converts into one (on the drawing
  // thread), writeStaged() only encodes it.
  std::unique_ptr<StagedFrame> newStagedFrame() final;
  void stage(const core::ImageView& frame, StagedFrame& staged,
             const std::vector<core::ImageRect>* rects) final;
  void writeStaged(StagedFrame& staged) final;

  int framesWritten() const { return frames_written_; }

 protected:
  EncodedVideoSink(std::filesystem::path path, MediaExtras extras);

  // Checks the subclass's options (throwing OutputError with errorPrefix()) and fills `setup`.
  virtual void describe(const FrameFormat& format, av::VideoSetup& setup) const = 0;
  // "cannot write video 'PATH': ", the start of every error about this file.
  std::string errorPrefix() const;

 private:
  std::filesystem::path path_;
  MediaExtras extras_;
  FrameFormat format_;
  std::unique_ptr<av::Writer> writer_;
  int frames_written_ = 0;
  bool finished_ = false;
  bool failed_ = false;  // an earlier call threw; the file can no longer be completed
};

}  // namespace collide::output
