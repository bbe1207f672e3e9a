// The compose-ahead worker of the video path: models arrive in frame order, no more than `depth`
// wait, a composer's error reaches the drawing thread after the frames before it, and abandoning a
// run (an error or a signal while drawing) stops the worker without waiting for the rest.
#include "app/frames_ahead.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace collide::app {
namespace {

// A model that carries its frame number as its title.
frame::FrameModel numbered(int frame) {
  frame::FrameModel model;
  model.title = std::to_string(frame);
  return model;
}

TEST(FramesAheadTest, ModelsArriveInFrameOrder) {
  FramesAhead models(200, numbered);
  for (int k = 0; k < 200; ++k) EXPECT_EQ(models.next().title, std::to_string(k));
}

TEST(FramesAheadTest, ComposesAheadButAtMostDepthFrames) {
  std::atomic<int> composed{0};
  FramesAhead models(
      50,
      [&](int k) {
        ++composed;
        return numbered(k);
      },
      2);
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(models.next().title, std::to_string(k));
    // k + 1 taken: the worker fills the two waiting places (a generous deadline for a loaded
    // machine), then waits for room instead of composing further.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (composed.load() < k + 1 + 2 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(composed.load(), k + 1 + 2);
  }
}

TEST(FramesAheadTest, AComposerErrorArrivesAfterTheFramesBeforeIt) {
  FramesAhead models(10, [](int k) {
    if (k == 3) throw std::runtime_error("frame 3 failed");
    return numbered(k);
  });
  for (int k = 0; k < 3; ++k) EXPECT_EQ(models.next().title, std::to_string(k));
  try {
    static_cast<void>(models.next());
    FAIL() << "frame 3's error was not rethrown";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "frame 3 failed");
  }
}

TEST(FramesAheadTest, AnAbandonedRunStopsTheWorker) {
  std::atomic<int> composed{0};
  {
    FramesAhead models(1000000, [&](int k) {
      ++composed;
      return numbered(k);
    });
    EXPECT_EQ(models.next().title, "0");
  }  // destroyed with 999,999 frames left: must not compose them all
  EXPECT_LT(composed.load(), 10);
}

}  // namespace
}  // namespace collide::app
