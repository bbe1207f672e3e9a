#include "output/encode_thread.hpp"

#include <cstring>

#include "core/error.hpp"

namespace collide::output {

EncodeThread::EncodeThread(output::FrameSink& sink, int width_px, int height_px, int buffers,
                           int staged_buffers, FrameLifetime lifetime, EncodeOn on)
    : sink_(sink), width_px_(width_px), height_px_(height_px) {
  COLLIDE_ASSERT(buffers >= 1 && staged_buffers >= 1 && width_px > 0 && height_px > 0,
                 "need a buffer and a size");
  std::unique_ptr<StagedFrame> first = sink_.newStagedFrame();
  if (on == EncodeOn::kCallingThread) {
    // Each frame is written before submit() returns: nothing waits, so one staged frame (kept
    // for the rectangles the next frame changes) or none.
    slots_.resize(1);
    slots_.front().staged = std::move(first);
    return;
  }
  if (first != nullptr) {
    slots_.resize(static_cast<std::size_t>(staged_buffers));
    slots_.front().staged = std::move(first);
    for (std::size_t s = 1; s < slots_.size(); ++s) slots_[s].staged = sink_.newStagedFrame();
  } else {
    slots_.resize(static_cast<std::size_t>(buffers));
    for (Slot& slot : slots_) {
      slot.pixels.resize(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px) *
                         4);
    }
  }
  worker_ = std::thread([this] { run(); });
  if (slots_.front().staged != nullptr && lifetime == FrameLifetime::kUntilNextSubmit) {
    converter_ = std::thread([this] { convert(); });
  }
}

EncodeThread::~EncodeThread() {
  stopWorker();
}

void EncodeThread::stopWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    queued_ = writing_ ? 1 : 0;  // drop waiting frames; the one being written finishes
  }
  changed_.notify_all();
  if (converter_.joinable()) converter_.join();
  if (worker_.joinable()) worker_.join();
}

void EncodeThread::rethrowIfFailed() {
  if (error_) std::rethrow_exception(error_);
}

void EncodeThread::copyInto(Slot& slot, const core::ImageView& frame) const {
  const std::size_t row_bytes = static_cast<std::size_t>(width_px_) * 4;
  const auto stride = static_cast<std::ptrdiff_t>(row_bytes);
  if (frame.row_stride == stride || frame.row_stride == -stride) {
    // Rows are contiguous in memory, top-down or bottom-up: one copy of the whole block.
    const std::uint8_t* lowest = frame.row_stride > 0 ? frame.top_row : frame.row(height_px_ - 1);
    std::memcpy(slot.pixels.data(), lowest, row_bytes * static_cast<std::size_t>(height_px_));
    std::uint8_t* top =
        frame.row_stride > 0
            ? slot.pixels.data()
            : slot.pixels.data() + row_bytes * static_cast<std::size_t>(height_px_ - 1);
    slot.view = core::ImageView{top, width_px_, height_px_, frame.row_stride};
  } else {
    for (int y = 0; y < height_px_; ++y) {
      std::memcpy(slot.pixels.data() + row_bytes * static_cast<std::size_t>(y), frame.row(y),
                  row_bytes);
    }
    slot.view = core::ImageView{slot.pixels.data(), width_px_, height_px_, stride};
  }
}

void EncodeThread::noteChanged(const std::vector<core::ImageRect>* changed) {
  for (Slot& slot : slots_) slot.stale.note(changed);
}

void EncodeThread::submit(const core::ImageView& frame,
                          const std::vector<core::ImageRect>* changed) {
  COLLIDE_ASSERT(frame.width == width_px_ && frame.height == height_px_,
                 "frame size differs from the encoder's");
  if (!worker_.joinable()) {
    submitHere(frame, changed);
    return;
  }
  if (converter_.joinable()) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      // The previous frame staged: its pixels may be overwritten once this call returns.
      changed_.wait(lock, [&] { return error_ || !handed_; });
      rethrowIfFailed();
      handed_ = frame;
      noteChanged(changed);
    }
    changed_.notify_all();
    return;
  }
  Slot* slot = nullptr;
  const std::vector<core::ImageRect>* rects = nullptr;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return error_ || queued_ < slots_.size(); });
    rethrowIfFailed();
    slot = &slots_[(head_ + queued_) % slots_.size()];
    noteChanged(changed);
    if (slot->staged != nullptr) rects = slot->stale.take();
  }
  // Convert or copy outside the lock; the slot is not visible to the worker until queued_ grows.
  if (slot->staged != nullptr) {
    sink_.stage(frame, *slot->staged, rects);
  } else {
    copyInto(*slot, frame);
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++queued_;
  }
  changed_.notify_all();
}

void EncodeThread::submitHere(const core::ImageView& frame,
                              const std::vector<core::ImageRect>* changed) {
  Slot& slot = slots_.front();
  if (slot.staged == nullptr) {
    sink_.write(frame);
  } else {
    const std::vector<core::ImageRect>* rects = nullptr;
    {
      // No other thread: the lock only keeps framesWritten() and the bookkeeping's contract.
      std::lock_guard<std::mutex> lock(mutex_);
      noteChanged(changed);
      rects = slot.stale.take();
    }
    sink_.stage(frame, *slot.staged, rects);
    sink_.writeStaged(*slot.staged);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++frames_written_;
}

void EncodeThread::run() {
  for (;;) {
    Slot* slot = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || queued_ > 0; });
      if (queued_ == 0 || error_) return;  // stopping with nothing left, or after a failure
      slot = &slots_[head_];
      writing_ = true;
    }
    try {
      if (slot->staged != nullptr) {
        sink_.writeStaged(*slot->staged);
      } else {
        sink_.write(slot->view);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = std::current_exception();
      writing_ = false;
      changed_.notify_all();
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      writing_ = false;
      head_ = (head_ + 1) % slots_.size();
      --queued_;
      ++frames_written_;
    }
    changed_.notify_all();
  }
}

void EncodeThread::convert() {
  for (;;) {
    Slot* slot = nullptr;
    core::ImageView frame;
    const std::vector<core::ImageRect>* rects = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || error_ || handed_; });
      if (stopping_ || error_) return;
      frame = *handed_;
      changed_.wait(lock, [&] { return stopping_ || error_ || queued_ < slots_.size(); });
      if (stopping_ || error_) return;
      slot = &slots_[(head_ + queued_) % slots_.size()];
      // The next frame's changes are noted only once this one is staged (submit waits for that).
      rects = slot->stale.take();
    }
    // Outside the lock: the slot is not visible to the worker until queued_ grows.
    try {
      sink_.stage(frame, *slot->staged, rects);
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      error_ = std::current_exception();
      changed_.notify_all();
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) return;  // abandoned meanwhile: the frame is dropped
      ++queued_;
      handed_.reset();
    }
    changed_.notify_all();
  }
}

void EncodeThread::finish() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return error_ || (queued_ == 0 && !handed_); });
    rethrowIfFailed();
    stopping_ = true;
  }
  changed_.notify_all();
  if (converter_.joinable()) converter_.join();
  if (worker_.joinable()) worker_.join();
  rethrowIfFailed();
  sink_.finish();
}

int EncodeThread::framesWritten() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return frames_written_;
}

}  // namespace collide::output
