#pragma once
// Where rendered frames go. Three calls, in order: begin once, write per frame, finish once. A sink
// that is destroyed without finish() (an error or a signal) removes everything it wrote, so the
// target path never holds a partial file.
#include <string>

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

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void begin(const FrameFormat& format) = 0;
  virtual void write(const core::ImageView& frame) = 0;
  virtual void finish() = 0;
};

}  // namespace collide::output
