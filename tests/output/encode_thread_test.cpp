// The render/encode overlap: frames reach the sink in order and upright, a sink error comes back
// to the renderer's thread, an abandoned run never finishes the sink; the progress text.
#include "output/encode_thread.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/progress.hpp"
#include "output/memory_sink.hpp"

namespace collide::output {
namespace {

// A 4x3 frame whose every pixel holds its frame number; `bottom_up` stores it upside down.
core::ImageView numberedFrame(int number, bool bottom_up, std::vector<std::uint8_t>& storage) {
  storage.assign(4 * 4 * 3, 0);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      std::uint8_t* p = storage.data() + 4 * (4 * (bottom_up ? 2 - y : y) + x);
      p[0] = static_cast<std::uint8_t>(number);
      p[1] = static_cast<std::uint8_t>(y);  // the row as seen upright
      p[3] = 255;
    }
  }
  if (!bottom_up) return {storage.data(), 4, 3, 16};
  return {storage.data() + 2 * 16, 4, 3, -16};
}

TEST(EncodeThreadTest, FramesArriveInOrderAndUpright) {
  MemorySink sink;
  sink.begin({4, 3, 10});
  {
    EncodeThread encoder(sink, 4, 3, 2);
    std::vector<std::uint8_t> storage;
    for (int k = 0; k < 50; ++k) encoder.submit(numberedFrame(k, k % 2 == 1, storage));
    encoder.finish();
    EXPECT_EQ(encoder.framesWritten(), 50);
  }
  ASSERT_TRUE(sink.finished());
  ASSERT_EQ(sink.frames().size(), 50u);
  for (int k = 0; k < 50; ++k) {
    EXPECT_EQ(sink.frames()[k].pixel(1, 0)[0], k);
    EXPECT_EQ(sink.frames()[k].pixel(1, 2)[1], 2) << "frame " << k << " upside down";
  }
}

class FailingSink : public FrameSink {
 public:
  void begin(const FrameFormat&) override {}
  void write(const core::ImageView&) override {
    if (++written_ == 3) throw OutputError("disk full");
  }
  void finish() override { finished_ = true; }
  bool finished_ = false;

 private:
  int written_ = 0;
};

TEST(EncodeThreadTest, SinkErrorReachesTheRenderingThread) {
  FailingSink sink;
  std::vector<std::uint8_t> storage;
  EXPECT_THROW(
      {
        EncodeThread encoder(sink, 4, 3, 2);
        for (int k = 0; k < 100; ++k) encoder.submit(numberedFrame(k, false, storage));
        encoder.finish();
      },
      OutputError);
  EXPECT_FALSE(sink.finished_);
}

TEST(EncodeThreadTest, AbandonedRunDoesNotFinishTheSink) {
  MemorySink sink;
  sink.begin({4, 3, 10});
  {
    EncodeThread encoder(sink, 4, 3, 3);
    std::vector<std::uint8_t> storage;
    for (int k = 0; k < 5; ++k) encoder.submit(numberedFrame(k, false, storage));
  }  // as when a signal or an error unwinds the render loop
  EXPECT_FALSE(sink.finished());
  EXPECT_LE(sink.frames().size(), 5u);
}

// Stages a frame as its number and upright row mark, on whatever thread submits it; records the
// threads and the order in which staged frames are written.
class StagingSink : public FrameSink {
 public:
  struct Staged : StagedFrame {
    int number = -1;
    int lower_row_mark = -1;
  };
  void begin(const FrameFormat&) override {}
  void write(const core::ImageView&) override { ++unstaged_writes; }
  void finish() override { finished = true; }
  std::unique_ptr<StagedFrame> newStagedFrame() override {
    ++staged_frames_made;
    return std::make_unique<Staged>();
  }
  void stage(const core::ImageView& frame, StagedFrame& staged,
             const std::vector<core::ImageRect>* /*rects*/) override {
    stage_threads.push_back(std::this_thread::get_id());
    auto& s = static_cast<Staged&>(staged);
    s.number = frame.pixel(1, 0)[0];
    if (s.number == fail_stage_at) throw OutputError("cannot convert frame");
    s.lower_row_mark = frame.pixel(1, 2)[1];
  }
  void writeStaged(StagedFrame& staged) override {
    write_threads.push_back(std::this_thread::get_id());
    const auto& s = static_cast<const Staged&>(staged);
    written.push_back(s.number);
    marks.push_back(s.lower_row_mark);
  }
  int unstaged_writes = 0;
  int staged_frames_made = 0;
  int fail_stage_at = -1;  // stage() throws for the frame of this number
  bool finished = false;
  std::vector<std::thread::id> stage_threads, write_threads;
  std::vector<int> written, marks;
};

// The sink finished with `count` frames, every one staged (converted into the encoder's own
// frame), written in order (frame k k-th) and right way up and intact (numberedFrame's mark).
void expectAllStagedAndWrittenInOrder(const StagingSink& sink, int count) {
  EXPECT_TRUE(sink.finished);
  EXPECT_EQ(sink.unstaged_writes, 0);
  ASSERT_EQ(sink.written.size(), static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    EXPECT_EQ(sink.written[k], k);
    EXPECT_EQ(sink.marks[k], 2) << "frame " << k << " upside down or overwritten";
  }
}

TEST(EncodeThreadTest, StagedFramesAreConvertedOnTheCallersThreadAndWrittenInOrder) {
  StagingSink sink;
  sink.begin({4, 3, 10});
  {
    EncodeThread encoder(sink, 4, 3, 1, 3);
    EXPECT_EQ(sink.staged_frames_made, 3);
    std::vector<std::uint8_t> storage;
    for (int k = 0; k < 40; ++k) encoder.submit(numberedFrame(k, k % 2 == 1, storage));
    encoder.finish();
    EXPECT_EQ(encoder.framesWritten(), 40);
  }
  expectAllStagedAndWrittenInOrder(sink, 40);
  for (const auto id : sink.stage_threads) EXPECT_EQ(id, std::this_thread::get_id());
  for (const auto id : sink.write_threads) EXPECT_NE(id, std::this_thread::get_id());
}

TEST(EncodeThreadTest, FramesThatLiveUntilTheNextSubmitAreConvertedOnAThreadOfTheirOwn) {
  // The video path: the renderer reads frames back into two buffers in turn, so frame k is
  // converted while frame k + 1 is drawn; once submit(k + 1) returns, frame k's buffer is reused.
  StagingSink sink;
  sink.begin({4, 3, 10});
  {
    EncodeThread encoder(sink, 4, 3, 1, 3, FrameLifetime::kUntilNextSubmit);
    std::vector<std::uint8_t> buffers[2];
    for (int k = 0; k < 40; ++k) {
      encoder.submit(numberedFrame(k, k % 2 == 1, buffers[k % 2]));
      // Frame k - 1 must be staged by now: scribble over it, as the next readback would.
      std::fill(buffers[(k + 1) % 2].begin(), buffers[(k + 1) % 2].end(), std::uint8_t{0xEE});
    }
    encoder.finish();
    EXPECT_EQ(encoder.framesWritten(), 40);
  }
  expectAllStagedAndWrittenInOrder(sink, 40);
  ASSERT_EQ(sink.stage_threads.size(), 40u);
  for (const auto id : sink.stage_threads) {
    EXPECT_NE(id, std::this_thread::get_id()) << "converted on the drawing thread";
    EXPECT_EQ(id, sink.stage_threads.front()) << "one converting thread, in frame order";
  }
  for (const auto id : sink.write_threads) EXPECT_NE(id, sink.stage_threads.front());
}

TEST(EncodeThreadTest, AConversionErrorReachesTheRenderingThread) {
  StagingSink sink;
  sink.fail_stage_at = 3;
  sink.begin({4, 3, 10});
  std::vector<std::uint8_t> buffers[2];
  EXPECT_THROW(
      {
        EncodeThread encoder(sink, 4, 3, 1, 3, FrameLifetime::kUntilNextSubmit);
        for (int k = 0; k < 100; ++k) encoder.submit(numberedFrame(k, false, buffers[k % 2]));
        encoder.finish();
      },
      OutputError);
  EXPECT_FALSE(sink.finished);
  EXPECT_LE(sink.written.size(), 3u);
}

TEST(EncodeThreadTest, AnAbandonedRunStopsTheConvertingThread) {
  StagingSink sink;
  sink.begin({4, 3, 10});
  std::vector<std::uint8_t> buffers[2];
  {
    EncodeThread encoder(sink, 4, 3, 1, 3, FrameLifetime::kUntilNextSubmit);
    for (int k = 0; k < 5; ++k) encoder.submit(numberedFrame(k, false, buffers[k % 2]));
  }  // as when a signal or an error unwinds the render loop
  EXPECT_FALSE(sink.finished);
  EXPECT_LE(sink.written.size(), 5u);
}

// Staged frames hold an RGBA copy of their frame; stage() copies only the rectangles it is given,
// as the video sinks convert only those. Records every frame written, how many pixels were
// staged, and whether a stage() call staged a pixel twice.
class RectStagingSink : public FrameSink {
 public:
  struct Staged : StagedFrame {
    std::vector<std::uint8_t> pixels;  // top-down, tightly packed
  };
  void begin(const FrameFormat&) override {}
  void write(const core::ImageView&) override { ADD_FAILURE() << "a frame not staged"; }
  void finish() override {}
  std::unique_ptr<StagedFrame> newStagedFrame() override { return std::make_unique<Staged>(); }
  void stage(const core::ImageView& frame, StagedFrame& staged,
             const std::vector<core::ImageRect>* rects) override {
    auto& pixels = static_cast<Staged&>(staged).pixels;
    pixels.resize(4u * frame.width * frame.height);
    const std::vector<core::ImageRect> all{{0, 0, frame.width, frame.height}};
    std::vector<int> times(static_cast<std::size_t>(frame.width * frame.height), 0);
    for (const core::ImageRect& r : rects != nullptr ? *rects : all) {
      for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
          std::copy_n(frame.pixel(x, y), 4, pixels.begin() + 4 * (y * frame.width + x));
          if (++times[static_cast<std::size_t>(y * frame.width + x)] == 2) ++pixels_staged_twice;
          ++pixels_staged;
        }
      }
    }
  }
  void writeStaged(StagedFrame& staged) override {
    written.push_back(static_cast<Staged&>(staged).pixels);
  }
  std::vector<std::vector<std::uint8_t>> written;
  int pixels_staged = 0;
  int pixels_staged_twice = 0;
};

// Each frame differs from the one before in a few random rectangles, given with it (every few
// frames anywhere, given as nullptr). Each staged frame is reused every third frame, so it must be
// staged again in the rectangles changed over the frames since it was last: every frame written
// must be the frame submitted, while fewer pixels than all are staged, each at most once a frame.
void expectChangedRectanglesStagedWhole(FrameLifetime lifetime,
                                        EncodeOn on = EncodeOn::kOwnThreads) {
  const int width = 16, height = 12, count = 40;
  RectStagingSink sink;
  sink.begin({width, height, 10});
  std::mt19937 random(19);
  const auto below = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
  std::vector<std::uint8_t> current(4 * width * height, 0);
  std::vector<std::vector<std::uint8_t>> submitted;
  {
    EncodeThread encoder(sink, width, height, 1, 3, lifetime, on);
    std::vector<std::uint8_t> buffers[2];
    for (int k = 0; k < count; ++k) {
      std::vector<core::ImageRect> changed;
      const bool whole = k % 13 == 5;
      if (whole) changed.push_back({0, 0, width, height});
      for (int n = below(3); n > 0; --n) {
        const int x0 = below(width), y0 = below(height);
        changed.push_back(
            {x0, y0, std::min(width, x0 + 1 + below(6)), std::min(height, y0 + 1 + below(4))});
      }
      for (const core::ImageRect& r : changed) {
        for (int y = r.y0; y < r.y1; ++y) {
          for (int b = 4 * r.x0; b < 4 * r.x1; ++b) {
            current[static_cast<std::size_t>(4 * width * y + b)] =
                static_cast<std::uint8_t>(random());
          }
        }
      }
      submitted.push_back(current);
      std::vector<std::uint8_t>& buffer = buffers[k % 2];
      buffer = current;
      encoder.submit({buffer.data(), width, height, 4 * width}, whole ? nullptr : &changed);
      // The frame before must be staged by now: scribble over it, as the next readback would.
      std::fill(buffers[(k + 1) % 2].begin(), buffers[(k + 1) % 2].end(), std::uint8_t{0xEE});
    }
    encoder.finish();
  }
  ASSERT_EQ(sink.written.size(), submitted.size());
  for (int k = 0; k < count; ++k) EXPECT_EQ(sink.written[k], submitted[k]) << "frame " << k;
  EXPECT_LT(sink.pixels_staged, count * width * height) << "every pixel staged, changes unused";
  EXPECT_EQ(sink.pixels_staged_twice, 0);
}

TEST(EncodeThreadTest, AStagedFrameIsStagedAgainWhereTheFramesChangedSinceItsLast) {
  expectChangedRectanglesStagedWhole(FrameLifetime::kUntilSubmitReturns);
  expectChangedRectanglesStagedWhole(FrameLifetime::kUntilNextSubmit);
  // One staged frame, reused every frame: staged again where the last frame changed.
  expectChangedRectanglesStagedWhole(FrameLifetime::kUntilNextSubmit, EncodeOn::kCallingThread);
}

// A batch worker whose share is one core (app/batch_threads.hpp): no thread of the encoder's own.
TEST(EncodeThreadTest, OnTheCallingThreadEachFrameIsStagedAndWrittenBeforeSubmitReturns) {
  StagingSink sink;
  sink.begin({4, 3, 10});
  {
    EncodeThread encoder(sink, 4, 3, 1, 3, FrameLifetime::kUntilNextSubmit,
                         EncodeOn::kCallingThread);
    EXPECT_EQ(sink.staged_frames_made, 1) << "nothing waits, so one staged frame is enough";
    std::vector<std::uint8_t> buffers[2];
    for (int k = 0; k < 40; ++k) {
      encoder.submit(numberedFrame(k, k % 2 == 1, buffers[k % 2]));
      EXPECT_EQ(sink.written.size(), static_cast<std::size_t>(k + 1)) << "frame " << k;
      EXPECT_EQ(encoder.framesWritten(), k + 1);
      // Written already: scribbling over the caller's buffer at once cannot reach the sink.
      std::fill(buffers[k % 2].begin(), buffers[k % 2].end(), std::uint8_t{0xEE});
    }
    encoder.finish();
  }
  expectAllStagedAndWrittenInOrder(sink, 40);
  for (const auto id : sink.stage_threads) EXPECT_EQ(id, std::this_thread::get_id());
  for (const auto id : sink.write_threads) EXPECT_EQ(id, std::this_thread::get_id());
}

TEST(EncodeThreadTest, OnTheCallingThreadUnstagedFramesGoStraightToTheSinkUpright) {
  MemorySink sink;
  sink.begin({4, 3, 10});
  {
    EncodeThread encoder(sink, 4, 3, 2, 3, FrameLifetime::kUntilSubmitReturns,
                         EncodeOn::kCallingThread);
    std::vector<std::uint8_t> storage;
    for (int k = 0; k < 20; ++k) {
      encoder.submit(numberedFrame(k, k % 2 == 1, storage));
      EXPECT_EQ(sink.frames().size(), static_cast<std::size_t>(k + 1)) << "frame " << k;
    }
    encoder.finish();
  }
  ASSERT_TRUE(sink.finished());
  ASSERT_EQ(sink.frames().size(), 20u);
  for (int k = 0; k < 20; ++k) {
    EXPECT_EQ(sink.frames()[k].pixel(1, 0)[0], k);
    EXPECT_EQ(sink.frames()[k].pixel(1, 2)[1], 2) << "frame " << k << " upside down";
  }
}

TEST(EncodeThreadTest, OnTheCallingThreadASinkErrorComesOutOfSubmit) {
  FailingSink sink;  // throws on its third frame
  std::vector<std::uint8_t> storage;
  EncodeThread encoder(sink, 4, 3, 2, 3, FrameLifetime::kUntilSubmitReturns,
                       EncodeOn::kCallingThread);
  encoder.submit(numberedFrame(0, false, storage));
  encoder.submit(numberedFrame(1, false, storage));
  EXPECT_THROW(encoder.submit(numberedFrame(2, false, storage)), OutputError);
  EXPECT_FALSE(sink.finished_);
}

TEST(ProgressTest, DescribesFramesElapsedAndRemaining) {
  EXPECT_EQ(core::Progress::describe(120, 240, 1.2),
            "120/240 frames (50%), 1.2 s elapsed, about 1.2 s left");
  EXPECT_EQ(core::Progress::describe(240, 240, 12.0), "240/240 frames (100%), 12 s elapsed");
  std::ostringstream quiet;
  core::Progress silent(quiet, core::ProgressStyle::kSilent, 10, "rendering");
  silent.update(5);
  silent.finish();
  EXPECT_TRUE(quiet.str().empty());
  std::ostringstream bar;
  core::Progress drawn(bar, core::ProgressStyle::kBar, 10, "rendering");
  drawn.update(10);
  drawn.finish();
  EXPECT_EQ(bar.str().rfind("\rrendering [########################] 10/10 frames (100%)", 0), 0u)
      << bar.str();
  EXPECT_EQ(core::chooseProgressStyle(bar, false), core::ProgressStyle::kLines);
  EXPECT_EQ(core::chooseProgressStyle(bar, true), core::ProgressStyle::kSilent);
}

}  // namespace
}  // namespace collide::output
