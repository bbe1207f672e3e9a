#pragma once
// Overlaps rendering and encoding: the GL thread (the caller) renders frame k+1 while a worker
// thread hands frame k to the sink (colour conversion, compression, file writes). Frames pass
// through a small ring of buffers, so memory stays bounded and a slow sink holds the renderer
// back instead of piling frames up. Where the sink stages frames (FrameSink::newStagedFrame: the
// MP4 and WebM sinks convert to Y'CbCr 4:2:0), the caller's thread converts each frame straight
// into a staged frame and the worker only encodes; otherwise the ring holds RGBA copies.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/image.hpp"
#include "output/frame_sink.hpp"

namespace collide::output {

class EncodeThread {
 public:
  // `sink` must have begun; frames are width x height. `buffers` RGBA frames may wait at once
  // (>= 1; with one, the caller's next frame is drawn while this one is written), or
  // `staged_buffers` staged frames where the sink stages them.
  EncodeThread(output::FrameSink& sink, int width_px, int height_px, int buffers = 3,
               int staged_buffers = 3);
  // Stops the worker and drops frames not yet written; the sink is not finished (an error or a
  // signal is unwinding: the sink's own destructor then removes its partial output).
  ~EncodeThread();
  EncodeThread(const EncodeThread&) = delete;
  EncodeThread& operator=(const EncodeThread&) = delete;

  // Copies `frame` (any orientation; a bottom-up view stays bottom-up, so the sink flips it for
  // free), or stages it, and queues it; waits while every buffer is in use. Rethrows the sink's
  // error, if any.
  void submit(const core::ImageView& frame);
  // Waits until every queued frame is written, stops the worker and calls sink.finish() on the
  // calling thread. Rethrows the sink's error, if any.
  void finish();

  int framesWritten() const;

 private:
  struct Slot {
    std::vector<std::uint8_t> pixels;
    core::ImageView view;                 // into pixels, same orientation as the submitted frame
    std::unique_ptr<StagedFrame> staged;  // instead of pixels where the sink stages frames
  };
  void copyInto(Slot& slot, const core::ImageView& frame) const;
  void run();
  void stopWorker();
  void rethrowIfFailed();  // with mutex_ held

  output::FrameSink& sink_;
  int width_px_;
  int height_px_;
  std::vector<Slot> slots_;
  // Ring: slots [head_, head_ + queued_) hold frames waiting for the worker, in order.
  std::size_t head_ = 0;
  std::size_t queued_ = 0;
  bool writing_ = false;  // the worker is writing the slot at head_ (not reusable yet)
  bool stopping_ = false;
  int frames_written_ = 0;
  std::exception_ptr error_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::thread worker_;
};

}  // namespace collide::output
