// Issue 5 through the real binary: sound, captions, metadata, WebM alpha, GIF defaults, alt text,
// signals and unwritable paths. Every file is read back.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>

#include "binary_run_test.hpp"
#include "output/media_probe.hpp"
#include "scratch.hpp"

extern char** environ;

namespace collide {
namespace {
namespace fs = std::filesystem;

// The worked example: carts meet when the 3.5 m gap between their faces closes at 3 m/s.
constexpr double kCollisionS = 3.5 / 3.0;

class OutputsGLTest : public test::BinaryRunTest {
 protected:
  OutputsGLTest() : BinaryRunTest("collide_outputs_test_") {}
  void SetUp() override {
    BinaryRunTest::SetUp();
    fs::create_directories(dir_ / "out");
  }
  std::string out(const std::string& name) const { return (dir_ / "out" / name).string(); }
  std::string stderrText() const { return test::readFileBytes(dir_ / "stderr.txt"); }
  std::vector<std::string> outEntries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  // Starts a long render, waits until its temporary file exists, sends `signal_number`; returns
  // the exit status.
  int interruptedRender(int signal_number) {
    const std::string target = out("long.mp4");
    std::vector<std::string> args = {COLLIDE_BINARY, "render", "worked-example", "-o",    target,
                                     "--duration",   "600",    "--size",         "160x90"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string out_log = (dir_ / "stdout.txt").string();
    posix_spawn_file_actions_addopen(&actions, 1, out_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    const std::string err = (dir_ / "stderr.txt").string();
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, COLLIDE_BINARY, &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    bool started = false;
    while (!started && std::chrono::steady_clock::now() < deadline) {
      for (const std::string& name : outEntries()) started |= name.rfind(".long.tmp-", 0) == 0;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_TRUE(started) << "the render never created its temporary file";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // well inside the frame loop
    kill(pid, signal_number);
    // A render that ignored the signal would run for many minutes: give it 60 s, then kill it
    // and fail rather than hang the suite.
    int status = 0;
    const auto exit_deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (waitpid(pid, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > exit_deadline) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, WNOHANG);  // check-tests: bounded by SIGKILL just sent
        ADD_FAILURE() << "the render was still running 60 s after the signal";
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1000 - WTERMSIG(status);
  }
};

TEST_F(OutputsGLTest, Mp4WithSoundCaptionsAndMetadata) {
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(out("lesson.mp4")) +
                    " --size 160x90 --fps 30 --duration 2 --sound --captions --srt "
                    "--embed-captions"),
            0)
      << stderrText();
  EXPECT_EQ(outEntries(), (std::vector<std::string>{"lesson.mp4", "lesson.srt", "lesson.vtt"}));
  output::test::MediaFacts facts = output::test::probeMedia(out("lesson.mp4"));
  EXPECT_EQ(facts.video_frames, 60);
  EXPECT_EQ(facts.metadata.count("title") ? facts.metadata.at("title") : "",
            "Inelastic collision, e = 0.5");
  EXPECT_NE(facts.metadata["comment"].find("collide 0.1.0 "), std::string::npos);
  EXPECT_NE(facts.metadata["comment"].find("worked-example"), std::string::npos);
  EXPECT_NE(facts.metadata["description"].find("cart 1: 1 kg"), std::string::npos)
      << facts.metadata["description"];

  // One click, at the collision, to the millisecond after AAC coding.
  const output::test::StreamFacts* audio = output::test::findStream(facts, "audio");
  ASSERT_NE(audio, nullptr);
  EXPECT_EQ(audio->codec, "aac");
  std::vector<double> onsets;
  double last_loud = -1.0;
  for (std::size_t n = 0; n < facts.audio.size(); ++n) {
    const double t = static_cast<double>(n) / facts.audio_rate_hz;
    if (std::fabs(facts.audio[n]) > 0.2f) {
      if (t - last_loud > 0.05) onsets.push_back(t);
      last_loud = t;
    }
  }
  ASSERT_EQ(onsets.size(), 1u);
  EXPECT_NEAR(onsets[0], kCollisionS, 0.002);

  // The embedded narration: the start, then the collision; the video ends 0.8 s later, too soon
  // for a cue of its own, so the end's words join the collision's cue.
  const output::test::StreamFacts* text = output::test::findStream(facts, "subtitle");
  ASSERT_NE(text, nullptr);
  EXPECT_EQ(text->codec, "mov_text");
  ASSERT_EQ(facts.cues.size(), 2u);
  EXPECT_NEAR(facts.cues[1].start_s, kCollisionS, 0.0006);
  EXPECT_NEAR(facts.cues[1].end_s, 2.0, 0.0006);
  EXPECT_NE(facts.cues[1].text.find("End, t = 2.000 s: 1 collision."), std::string::npos)
      << facts.cues[1].text;

  // The WebVTT file: same cue times.
  const std::string vtt = test::readFileBytes(out("lesson.vtt"));
  EXPECT_EQ(vtt.rfind("WEBVTT - Inelastic collision, e = 0.5\nKind: captions\nLanguage: en\n\n1\n"
                      "00:00:00.000 --> ",
                      0),
            0u)
      << vtt;
  EXPECT_NE(vtt.find("\n2\n00:00:01.167 --> "), std::string::npos) << vtt;
  EXPECT_NE(vtt.find("cart 1 hits cart 2 at a closing speed of 3.00 m/s (e = 0.5)"),
            std::string::npos);
  const std::string srt = test::readFileBytes(out("lesson.srt"));
  EXPECT_NE(srt.find("\n\n2\n00:00:01,167 --> "), std::string::npos) << srt;
}

TEST_F(OutputsGLTest, TransparentWebmHasAlpha) {
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(out("overlay.webm")) +
                    " --size 160x90 --fps 10 --duration 1 --transparent"),
            0)
      << stderrText();
  output::test::MediaFacts facts = output::test::probeMedia(out("overlay.webm"), {5}, "libvpx-vp9");
  ASSERT_EQ(facts.streams.size(), 1u);
  EXPECT_EQ(facts.streams[0].codec, "vp9");
  EXPECT_EQ(facts.streams[0].metadata["alpha_mode"], "1");
  EXPECT_EQ(facts.video_frames, 10);
  EXPECT_NEAR(facts.duration_s, 1.0, 1e-3);
  ASSERT_EQ(facts.kept.size(), 1u);
  EXPECT_LE(facts.kept[0].pixel(0, 0)[3], 8);  // the background corner is see-through
}

TEST_F(OutputsGLTest, GifDefaultsTo25FpsAndSlideSize) {
  ASSERT_EQ(collide("render worked-example -o " + test::shellQuoted(out("slide.gif")) +
                    " --duration 0.4"),
            0)
      << stderrText();
  const output::test::MediaFacts facts = output::test::probeMedia(out("slide.gif"));
  ASSERT_EQ(facts.streams.size(), 1u);
  EXPECT_EQ(facts.streams[0].codec, "gif");
  EXPECT_EQ(facts.streams[0].width, 640);
  EXPECT_EQ(facts.streams[0].height, 360);
  EXPECT_EQ(facts.video_frames, 10);
  EXPECT_NEAR(facts.duration_s, 0.4, 0.011);
}

TEST_F(OutputsGLTest, StillHasAltTextBesideIt) {
  ASSERT_EQ(collide("still worked-example --at 2.5 --size 160x90 -o " +
                    test::shellQuoted(out("after.png"))),
            0);
  EXPECT_EQ(outEntries(), (std::vector<std::string>{"after.alt.txt", "after.png"}));
  const std::string alt = test::readFileBytes(out("after.alt.txt"));
  EXPECT_NE(alt.find("Still image at t = 2.500 s"), std::string::npos) << alt;
  EXPECT_NE(alt.find("1 collision has happened so far."), std::string::npos) << alt;
  // The air track's bodies are gliders, in the picture and in its words.
  ASSERT_EQ(
      collide("still air-track --at 0 --size 160x90 -o " + test::shellQuoted(out("track.png"))), 0);
  const std::string track = test::readFileBytes(out("track.alt.txt"));
  EXPECT_NE(track.find("2 gliders ride on an air track with 2 walls."), std::string::npos) << track;
}

TEST_F(OutputsGLTest, SigintStopsCleanlyAndLeavesNothing) {
  EXPECT_EQ(interruptedRender(SIGINT), 130) << stderrText();
  EXPECT_TRUE(outEntries().empty());
  EXPECT_NE(stderrText().find("stopped by SIGINT"), std::string::npos) << stderrText();
}

TEST_F(OutputsGLTest, SigtermStopsCleanlyAndLeavesNothing) {
  EXPECT_EQ(interruptedRender(SIGTERM), 143) << stderrText();
  EXPECT_TRUE(outEntries().empty());
}

TEST_F(OutputsGLTest, UnwritablePathIsARuntimeErrorAndLeavesNothing) {
  // /proc exists but takes no new files, even for root.
  EXPECT_EQ(collide("render worked-example -o /proc/collide-test.mp4 --size 160x90 --duration "
                    "0.2"),
            1);
  const std::string err = stderrText();
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("'/proc/collide-test.mp4'"), std::string::npos) << err;
  EXPECT_EQ(collide("data worked-example --csv /proc/collide-test.csv"), 1);
  EXPECT_FALSE(fs::exists("/proc/collide-test.mp4"));
}

TEST_F(OutputsGLTest, OptionsThatDoNotFitTheFormatAreBadInput) {
  EXPECT_EQ(
      collide("render worked-example -o " + test::shellQuoted(out("a.mp4")) + " --transparent"), 2);
  EXPECT_NE(stderrText().find("--transparent"), std::string::npos);
  EXPECT_EQ(collide("render worked-example -o " + test::shellQuoted(out("a.gif")) + " --sound"), 2);
  EXPECT_EQ(
      collide("render worked-example -o " + test::shellQuoted(out("a.mp4")) + " --quality 70"), 2);
  EXPECT_EQ(
      collide("render worked-example -o " + test::shellQuoted(out("a.mp4")) + " --preset warp"), 2);
  EXPECT_TRUE(outEntries().empty());
}

}  // namespace
}  // namespace collide
