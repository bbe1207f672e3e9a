// Outputs that are not regular files, through the real binary: a character device (the null
// device, made with mknod in the test's own directory), a FIFO with a reader, a symbolic link to a
// file, a link to the process's own stdout (/proc/self/fd/1) and "-", as the JSON, CSV, captions
// and MP4 outputs. Devices and FIFOs keep their type and numbers, links stay links, exit 0. No
// test here opens the machine's own /dev files for writing: as root, a regression would replace
// them.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "output/media_probe.hpp"
#include "support/scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

// 0.5 s of the worked example at 60 fps: round(0.5 * 60) frames.
constexpr int kFrames = 30;
const std::string kRender = "render worked-example --duration 0.5 --size 160x90";

// Each output, as the arguments that write it to PATH, and a check of the bytes that arrived.
struct OutputCase {
  const char* name;
  std::string arguments;  // {} stands for the output path
  std::string arrived_prefix;
};

std::string withPath(std::string arguments, const std::string& path) {
  arguments.replace(arguments.find("{}"), 2, path);
  return arguments;
}

class OutputPlacesGLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir(std::string("collide_output_places_") +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                                   "_");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs collide with stdout and stderr in files of the test directory; the exit code.
  int collide(const std::string& arguments) {
    return test::runShellBounded(test::shellQuoted(COLLIDE_BINARY) + " " + arguments + " >" +
                                     test::shellQuoted((dir_ / "stdout.txt").string()) + " 2>" +
                                     test::shellQuoted((dir_ / "stderr.txt").string()),
                                 std::chrono::seconds(120));
  }
  // Runs collide with its stdout a pipe (into cat); returns what came through, `exit_code` set.
  std::string collidePiped(const std::string& arguments, int& exit_code) {
    const fs::path arrived = at("piped.bin"), code = at("code.txt");
    const int shell = test::runShellBounded(
        "{ " + test::shellQuoted(COLLIDE_BINARY) + " " + arguments + " 2>" +
            test::shellQuoted((dir_ / "stderr.txt").string()) + "; echo $? >" +
            test::shellQuoted(code.string()) + "; } | cat >" + test::shellQuoted(arrived.string()),
        std::chrono::seconds(120));
    exit_code = shell == 0 ? std::stoi(test::readFileBytes(code)) : -1;
    std::string bytes = test::readFileBytes(arrived);
    fs::remove(arrived);
    fs::remove(code);
    return bytes;
  }
  std::string stderrText() const { return test::readFileBytes(dir_ / "stderr.txt"); }
  fs::path at(const std::string& name) const { return dir_ / name; }

  // The four outputs, each written to a name in the test directory (captions: NAME.vtt beside a
  // regular MP4 file).
  static std::vector<OutputCase> outputs() {
    return {{"json", "data worked-example --json {}", "{"},
            {"csv", "data worked-example --csv {}", "t_s,"},
            {"captions", kRender + " -o CAPTIONS.mp4 --captions", "WEBVTT"},
            {"mp4", kRender + " -o {}", ""}};
  }
  // For the captions case the output path is the .vtt beside "{dir}/lesson.mp4".
  std::string argumentsFor(const OutputCase& output, const fs::path& path) const {
    if (std::string(output.name) == "captions") {
      std::string arguments = output.arguments;
      arguments.replace(arguments.find("CAPTIONS"), 8,
                        test::shellQuoted((path.parent_path() / path.stem()).string()));
      return arguments;
    }
    return withPath(output.arguments, test::shellQuoted(path.string()));
  }
  static std::string nameFor(const OutputCase& output, const std::string& stem) {
    return stem + (std::string(output.name) == "captions" ? ".vtt" : "");
  }

  // The MP4 bytes that arrived are a whole H.264 video of kFrames frames.
  void expectVideo(const std::string& bytes) {
    const fs::path copy = at("arrived.mp4");
    std::ofstream(copy, std::ios::binary) << bytes;
    const output::test::MediaFacts facts = output::test::probeMedia(copy);
    ASSERT_NE(output::test::findStream(facts, "video"), nullptr);
    EXPECT_EQ(output::test::findStream(facts, "video")->codec, "h264");
    EXPECT_EQ(facts.video_frames, kFrames);
    fs::remove(copy);
  }
  void expectArrived(const OutputCase& output, const std::string& bytes) {
    if (std::string(output.name) == "mp4") {
      expectVideo(bytes);
    } else {
      EXPECT_EQ(bytes.rfind(output.arrived_prefix, 0), 0u)
          << output.name << ": " << bytes.substr(0, 80);
    }
  }

  fs::path dir_;
};

TEST_F(OutputPlacesGLTest, ACharacterDeviceStaysTheSameDevice) {
  for (const OutputCase& output : outputs()) {
    SCOPED_TRACE(output.name);
    const fs::path node = at(nameFor(output, "null"));
    // c 1 3 is the null device: written through, the bytes vanish, as they should.
    if (::mknod(node.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) {
      GTEST_SKIP() << "mknod is not allowed here (" << std::strerror(errno)
                   << "): the device case is not tested";
    }
    ASSERT_EQ(collide(argumentsFor(output, node)), 0) << stderrText();
    struct stat info {};
    ASSERT_EQ(::lstat(node.c_str(), &info), 0);
    EXPECT_TRUE(S_ISCHR(info.st_mode));
    EXPECT_EQ(::major(info.st_rdev), 1u);
    EXPECT_EQ(::minor(info.st_rdev), 3u);
    fs::remove(node);
    fs::remove(at("null.mp4"));
  }
}

TEST_F(OutputPlacesGLTest, AFifoWithAReaderGetsTheWholeOutput) {
  for (const OutputCase& output : outputs()) {
    SCOPED_TRACE(output.name);
    const fs::path fifo = at(nameFor(output, "pipe"));
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string arrived;
    std::thread reader([&] {
      std::ifstream in(fifo, std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      arrived = bytes.str();
    });
    const int code = collide(argumentsFor(output, fifo));
    // Should collide never have opened the FIFO, this open (which needs a reader) releases the
    // reader's own open with an empty stream; once the reader is gone it fails, harmlessly.
    const int release = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (release >= 0) ::close(release);
    reader.join();
    ASSERT_EQ(code, 0) << stderrText();
    expectArrived(output, arrived);
    struct stat info {};
    ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
    EXPECT_TRUE(S_ISFIFO(info.st_mode));
    fs::remove(fifo);
    fs::remove(at("pipe.mp4"));
  }
}

TEST_F(OutputPlacesGLTest, ALinkToAFileStaysALinkAndItsFileIsReplaced) {
  for (const OutputCase& output : outputs()) {
    SCOPED_TRACE(output.name);
    fs::create_directories(at("real"));
    // Named as regular files are: the MP4 by its extension.
    const std::string extension = std::string(output.name) == "mp4" ? ".mp4" : "";
    const fs::path file = at("real") / (nameFor(output, "target") + extension);
    std::ofstream(file) << "earlier\n";
    const fs::path link = at(nameFor(output, "link") + extension);
    fs::create_symlink(file, link);
    ASSERT_EQ(collide(argumentsFor(output, link)), 0) << stderrText();
    ASSERT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(fs::read_symlink(link), file);
    expectArrived(output, test::readFileBytes(file));
    // Nothing else appeared beside the file (no temporary left).
    EXPECT_EQ(std::distance(fs::directory_iterator(at("real")), fs::directory_iterator()), 1);
    fs::remove_all(at("real"));
    fs::remove(link);
    fs::remove(at("link.mp4"));
  }
}

TEST_F(OutputPlacesGLTest, ALinkToTheProcessesOwnStdoutWritesToItsPipe) {
  for (const OutputCase& output : outputs()) {
    SCOPED_TRACE(output.name);
    const fs::path link = at(nameFor(output, "self"));
    fs::create_symlink("/proc/self/fd/1", link);
    int code = -1;
    const std::string arrived = collidePiped(argumentsFor(output, link), code);
    ASSERT_EQ(code, 0) << stderrText();
    expectArrived(output, arrived);
    ASSERT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(fs::read_symlink(link), "/proc/self/fd/1");
    fs::remove(link);
    fs::remove(at("self.mp4"));
  }
}

TEST_F(OutputPlacesGLTest, DashIsStdoutForTextAndForStreamableVideo) {
  int code = -1;
  std::string arrived = collidePiped("data worked-example --json -", code);
  ASSERT_EQ(code, 0) << stderrText();
  EXPECT_EQ(arrived.rfind("{", 0), 0u);
  arrived = collidePiped("data worked-example --csv -", code);
  ASSERT_EQ(code, 0) << stderrText();
  EXPECT_EQ(arrived.rfind("t_s,", 0), 0u);
  arrived = collidePiped(kRender + " -o - --format mp4", code);
  ASSERT_EQ(code, 0) << stderrText();
  expectVideo(arrived);
  // The report line goes to stderr, out of the video's way.
  EXPECT_NE(stderrText().find("wrote stdout"), std::string::npos) << stderrText();
  // A still is one PNG on stdout.
  arrived = collidePiped("still worked-example --at 1 --size 160x90 -o -", code);
  ASSERT_EQ(code, 0) << stderrText();
  EXPECT_EQ(arrived.rfind("\x89PNG\r\n\x1a\n", 0), 0u);
  // Only the files the test made itself: no "-" file, no alt text, no temporary.
  EXPECT_FALSE(fs::exists(at("-")));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()),
            1);  // stderr.txt
}

}  // namespace
}  // namespace collide
