#pragma once
// What every test that touches files or runs commands needs, done safely: a fresh directory of its
// own (unique even when two builds run the suite at once), a shell command that cannot hang the
// suite, and a "disk full" device made inside that directory instead of using the machine's /dev.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace collide::test {

// A new empty directory under the temporary directory, named `prefix` plus a random suffix
// (mkdtemp), removed with everything in it on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // The same path as one word of a shell command line (shellQuoted).
  std::string shellFile(const std::string& name) const;
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of every entry in the directory (hidden ones included), sorted.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

// A fresh directory as above, for fixtures that manage removal themselves.
std::filesystem::path makeUniqueTempDir(const std::string& prefix);

// `text` as one single-quoted word of a /bin/sh command line: a path with a space, a quote, '$' or
// '*' in it (a clone under "/tmp/with space", a scratch folder under such a TMPDIR) stays one word,
// taken as typed. Every path a test puts into a command line goes through it; scripts/check-tests
// looks for COLLIDE_BINARY and scratch paths put in bare.
std::string shellQuoted(const std::string& text);

// Runs `command` with /bin/sh, killed (with its process group) after `limit`; returns its exit
// status, 124 when it timed out, -1 when it could not run.
int runShellBounded(const std::string& command,
                    std::chrono::seconds limit = std::chrono::seconds(300));

// A shell command's exit status (as runShellBounded gives it) and what it printed.
struct ShellRun {
  int exit_code;
  std::string out, err;  // stdout and stderr
};

// Runs `command` as runShellBounded does, its stdout and stderr sent to files in `directory`
// (a test's own scratch directory) and read back; the files are removed afterwards.
ShellRun runShellCaptured(const std::filesystem::path& directory, const std::string& command,
                          std::chrono::seconds limit = std::chrono::seconds(300));

// The whole content of a file, byte for byte; empty when it cannot be read.
std::string readFileBytes(const std::filesystem::path& path);

// A character device that behaves like /dev/full (major 1, minor 7: every write fails with
// ENOSPC), made with mknod at `directory`/`name`. nullopt, with the reason in `why_not`, where
// device nodes cannot be made or used there (not root, a nodev mount): the caller skips.
std::optional<std::filesystem::path> makeFullDevice(const std::filesystem::path& directory,
                                                    const std::string& name, std::string& why_not);

}  // namespace collide::test
