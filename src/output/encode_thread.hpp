#pragma once
// Overlaps rendering and encoding: the GL thread (the caller) renders frame k+1 while a worker
// thread hands frame k to the sink (colour conversion, compression, file writes). Frames pass
// through a small ring of buffers, so memory stays bounded and a slow sink holds the renderer
// back instead of piling frames up. Where the sink stages frames (FrameSink::newStagedFrame: the
// MP4 and WebM sinks convert to Y'CbCr 4:2:0), each frame is converted straight into a staged
// frame and the worker only encodes: on the caller's thread, or, where the caller's frames stay
// whole until its next submit() (FrameLifetime::kUntilNextSubmit, the renderer's two readback
// buffers), on a third thread while the caller draws the next frame. Otherwise the ring holds RGBA
// copies. With EncodeOn::kCallingThread (a batch worker whose share is one core) there is no
// thread at all: submit() converts and encodes each frame before it returns.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/image.hpp"
#include "core/stale_rects.hpp"
#include "output/frame_sink.hpp"

namespace collide::output {

// How long the pixels of a frame given to EncodeThread::submit() stay whole in the caller's memory.
enum class FrameLifetime {
  kUntilSubmitReturns,  // the caller may overwrite them as soon as submit() returns
  kUntilNextSubmit,     // until the next submit() or finish() returns (two buffers in turn)
};

// Where frames are converted and encoded.
enum class EncodeOn {
  kOwnThreads,     // a worker thread (and a converting one, see above): overlaps the caller
  kCallingThread,  // in submit() itself: one thread does everything, in turn
};

class EncodeThread {
 public:
  // `sink` must have begun; frames are width x height. `buffers` RGBA frames may wait at once
  // (>= 1; with one, the caller's next frame is drawn while this one is written), or
  // `staged_buffers` staged frames where the sink stages them. On the calling thread one staged
  // frame is kept, or none (the caller's frame then goes to the sink as it is).
  EncodeThread(output::FrameSink& sink, int width_px, int height_px, int buffers = 3,
               int staged_buffers = 3, FrameLifetime lifetime = FrameLifetime::kUntilSubmitReturns,
               EncodeOn on = EncodeOn::kOwnThreads);
  // Stops the worker and drops frames not yet written; the sink is not finished (an error or a
  // signal is unwinding: the sink's own destructor then removes its partial output).
  ~EncodeThread();
  EncodeThread(const EncodeThread&) = delete;
  EncodeThread& operator=(const EncodeThread&) = delete;

  // Copies `frame` (any orientation; a bottom-up view stays bottom-up, so the sink flips it for
  // free), or stages it, and queues it; waits while every buffer is in use. Where frames live
  // until the next submit and the sink stages them, it only waits for the previous frame to be
  // staged and hands this one to the converting thread. Rethrows the sink's error, if any.
  // Outside `changed` (top row 0; nullptr: anywhere), `frame` equals the frame submitted before
  // it: a staged frame, reused every few frames, is then staged again only in the rectangles
  // changed since it was staged last.
  void submit(const core::ImageView& frame, const std::vector<core::ImageRect>* changed = nullptr);
  // Waits until every queued frame is written, stops the worker and calls sink.finish() on the
  // calling thread. Rethrows the sink's error, if any.
  void finish();

  int framesWritten() const;

 private:
  struct Slot {
    std::vector<std::uint8_t> pixels;
    core::ImageView view;                 // into pixels, same orientation as the submitted frame
    std::unique_ptr<StagedFrame> staged;  // instead of pixels where the sink stages frames
    // Where the next frame staged here may differ from the one it holds; taken (with mutex_
    // held) by the one thread that stages, whose answer stays valid while it stages.
    core::StaleRects stale;
  };
  void copyInto(Slot& slot, const core::ImageView& frame) const;
  void noteChanged(const std::vector<core::ImageRect>* changed);  // with mutex_ held
  void submitHere(const core::ImageView& frame, const std::vector<core::ImageRect>* changed);
  void run();
  void convert();  // the converting thread: stages each handed frame into a free slot
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
  // A caller's frame handed to the converting thread and not yet staged (kUntilNextSubmit).
  std::optional<core::ImageView> handed_;
  bool stopping_ = false;
  int frames_written_ = 0;
  std::exception_ptr error_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::thread worker_;     // none with EncodeOn::kCallingThread
  std::thread converter_;  // only for kUntilNextSubmit with a staging sink
};

}  // namespace collide::output
