#pragma once
// Composes a video's frames on a worker thread, a few ahead of the thread that draws them: working
// out frame k + 1's FrameModel (sampling the timeline, placing labels) then overlaps drawing,
// reading back and converting frame k, which all wait on each other on the drawing thread, the
// render's critical chain on two cores (bench/results.md). Models come out in frame order; memory
// stays at `depth` models.
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include "frame/frame_model.hpp"

namespace collide::app {

class FramesAhead {
 public:
  using Compose = std::function<frame::FrameModel(int frame)>;

  // Starts composing frames 0 .. frames - 1 with `compose` (called on the worker thread, in
  // order), keeping at most `depth` (>= 1) composed frames waiting.
  FramesAhead(int frames, Compose compose, int depth = 2);
  // Stops the worker after the frame it is composing; frames not taken are dropped.
  ~FramesAhead();
  FramesAhead(const FramesAhead&) = delete;
  FramesAhead& operator=(const FramesAhead&) = delete;

  // The next frame's model, waiting for it if need be; at most `frames` calls. Rethrows what
  // `compose` threw, once the frames composed before it are taken.
  frame::FrameModel next();

 private:
  void run();

  Compose compose_;
  int frames_;
  std::size_t depth_;
  int taken_ = 0;
  std::deque<frame::FrameModel> ready_;
  std::exception_ptr error_;
  bool stopping_ = false;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::thread worker_;  // last: starts once everything above is set up
};

}  // namespace collide::app
