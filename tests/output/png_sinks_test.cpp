#include "output/png_sinks.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
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

// The frames directory follows the rules of every output: a frame name that is a link is
// followed (its file replaced, the link stays a link), a FIFO or character device there is
// written straight through and keeps its type, and nothing there is ever replaced by a file.
TEST(PngSequenceSinkTest, ALinkedFrameReplacesItsFileAndStaysALink) {
  ScratchDirectory dir;
  std::filesystem::create_directory(dir / "frames");
  std::filesystem::create_directory(dir / "elsewhere");
  { std::ofstream(dir / "elsewhere" / "kept.png") << "an earlier frame"; }
  std::filesystem::create_symlink("../elsewhere/kept.png", dir / "frames" / "frame_00001.png");
  std::vector<core::Image> frames;
  PngSequenceSink sink(dir / "frames");
  sink.begin(kSmall);
  for (int i = 0; i < 2; ++i) {
    frames.push_back(test::makeFrame(kSmall.width_px, kSmall.height_px, i));
    sink.write(frames.back().view());
  }
  sink.finish();
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "frames" / "frame_00001.png"));
  EXPECT_EQ(test::maxChannelDifference(frames[1], test::readPng(dir / "elsewhere" / "kept.png")),
            0);
  EXPECT_EQ(
      test::maxChannelDifference(frames[0], test::readPng(dir / "frames" / "frame_00000.png")), 0);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"elsewhere", "frames"}));
}

TEST(PngSequenceSinkTest, AFifoFrameIsWrittenThroughAndStaysAFifo) {
  ScratchDirectory dir;
  const std::filesystem::path fifo = dir / "frame_00000.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  // A reader first (non-blocking, so the test cannot hang): the sink's open then succeeds, and a
  // small frame fits in the pipe's buffer.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0) << std::strerror(errno);
  const core::Image frame = test::makeFrame(kSmall.width_px, kSmall.height_px, 4);
  PngSequenceSink sink(dir.path());
  sink.begin(kSmall);
  sink.write(frame.view());
  sink.finish();
  std::string bytes(1 << 16, '\0');
  const ssize_t got = ::read(reader, bytes.data(), bytes.size());
  ::close(reader);
  ASSERT_GT(got, 8);
  EXPECT_EQ(bytes.substr(0, 8), "\x89PNG\r\n\x1a\n");
  struct stat info {};
  ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame_00000.png"});
}

TEST(PngSequenceSinkTest, ADeviceFrameKeepsItsTypeAndNumbers) {
  ScratchDirectory dir;
  const std::filesystem::path node = dir / "frame_00000.png";
  // The null device's numbers (1, 3), made here: never the machine's own /dev node.
  if (::mknod(node.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) {
    GTEST_SKIP() << "mknod is not allowed here (" << std::strerror(errno) << ")";
  }
  PngSequenceSink sink(dir.path());
  sink.begin(kSmall);
  sink.write(test::makeFrame(kSmall.width_px, kSmall.height_px, 0).view());
  sink.write(test::makeFrame(kSmall.width_px, kSmall.height_px, 1).view());
  sink.finish();
  struct stat info {};
  ASSERT_EQ(::lstat(node.c_str(), &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  EXPECT_EQ(info.st_rdev, ::makedev(1, 3));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"frame_00000.png", "frame_00001.png"}));
}

TEST(PngSequenceSinkTest, AFrameNameThatIsADirectoryOrALinkLoopIsRefusedBeforeAnyFrame) {
  const std::pair<const char*, const char*> kinds[] = {{"frame_00002.png", "': is a directory;"},
                                                       {"frame_00007.png", "': is a link loop;"}};
  for (const auto& [name, what] : kinds) {
    SCOPED_TRACE(name);
    ScratchDirectory dir;
    if (std::string(what).find("directory") != std::string::npos) {
      std::filesystem::create_directory(dir / name);
    } else {
      std::filesystem::create_symlink(name, dir / name);  // a link to itself
    }
    PngSequenceSink sink(dir.path());
    try {
      sink.begin(kSmall);
      FAIL() << "expected core::InputError";
    } catch (const core::InputError& error) {
      std::string expected = "'";
      expected.append((dir / name).string()).append(what);
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
  }
}

}  // namespace
}  // namespace collide::output
