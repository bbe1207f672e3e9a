// SPDX-License-Identifier: MIT
// Issue 38, item 4, through the real `collide` binary: outputs that failed late or not at all.
//   - Every output's path and every side file's (alt text, captions, LaTeX, Markdown, a batch's
//     manifest) is checked before any work: a directory in the way is exit 2 with nothing touched.
//   - Every write to stdout is checked: a full device, a closed stdout and a broken pipe with
//     SIGPIPE ignored are exit 1 with one line, for each command that writes there.
//   - Issue 45: an output that would replace an input of the run, or one named twice, is exit 2;
//     an output estimated past 10 GB is exit 2 naming the estimate and --force, at once.
// Everything in the test's own folder; the "full disk" is a device node made there.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "faults_fixture.hpp"
#include "progress_lines.hpp"

namespace collide::faults_test {
namespace {

// ---- side files checked before any work ---------------------------------------------------

struct SideFileCase {
  std::string name;
  std::vector<std::string> args;  // "@" stands for the output folder
  std::string main_output;        // a file there before the run, which must stay as it was
  std::string blocked;            // the side file, made a directory
};

void PrintTo(const SideFileCase& c, std::ostream* out) {
  *out << c.name;
}

const std::vector<std::string> kTiny = {"--size", "64x64"};

std::vector<SideFileCase> sideFileCases() {
  const auto with = [](std::vector<std::string> args, bool tiny = true) {
    if (tiny) args.insert(args.end(), kTiny.begin(), kTiny.end());
    return args;
  };
  return {
      {"StillAltText", with({"still", "worked-example", "-o", "@/a.png"}), "a.png", "a.alt.txt"},
      {"StillLatex", with({"still", "worked-example", "-o", "@/a.png", "--latex"}), "a.png",
       "a.tex"},
      {"StrobeMarkdown", with({"strobe", "worked-example", "-o", "@/s.png", "--markdown"}), "s.png",
       "s.md"},
      {"RenderCaptions",
       with({"render", "worked-example", "-o", "@/v.mp4", "--captions", "--duration", "0.2"}),
       "v.mp4", "v.vtt"},
      {"RenderSubRip",
       with({"render", "worked-example", "-o", "@/v.mp4", "--srt", "--duration", "0.2"}), "v.mp4",
       "v.srt"},
      {"DataSecondOutput",
       with({"data", "worked-example", "--json", "@/a.json", "--csv", "@/b.csv"}, false), "a.json",
       "b.csv"},
      {"BatchManifest",
       with({"batch", "worked-example", "bouncing-ball", "--formats", "json", "-o", "@"}, false),
       "worked-example.json", "manifest.json"},
      {"BatchAltText", with({"batch", "worked-example", "--formats", "png,json", "-o", "@"}),
       "worked-example.json", "worked-example.alt.txt"},
  };
}

class SideFileGLTest : public FaultsGLTest, public ::testing::WithParamInterface<SideFileCase> {};

TEST_P(SideFileGLTest, ADirectoryInTheWayFailsBeforeAnythingIsWritten) {
  const SideFileCase& c = GetParam();
  writeText(out_dir_() / c.main_output, "earlier");
  fs::create_directory(out_dir_() / c.blocked);
  const Snapshot before = snapshot();
  std::vector<std::string> args = c.args;
  for (std::string& arg : args) {
    if (arg[0] == '@') arg = out_dir_().string() + arg.substr(1);
  }
  const auto start = std::chrono::steady_clock::now();
  const ChildResult result = collide(args);
  expectCleanFailure(result, 2, {c.blocked, "is a directory"}, before);
  // Before any work: no simulation, no frame (a fraction of the shortest render).
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

INSTANTIATE_TEST_SUITE_P(EverySideFile, SideFileGLTest, ::testing::ValuesIn(sideFileCases()),
                         [](const auto& info) { return info.param.name; });

// A frame name in the folder that no frame may replace: found before the scene is simulated.
TEST_F(FaultsGLTest, AFrameNameThatIsADirectoryFailsBeforeAnythingIsDrawn) {
  const fs::path frames = out_dir_() / "frames";
  fs::create_directories(frames / "frame_00003.png");
  writeText(frames / "frame_00000.png", "earlier");
  const Snapshot before = snapshot();
  const ChildResult result =
      collide({"render", "worked-example", "--size", "64x64", "-o", frames.string() + "/"});
  expectCleanFailure(result, 2, {"frame_00003.png", "is a directory"}, before);
}

// ---- every write to stdout checked ----------------------------------------------------------

struct StdoutCase {
  std::string name;
  std::vector<std::string> args;
};

void PrintTo(const StdoutCase& c, std::ostream* out) {
  *out << c.name;
}

enum class Broken { kFullDevice, kClosed, kBrokenPipe };

void PrintTo(Broken broken, std::ostream* out) {
  *out << (broken == Broken::kFullDevice ? "a full device"
           : broken == Broken::kClosed   ? "a closed stdout"
                                         : "a broken pipe, SIGPIPE ignored");
}

class StdoutFaultGLTest : public FaultsGLTest,
                          public ::testing::WithParamInterface<std::tuple<StdoutCase, Broken>> {};

TEST_P(StdoutFaultGLTest, AFailedWriteIsExitOneWithOneLine) {
  const auto& [c, broken] = GetParam();
  ChildOptions options;
  std::string why;
  switch (broken) {
    case Broken::kFullDevice: {
      std::string why_not;
      const std::optional<fs::path> full = test::makeFullDevice(dir_, "full", why_not);
      if (!full) GTEST_SKIP() << why_not;
      options.stdout_to = test::ChildStdout::kFile;
      options.stdout_path = full->string();
      why = "No space left on device";
      break;
    }
    case Broken::kClosed:
      options.stdout_to = test::ChildStdout::kClosed;
      why = "Bad file descriptor";
      break;
    case Broken::kBrokenPipe:
      options.stdout_to = test::ChildStdout::kBrokenPipe;
      options.ignore_sigpipe = true;
      why = "Broken pipe";
      break;
  }
  const ChildResult result = collide(c.args, options);
  EXPECT_EQ(result.exit_code, 1) << test::describe(result) << ": " << result.err;
  // A slow run (a loaded machine) may report its progress before failing: not part of the error.
  const std::string error = test::withoutProgressLines(result.err);
  EXPECT_EQ(std::count(error.begin(), error.end(), '\n'), 1) << result.err;
  EXPECT_EQ(error.rfind("collide: cannot ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find(why), std::string::npos) << result.err;
  EXPECT_TRUE(fs::is_empty(out_dir_()));
}

INSTANTIATE_TEST_SUITE_P(
    EveryWriter, StdoutFaultGLTest,
    ::testing::Combine(
        ::testing::Values(
            StdoutCase{"DataJson", {"data", "worked-example", "--json", "-", "--events"}},
            StdoutCase{"DataCsv", {"data", "worked-example", "--csv", "-"}},
            StdoutCase{"StillPng", {"still", "worked-example", "--size", "64x64", "-o", "-"}},
            StdoutCase{"PresetsList", {"presets"}}),
        ::testing::Values(Broken::kFullDevice, Broken::kClosed, Broken::kBrokenPipe)),
    [](const auto& info) {
      const Broken broken = std::get<1>(info.param);
      return std::get<0>(info.param).name + (broken == Broken::kFullDevice ? "FullDevice"
                                             : broken == Broken::kClosed   ? "Closed"
                                                                           : "BrokenPipe");
    });

// ---- inputs and outputs of one run ----------------------------------------------------------

// Writes worked-example as a scene file in the output folder.
fs::path writeScene(const fs::path& path) {
  const ChildResult shown = test::runChild(COLLIDE_BINARY, {"presets", "show", "worked-example"});
  EXPECT_EQ(shown.exit_code, 0) << shown.err;
  writeText(path, shown.out);
  return path;
}

TEST_F(FaultsGLTest, AnOutputThatIsAnInputOfTheRunIsRefused) {
  const fs::path scene = writeScene(out_dir_() / "w.toml");
  fs::create_hard_link(scene, out_dir_() / "same.json");
  fs::create_symlink("w.toml", out_dir_() / "link.csv");
  const Snapshot before = snapshot();
  for (const std::string option : {"--json", "--csv"}) {
    for (const std::string output : {"w.toml", "same.json", "link.csv"}) {
      const ChildResult result =
          collide({"data", scene.string(), option, (out_dir_() / output).string()});
      expectCleanFailure(result, 2, {option, output, "which this run reads"}, before);
    }
  }
  // The video too: an MP4 written over the scene file it was made from.
  const ChildResult video = collide({"render", scene.string(), "--format", "mp4", "-o",
                                     (out_dir_() / "same.json").string(), "--size", "64x64"});
  expectCleanFailure(video, 2, {"-o", "which this run reads"}, before);
}

// The font a run draws with is one of its inputs too (a copy of the default one, in the folder).
TEST_F(FaultsGLTest, AnOutputThatIsTheRunsFontIsRefused) {
  const fs::path installed = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (!fs::exists(installed)) GTEST_SKIP() << installed << " is not installed";
  const fs::path font = out_dir_() / "font.ttf";
  fs::copy_file(installed, font);
  const Snapshot before = snapshot();
  const ChildResult result =
      collide({"render", "worked-example", "--font", font.string(), "--format", "mp4", "-o",
               font.string(), "--size", "64x64", "--duration", "0.2"});
  expectCleanFailure(result, 2, {"-o", "font.ttf", "which this run reads"}, before);
}

TEST_F(FaultsGLTest, TwoOutputsThatAreOneFileAreRefused) {
  writeText(out_dir_() / "a.json", "earlier");
  fs::create_hard_link(out_dir_() / "a.json", out_dir_() / "hard.csv");
  const Snapshot before = snapshot();
  const std::string a = (out_dir_() / "a.json").string();
  for (const std::string& second :
       {a, (out_dir_() / "." / "a.json").string(), (out_dir_() / "hard.csv").string()}) {
    const ChildResult result = collide({"data", "worked-example", "--json", a, "--csv", second});
    expectCleanFailure(result, 2, {"--csv", "the same file as --json"}, before);
  }
  // A new name twice (nothing there yet) is one file too.
  const std::string fresh = (out_dir_() / "new.json").string();
  expectCleanFailure(collide({"data", "worked-example", "--json", fresh, "--csv", fresh}), 2,
                     {"the same file as --json"}, before);
}

// ---- sizes known before the work -------------------------------------------------------------

struct HugeCase {
  std::string name;
  std::vector<std::string> args;  // "@" as above
  std::string estimate;           // the unit the estimate is given in
};

class HugeOutputGLTest : public FaultsGLTest, public ::testing::WithParamInterface<HugeCase> {};

TEST_P(HugeOutputGLTest, IsRefusedAtOnceNamingTheEstimateAndForce) {
  std::vector<std::string> args = GetParam().args;
  for (std::string& arg : args) {
    if (arg[0] == '@') arg = out_dir_().string() + arg.substr(1);
  }
  const Snapshot before = snapshot();
  const auto start = std::chrono::steady_clock::now();
  const ChildResult result = collide(args);
  expectCleanFailure(result, 2, {"would be about", GetParam().estimate, "--force"}, before);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << "not up front";
}

// 1000 disks for an hour at 0.5 ms: 7.2 million rows of 7005 columns, about a terabyte; an hour of
// 8K at 240 fps: 864,000 frames of 33 megapixels.
INSTANTIATE_TEST_SUITE_P(
    Requests, HugeOutputGLTest,
    ::testing::Values(HugeCase{"DataCsv",
                               {"data", "ideal-gas", "--set", "disks=1000", "--duration", "3600",
                                "--csv", "@/big.csv", "--dt", "0.0005"},
                               "TB"},
                      HugeCase{"RenderVideo",
                               {"render", "worked-example", "--size", "7680x4320", "--fps", "240",
                                "--duration", "3600", "-o", "@/big.mp4"},
                               "GB"},
                      HugeCase{"RenderFrames",
                               {"render", "worked-example", "--size", "3840x2160", "--duration",
                                "3600", "-o", "@/frames/"},
                               "GB"},
                      HugeCase{"BatchCsv",
                               {"batch", "ideal-gas", "--set", "disks=1000", "--duration", "3600",
                                "--formats", "csv", "--csv-step", "0.0005", "-o", "@"},
                               "TB"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace collide::faults_test
