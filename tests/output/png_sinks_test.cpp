#include "output/png_sinks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "output/test_support.hpp"

namespace collide::output {
namespace {

using test::ScratchDirectory;

constexpr FrameFormat kSmall{48, 32, 30};

TEST(PngStillSinkTest, WritesOneFrameAtFinish) {
  ScratchDirectory dir;
  const core::Image frame = test::makeFrame(kSmall.width_px, kSmall.height_px, 3);
  PngStillSink sink(dir / "still.png");
  sink.begin(kSmall);
  sink.write(frame.view());
  // Written, but still under its temporary name until finish().
  EXPECT_FALSE(std::filesystem::exists(dir / "still.png"));
  sink.finish();
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"still.png"});
  EXPECT_EQ(test::maxChannelDifference(frame, test::readPng(dir / "still.png")), 0);
}

TEST(PngStillSinkTest, SecondFrameIsAnError) {
  ScratchDirectory dir;
  const core::Image frame = test::makeFrame(kSmall.width_px, kSmall.height_px, 0);
  PngStillSink sink(dir / "still.png");
  sink.begin(kSmall);
  sink.write(frame.view());
  EXPECT_THROW(sink.write(frame.view()), OutputError);
}

TEST(PngStillSinkTest, FinishWithoutFrameIsAnError) {
  ScratchDirectory dir;
  PngStillSink sink(dir / "still.png");
  sink.begin(kSmall);
  EXPECT_THROW(sink.finish(), OutputError);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngStillSinkTest, DestroyedWithoutFinishLeavesNothing) {
  ScratchDirectory dir;
  {
    const core::Image frame = test::makeFrame(kSmall.width_px, kSmall.height_px, 0);
    PngStillSink sink(dir / "still.png");
    sink.begin(kSmall);
    sink.write(frame.view());
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngStillSinkTest, UnwritablePathThrowsAndLeavesNothing) {
  ScratchDirectory dir;
  const core::Image frame = test::makeFrame(kSmall.width_px, kSmall.height_px, 0);
  PngStillSink sink(dir / "missing" / "still.png");
  sink.begin(kSmall);
  EXPECT_THROW(sink.write(frame.view()), OutputError);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngSequenceSinkTest, FrameFileNamesAreZeroPadded) {
  EXPECT_EQ(PngSequenceSink::frameFileName(0), "frame_00000.png");
  EXPECT_EQ(PngSequenceSink::frameFileName(42), "frame_00042.png");
  EXPECT_EQ(PngSequenceSink::frameFileName(123456), "frame_123456.png");
}

TEST(PngSequenceSinkTest, WritesNumberedFramesIntoANewDirectory) {
  ScratchDirectory dir;
  const auto frames_dir = dir / "frames";
  PngSequenceSink sink(frames_dir);
  sink.begin(kSmall);
  std::vector<core::Image> frames;
  for (int i = 0; i < 5; ++i) {
    frames.push_back(test::makeFrame(kSmall.width_px, kSmall.height_px, i));
    sink.write(frames.back().view());
  }
  sink.finish();
  EXPECT_EQ(sink.framesWritten(), 5);

  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(frames_dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png",
                                      "frame_00003.png", "frame_00004.png"}));
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(
        test::maxChannelDifference(frames[static_cast<std::size_t>(i)],
                                   test::readPng(frames_dir / PngSequenceSink::frameFileName(i))),
        0)
        << "frame " << i;
  }
}

TEST(PngSequenceSinkTest, BottomUpFramesAreWrittenUpright) {
  ScratchDirectory dir;
  const core::Image frame = test::makeFrame(kSmall.width_px, kSmall.height_px, 7);
  std::vector<std::uint8_t> storage;
  PngSequenceSink sink(dir.path());  // an existing directory
  sink.begin(kSmall);
  sink.write(test::bottomUpView(frame, storage));
  sink.finish();
  EXPECT_EQ(test::maxChannelDifference(frame, test::readPng(dir / "frame_00000.png")), 0);
}

TEST(PngSequenceSinkTest, DestroyedWithoutFinishLeavesNoFiles) {
  ScratchDirectory dir;
  { std::ofstream(dir / "keep.txt") << "not ours"; }
  {
    PngSequenceSink existing(dir.path());
    existing.begin(kSmall);
    for (int i = 0; i < 3; ++i) {
      existing.write(test::makeFrame(kSmall.width_px, kSmall.height_px, i).view());
    }
    PngSequenceSink created(dir / "new");
    created.begin(kSmall);
    created.write(test::makeFrame(kSmall.width_px, kSmall.height_px, 0).view());
  }
  // Frames and the directory the sink created are gone; what was there before stays.
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.txt"});
}

TEST(PngSequenceSinkTest, MissingParentDirectoryThrowsAndCreatesNothing) {
  ScratchDirectory dir;
  PngSequenceSink sink(dir / "missing" / "frames");
  try {
    sink.begin(kSmall);
    FAIL() << "expected OutputError";
  } catch (const OutputError& error) {
    EXPECT_NE(std::string(error.what()).find((dir / "missing" / "frames").string()),
              std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngSequenceSinkTest, DirectoryThatIsAFileThrows) {
  ScratchDirectory dir;
  { std::ofstream(dir / "frames") << "x"; }
  PngSequenceSink sink(dir / "frames");
  EXPECT_THROW(sink.begin(kSmall), OutputError);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frames"});
}

}  // namespace
}  // namespace collide::output
