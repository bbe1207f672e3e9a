#include "app/frames_ahead.hpp"

#include <utility>

#include "core/error.hpp"

namespace collide::app {

FramesAhead::FramesAhead(int frames, Compose compose, int depth)
    : compose_(std::move(compose)), frames_(frames), depth_(static_cast<std::size_t>(depth)) {
  COLLIDE_ASSERT(frames >= 0 && depth >= 1 && compose_,
                 "need a frame count, a depth and a composer");
  worker_ = std::thread([this] { run(); });
}

FramesAhead::~FramesAhead() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void FramesAhead::run() {
  for (int k = 0; k < frames_; ++k) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || ready_.size() < depth_; });
      if (stopping_) return;
    }
    try {
      frame::FrameModel model = compose_(k);
      std::lock_guard<std::mutex> lock(mutex_);
      ready_.push_back(std::move(model));
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = std::current_exception();
      changed_.notify_all();
      return;
    }
    changed_.notify_all();
  }
}

frame::FrameModel FramesAhead::next() {
  std::unique_lock<std::mutex> lock(mutex_);
  COLLIDE_ASSERT(taken_ < frames_, "more frames taken than were asked for");
  changed_.wait(lock, [&] { return !ready_.empty() || error_; });
  if (ready_.empty()) std::rethrow_exception(error_);
  frame::FrameModel model = std::move(ready_.front());
  ready_.pop_front();
  ++taken_;
  lock.unlock();
  changed_.notify_all();
  return model;
}

}  // namespace collide::app
