// Scene inputs that are not regular files, through the real binary: the zero and random devices
// (made with mknod in the test's own directory) are refused at once without being read, a pipe
// that never ends stops at the 4 MiB limit, and a scene through process substitution loads.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>

#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

// Without the bounded reader these runs never end (the device) or grow without limit (the pipe);
// a generous bound tells a hang from a slow machine.
constexpr std::chrono::seconds kBound{20};
constexpr long kMemoryLimitKiB = 50 * 1024;

class InputReaderTest : public ::testing::Test {
 protected:
  int collide(const std::string& arguments) {
    return test::runShellBounded(test::shellQuoted(COLLIDE_BINARY) + " " + arguments + " >" +
                                     scratch_.shellFile("out") + " 2>" + scratch_.shellFile("err"),
                                 kBound);
  }
  // The same under bash, for process substitution: <(...) is a pipe named /dev/fd/N.
  int collideInBash(const std::string& arguments) {
    return test::runShellBounded(
        "bash -c " + test::shellQuoted(test::shellQuoted(COLLIDE_BINARY) + " " + arguments) + " >" +
            scratch_.shellFile("out") + " 2>" + scratch_.shellFile("err"),
        kBound);
  }
  std::string out() const { return test::readFileBytes(scratch_.path() / "out"); }
  std::string err() const { return test::readFileBytes(scratch_.path() / "err"); }
  // The largest resident set, in KiB, that running `command` reached: measured in a forked
  // process of its own, whose only waited-for descendants are that command's.
  static long peakKiBOf(const std::string& command) {
    int channel[2];
    if (::pipe(channel) != 0) return -1;
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(channel[0]);
      test::runShellBounded(command, kBound);
      rusage usage{};
      ::getrusage(RUSAGE_CHILDREN, &usage);
      const long peak = usage.ru_maxrss;
      [[maybe_unused]] const ssize_t sent = ::write(channel[1], &peak, sizeof peak);
      ::_exit(0);
    }
    ::close(channel[1]);
    long peak = -1;
    // check-tests: bounded by kBound (the forked process runs one bounded command, then exits)
    if (::read(channel[0], &peak, sizeof peak) != sizeof peak) peak = -1;
    ::close(channel[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);  // check-tests: bounded by kBound, as above
    return peak;
  }
  // What reading `scene` adds to the memory of a run that reads nothing (`collide --version`:
  // the libraries alone, some 80 MiB resident).
  long extraKiBOfChecking(const std::string& scene) {
    const std::string binary = test::shellQuoted(COLLIDE_BINARY);
    const long baseline = peakKiBOf(binary + " --version >" + scratch_.shellFile("version"));
    const long reading = peakKiBOf("bash -c " + test::shellQuoted(binary + " check " + scene) +
                                   " >" + scratch_.shellFile("out") + " 2>&1");
    EXPECT_GT(baseline, 0);
    EXPECT_GT(reading, 0);
    return reading - baseline;
  }
  test::ScratchDir scratch_{"collide_input_reader_"};
};

TEST_F(InputReaderTest, CharacterDevicesAreRefusedWithoutReading) {
  for (const auto& [name, minor] : {std::pair{"zero", 5u}, std::pair{"urandom", 9u}}) {
    SCOPED_TRACE(name);
    const fs::path node = scratch_.path() / name;
    if (::mknod(node.c_str(), S_IFCHR | 0444, ::makedev(1, minor)) != 0) {
      GTEST_SKIP() << "mknod is not allowed here (" << std::strerror(errno)
                   << "): device scene files are not tested";
    }
    EXPECT_EQ(collide("check " + test::shellQuoted(node.string())), 2) << err();
    // Appended, not "'" + node.string(): GCC 12 warns falsely (-Wrestrict) on a literal plus a
    // string.
    std::string refusal = "'";
    refusal.append(node.string()).append("': is a character device");
    EXPECT_NE(err().find(refusal), std::string::npos) << err();
    EXPECT_EQ(collide("render " + test::shellQuoted(node.string()) + " -o " +
                      scratch_.shellFile("x.mp4")),
              2)
        << err();
    EXPECT_FALSE(fs::exists(scratch_.path() / "x.mp4"));
  }
  EXPECT_LT(extraKiBOfChecking(scratch_.shellFile("zero")), kMemoryLimitKiB);
}

TEST_F(InputReaderTest, AnEndlessPipeStopsAtTheLimit) {
  // `yes` writes for ever; the reader stops after 4 MiB and says so.
  EXPECT_EQ(collideInBash("check <(yes)"), 2) << err();
  EXPECT_NE(err().find("more than 4 MiB"), std::string::npos) << err();
  EXPECT_LT(extraKiBOfChecking("<(yes)"), kMemoryLimitKiB);
}

TEST_F(InputReaderTest, ASceneThroughProcessSubstitutionLoads) {
  EXPECT_EQ(collideInBash("check <(" + test::shellQuoted(COLLIDE_BINARY) +
                          " presets show worked-example)"),
            0)
      << err();
  EXPECT_EQ(out().rfind("ok: ", 0), 0u) << out();
}

}  // namespace
}  // namespace collide
