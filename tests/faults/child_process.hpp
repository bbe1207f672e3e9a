#pragma once
// Runs the real `collide` binary as a child process under an injected fault: a file-size limit
// (a full disk), an unprivileged user (an unwritable directory, even when the tests run as root),
// a preloaded fault shim (missing encoder, failing GL context, missing font), or a stop signal
// sent mid-run. Output is read through pipes, which no file-size limit touches.
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace collide::test {

// Where the child's standard output goes.
enum class ChildStdout {
  kCaptured,     // a pipe read into ChildResult::out
  kClosed,       // closed (the shell's >&-)
  kBrokenPipe,   // a pipe whose reading end is already closed
  kStalledPipe,  // a pipe nobody reads: writes block once it is full
  kFile,  // ChildOptions::stdout_path opened for writing (a device node in the test's folder)
};

struct ChildOptions {
  ChildStdout stdout_to = ChildStdout::kCaptured;
  std::string stdout_path;  // kFile
  // SIGPIPE ignored (inherited so across exec, as `trap '' PIPE` does): a write to a pipe whose
  // reader is gone fails with EPIPE instead of ending the child.
  bool ignore_sigpipe = false;
  // No core file when a signal ends the child (SIGQUIT, SIGXCPU): RLIMIT_CORE 0.
  bool no_core_dump = false;
  // The child's working directory (a test's own folder); empty: the test's.
  std::string working_directory;
  // NAME=VALUE entries added to (or replacing those of) the test's own environment.
  std::vector<std::string> environment;
  // A shared library put in front of every other with LD_PRELOAD. ASan's "runtime does not come
  // first" check is relaxed for it (verify_asan_link_order=0 added to ASAN_OPTIONS).
  std::string preload;
  // RLIMIT_FSIZE in bytes: writes past it fail as on a full disk (SIGXFSZ left at its default
  // action, so the binary itself must ignore it).
  std::optional<long long> file_size_limit_bytes;
  // When the tests run as root (whom permissions do not stop), run the child as user nobody.
  bool unprivileged = false;
  // Sent once `ready_for_signal` returns true (polled every 10 ms); 0: none.
  int signal_number = 0;
  std::function<bool()> ready_for_signal;
  // Poll `ready_for_signal` only once the child catches `signal_number` (a handler shows in
  // /proc/PID/status), so the signal meets collide's stop handling and not the default action
  // however slowly the child starts.
  bool signal_once_caught = false;
  // A child still running then is killed and reported as hung.
  std::chrono::seconds timeout{120};
};

struct ChildResult {
  int exit_code = -1;        // when it exited; -1 otherwise
  int killed_by_signal = 0;  // the signal that ended it, if one did
  bool signal_sent = false;  // ChildOptions::signal_number was delivered
  // From the signal to the child's exit, to within the 10 ms polling step.
  std::chrono::duration<double> signal_to_exit{0.0};
  bool timed_out = false;  // it hung and was killed
  std::string out, err;    // stdout and stderr
};

// Runs `program` with `arguments` (argv[1] onwards).
ChildResult runChild(const std::string& program, const std::vector<std::string>& arguments,
                     const ChildOptions& options = {});

// Whether process `pid` has a handler installed for `signal_number` (SigCgt in its
// /proc/PID/status).
bool catchesSignal(int pid, int signal_number);

// "exit 1", "killed by signal 25", "hung": for failure messages.
std::string describe(const ChildResult& result);

}  // namespace collide::test
