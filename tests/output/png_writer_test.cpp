#include "output/png_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "output/frame_sink.hpp"
#include "output/test_support.hpp"
#include "png_io.hpp"
#include "scratch.hpp"

namespace collide::output {
namespace {

using test::ScratchDirectory;

TEST(PngWriterTest, RoundTripKeepsSizeAndEveryPixel) {
  ScratchDirectory dir;
  const core::Image source = test::makeFrame(97, 31, 5);  // odd sizes: no row padding assumptions
  writePng(dir / "frame.png", source.view());
  const core::Image back = test::readPng(dir / "frame.png");
  ASSERT_EQ(back.width(), 97);
  ASSERT_EQ(back.height(), 31);
  EXPECT_EQ(test::maxChannelDifference(source, back), 0);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"frame.png"});  // no temporary left
}

TEST(PngWriterTest, RecordsThePrintingResolution) {
  ScratchDirectory dir;
  const core::Image source = test::makeFrame(16, 9, 0);
  writePng(dir / "print.png", source.view(), {}, 300.0);
  writePng(dir / "screen.png", source.view());
  // 300 dots per inch = 300 / 0.0254 m = 11811.02 pixels per metre, a whole number in the chunk.
  const auto [x, y] = collide::test::readPngPixelsPerMetre((dir / "print.png").string());
  EXPECT_EQ(x, 11811u);
  EXPECT_EQ(y, 11811u);
  EXPECT_NEAR(x * 0.0254, 300.0, 0.5 * 0.0254);
  EXPECT_EQ(collide::test::readPngPixelsPerMetre((dir / "screen.png").string()),
            (std::pair<unsigned, unsigned>{0, 0}));
}

// A large image deflated in parts on threads (output/png_deflate.hpp) reads back with every pixel
// (libpng checks the joined stream's Adler-32 as it reads), its text and resolution chunks kept.
TEST(PngWriterTest, DeflatedOnThreadsKeepsEveryPixelAndChunk) {
  ScratchDirectory dir;
  // Three parts of at least 256 KiB each need 3 * 262144 / (4 * 640) = 307.2 rows: 400.
  const core::Image source = test::makeFrame(640, 400, 7);
  std::vector<std::uint8_t> storage;
  const core::ImageView flipped = test::bottomUpView(source, storage);
  for (const core::ImageView& view : {source.view(), flipped}) {
    writePng(dir / "parts.png", view, {}, 300.0, 3);
    EXPECT_EQ(test::maxChannelDifference(source, test::readPng(dir / "parts.png")), 0);
    EXPECT_EQ(collide::test::readPngPixelsPerMetre((dir / "parts.png").string()),
              (std::pair<unsigned, unsigned>{11811, 11811}));
  }
}

TEST(PngWriterTest, KeepsAlpha) {
  ScratchDirectory dir;
  core::Image source = test::makeFrame(8, 8, 0);
  source.pixel(3, 4)[3] = 17;
  writePng(dir / "alpha.png", source.view());
  EXPECT_EQ(test::readPng(dir / "alpha.png").pixel(3, 4)[3], 17);
}

TEST(PngWriterTest, BottomUpViewIsWrittenUpright) {
  ScratchDirectory dir;
  const core::Image source = test::makeFrame(64, 36, 2);
  std::vector<std::uint8_t> storage;
  const core::ImageView flipped = test::bottomUpView(source, storage);
  ASSERT_LT(flipped.row_stride, 0);
  writePng(dir / "upright.png", flipped);
  EXPECT_EQ(test::maxChannelDifference(source, test::readPng(dir / "upright.png")), 0);
}

TEST(PngWriterTest, ReplacesAnExistingFile) {
  ScratchDirectory dir;
  { std::ofstream(dir / "old.png") << "not a png"; }
  const core::Image source = test::makeFrame(16, 16, 1);
  writePng(dir / "old.png", source.view());
  EXPECT_EQ(test::maxChannelDifference(source, test::readPng(dir / "old.png")), 0);
}

TEST(PngWriterTest, MissingDirectoryThrowsNamingThePathAndLeavesNoFile) {
  ScratchDirectory dir;
  const auto target = dir / "missing" / "frame.png";
  const core::Image source = test::makeFrame(8, 8, 0);
  try {
    writePng(target, source.view());
    FAIL() << "expected OutputError";
  } catch (const OutputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(target.string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(PngWriterTest, ParentIsAFileThrows) {
  ScratchDirectory dir;
  { std::ofstream(dir / "plain") << "x"; }
  const core::Image source = test::makeFrame(8, 8, 0);
  EXPECT_THROW(writePng(dir / "plain" / "frame.png", source.view()), OutputError);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plain"});
}

TEST(PngWriterTest, FullDiskThrowsWithTheReason) {
  // A full disk: a device node like /dev/full (every write fails with ENOSPC), made in the test's
  // own directory rather than writing to the machine's /dev.
  ScratchDirectory dir;
  std::string why_not;
  const auto full = collide::test::makeFullDevice(dir.path(), "full", why_not);
  if (!full) GTEST_SKIP() << why_not;
  // Large enough that the PNG overflows stdio's buffer before fclose.
  const core::Image source = test::makeFrame(256, 256, 0);
  try {
    writePngDirect(*full, source.view(), "video/frame.png");
    FAIL() << "expected OutputError";
  } catch (const OutputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("video/frame.png"), std::string::npos) << message;
    EXPECT_NE(message.find("No space left on device"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace collide::output
