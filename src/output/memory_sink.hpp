#pragma once
// Test double: keeps a top-down copy of every frame in memory.
#include <vector>

#include "output/frame_sink.hpp"

namespace collide::output {

class MemorySink : public FrameSink {
 public:
  void begin(const FrameFormat& format) override;
  void write(const core::ImageView& frame) override;
  void finish() override;

  const FrameFormat& format() const { return format_; }
  const std::vector<core::Image>& frames() const { return frames_; }
  bool begun() const { return begun_; }
  bool finished() const { return finished_; }

 private:
  FrameFormat format_;
  std::vector<core::Image> frames_;
  bool begun_ = false;
  bool finished_ = false;
};

}  // namespace collide::output
