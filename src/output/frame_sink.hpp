#pragma once
// Where rendered frames go. Three calls, in order: begin once, write per frame, finish once. A sink
// that is destroyed without finish() (an error or a signal) removes everything it wrote, so the
// target path never holds a partial file.
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/image.hpp"

namespace collide::output {

class OutputError : public core::RuntimeError {
 public:
  using core::RuntimeError::RuntimeError;
};

struct FrameFormat {
  int width_px = 1280;
  int height_px = 720;
  int fps = 60;  // frames per second of the stream; ignored by still sinks
};

// A frame already converted into what its sink writes (an encoder's Y'CbCr planes), made by
// FrameSink::stage() on one thread and written by FrameSink::writeStaged() on another.
class StagedFrame {
 public:
  virtual ~StagedFrame() = default;
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void begin(const FrameFormat& format) = 0;
  virtual void write(const core::ImageView& frame) = 0;
  virtual void finish() = 0;

  // A sink that converts every frame before writing it may split write() in two, so that an
  // EncodeThread converts straight out of the readback (on the drawing thread or one of its own)
  // and keeps converted frames waiting for the writer (1.5 bytes a pixel for 4:2:0 instead of an
  // RGBA copy's 4).
  // After begin(): newStagedFrame() gives a frame to stage into, or nullptr where the sink has
  // only write() (the default). stage() may run on another thread than writeStaged() and finish(),
  // at the same time as writeStaged() of a different StagedFrame; frames are written in the order
  // of the writeStaged() calls. With `rects` (top row 0, apart), `frame` differs from the frame
  // staged into `staged` before only inside them: stage() may redo only those pixels (a
  // StagedFrame keeps what it held after it is written).
  virtual std::unique_ptr<StagedFrame> newStagedFrame() { return nullptr; }
  virtual void stage(const core::ImageView& /*frame*/, StagedFrame& /*staged*/,
                     const std::vector<core::ImageRect>* /*rects*/) {
    COLLIDE_ASSERT(false, "stage() on a sink without staged frames");
  }
  virtual void writeStaged(StagedFrame& /*staged*/) {
    COLLIDE_ASSERT(false, "writeStaged() on a sink without staged frames");
  }
};

}  // namespace collide::output
