#include "output/memory_sink.hpp"

namespace collide::output {

void MemorySink::begin(const FrameFormat& format) {
  COLLIDE_ASSERT(!begun_, "begin() called twice");
  format_ = format;
  begun_ = true;
}

void MemorySink::write(const core::ImageView& frame) {
  COLLIDE_ASSERT(begun_ && !finished_, "write() outside begin()/finish()");
  COLLIDE_ASSERT(frame.width == format_.width_px && frame.height == format_.height_px,
                 "frame size differs from the format given to begin()");
  frames_.push_back(core::Image::copyOf(frame));
}

void MemorySink::finish() {
  COLLIDE_ASSERT(begun_ && !finished_, "finish() outside begin()");
  finished_ = true;
}

}  // namespace collide::output
