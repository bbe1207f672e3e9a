// The real `collide` binary run as a user would, and its files read back.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "binary_run_test.hpp"
#include "golden.hpp"
#include "png_io.hpp"
#include "scratch.hpp"
#include "video_probe.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

class CliRenderGLTest : public test::BinaryRunTest {
 protected:
  CliRenderGLTest() : BinaryRunTest("collide_render_test_") {}
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(CliRenderGLTest, Mp4HasExactlyFpsTimesDurationFramesAndMoovFirst) {
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(path("x.mp4")) +
                    " --duration 4 --fps 30"),
            0);
  const test::VideoProbe probe = test::probeVideo(path("x.mp4"));
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.pixel_format, "yuv420p");
  EXPECT_EQ(probe.width, 1280);
  EXPECT_EQ(probe.height, 720);
  EXPECT_EQ(probe.decoded_frames, 120);
  EXPECT_NEAR(probe.stream_duration_s, 4.0, 1e-9);
  EXPECT_NEAR(probe.frame_rate, 30.0, 1e-9);
  EXPECT_TRUE(probe.moov_before_mdat);
  // Only the video at the target: no temporary files left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);  // + 2 logs
}

TEST_F(CliRenderGLTest, DecodedVideoFrameMatchesTheStillAtTheSameTime) {
  // Frame 50 at 20 fps shows t = 2.5 s, the time of the reviewed golden still.
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(path("v.mp4")) +
                    " --size 480x270 --fps 20"),
            0);
  const core::Image decoded = test::decodeVideoFrame(path("v.mp4"), 50);
  // 4:2:0 chroma subsampling and x264 quantisation blur edges: a looser per-channel tolerance,
  // and thin glyph strokes lose more than that. Measured (Mesa 22.3, x264 164): 274 px beyond
  // 24/255 and 57 beyond 48/255 of 129600; the caps are about twice that.
  test::GoldenOptions options;
  options.channel_tolerance = 24;
  options.max_pixels_beyond = 600;
  options.allowances.push_back({0, 0, 480, 270, 120, "x264 4:2:0 blur of edges and glyphs"});
  EXPECT_TRUE(test::compareWithGolden(decoded.view(), "app/worked_example_t2_500.png", options));
}

TEST_F(CliRenderGLTest, PngFramesGoIntoADirectory) {
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(path("frames/")) +
                    " --size 160x90 --fps 10 --duration 0.5"),
            0);
  for (int k = 0; k < 5; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    const core::Image frame = test::readPng(path(std::string("frames/") + name));
    EXPECT_EQ(frame.width(), 160);
    EXPECT_EQ(frame.height(), 90);
  }
  EXPECT_FALSE(fs::exists(path("frames/frame_00005.png")));
}

TEST_F(CliRenderGLTest, StillIsThePngGoldenAtThatTime) {
  ASSERT_EQ(collide("still worked-example --at 2.5 --size 480x270 -o " +
                    test::shellQuoted(path("s.png"))),
            0);
  EXPECT_TRUE(test::compareWithGolden(test::readPng(path("s.png")).view(),
                                      "app/worked_example_t2_500.png"));
}

TEST_F(CliRenderGLTest, OddVideoSizeIsRoundedToEvenWithANote) {
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(path("odd.mp4")) +
                    " --size 161x91 --fps 10 --duration 0.3"),
            0);
  const test::VideoProbe probe = test::probeVideo(path("odd.mp4"));
  EXPECT_EQ(probe.width, 160);
  EXPECT_EQ(probe.height, 90);
  EXPECT_EQ(probe.decoded_frames, 3);
}

TEST_F(CliRenderGLTest, ExitCodesFromTheProcess) {
  EXPECT_EQ(collide("--help"), 0);
  EXPECT_EQ(collide(""), 2);
  EXPECT_EQ(collide("render no-such-scene -o " + test::shellQuoted(path("a.mp4"))), 2);
  EXPECT_FALSE(fs::exists(path("a.mp4")));
}

}  // namespace
}  // namespace collide
