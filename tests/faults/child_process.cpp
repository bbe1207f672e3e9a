#include "faults/child_process.hpp"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

extern char** environ;

namespace collide::test {
namespace {

constexpr uid_t kNobody = 65534;       // Debian's user and group "nobody"
constexpr int kSetupFailedExit = 125;  // the child could not set itself up (not collide's code)

// LD_PRELOAD splits its list at spaces and colons: a library whose path holds one (a clone under
// "/tmp/with space") is reached through a link of a plain name in a folder of its own, removed
// with the object.
class PreloadName {
 public:
  explicit PreloadName(const std::string& library) : name_(library) {
    if (library.find_first_of(" :\t") == std::string::npos) return;
    std::string folder =
        (std::filesystem::temp_directory_path() / "collide_preload_XXXXXX").string();
    if (mkdtemp(folder.data()) == nullptr) std::abort();
    folder_ = folder;
    chmod(folder_.c_str(), 0755);  // an unprivileged child reaches it too
    name_ = folder_ + "/shim.so";
    std::filesystem::create_symlink(library, name_);
    if (name_.find_first_of(" :\t") != std::string::npos) {
      std::fprintf(stderr, "child_process: no LD_PRELOAD name without spaces for %s\n",
                   library.c_str());
      std::abort();
    }
  }
  ~PreloadName() {
    std::error_code ignored;
    if (!folder_.empty()) std::filesystem::remove_all(folder_, ignored);
  }
  PreloadName(const PreloadName&) = delete;
  PreloadName& operator=(const PreloadName&) = delete;
  const std::string& name() const { return name_; }

 private:
  std::string name_, folder_;
};

// The test's environment with `changes` applied, as NAME=VALUE strings; `preload` is the name
// LD_PRELOAD gets for options.preload.
std::vector<std::string> childEnvironment(const ChildOptions& options, const std::string& preload) {
  std::map<std::string, std::string> variables;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string text = *entry;
    const std::size_t equals = text.find('=');
    if (equals != std::string::npos) variables[text.substr(0, equals)] = text.substr(equals + 1);
  }
  for (const std::string& change : options.environment) {
    const std::size_t equals = change.find('=');
    variables[change.substr(0, equals)] = change.substr(equals + 1);
  }
  if (!options.preload.empty()) {
    const std::string earlier = variables["LD_PRELOAD"];
    variables["LD_PRELOAD"] = earlier.empty() ? preload : earlier + ":" + preload;
    // An ASan build wants its runtime first in the library list; the shim now comes before it.
    const std::string asan = variables["ASAN_OPTIONS"];
    variables["ASAN_OPTIONS"] = (asan.empty() ? "" : asan + ":") + "verify_asan_link_order=0";
  }
  std::vector<std::string> list;
  for (const auto& [name, value] : variables) list.push_back(name + "=" + value);
  return list;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> list;
  for (std::string& s : strings) list.push_back(s.data());
  list.push_back(nullptr);
  return list;
}

// In the forked child: only async-signal-safe calls until execve.
[[noreturn]] void becomeChild(const ChildOptions& options, int out_fd, int err_fd,
                              char* const* argv, char* const* envp) {
  if (dup2(out_fd, STDOUT_FILENO) < 0 || dup2(err_fd, STDERR_FILENO) < 0) _exit(kSetupFailedExit);
  if (options.stdout_to == ChildStdout::kClosed) close(STDOUT_FILENO);
  if (options.stdout_to == ChildStdout::kFile) {
    const int fd = open(options.stdout_path.c_str(), O_WRONLY);
    if (fd < 0 || dup2(fd, STDOUT_FILENO) < 0) _exit(kSetupFailedExit);
    close(fd);
  }
  // Signal dispositions set to "ignore" survive exec: start from the defaults, as from a shell.
  for (int signal_number : {SIGINT, SIGTERM, SIGXFSZ, SIGPIPE}) signal(signal_number, SIG_DFL);
  if (options.ignore_sigpipe) signal(SIGPIPE, SIG_IGN);
  const rlimit no_core{0, 0};
  if (options.no_core_dump && setrlimit(RLIMIT_CORE, &no_core) != 0) _exit(kSetupFailedExit);
  if (!options.working_directory.empty() && chdir(options.working_directory.c_str()) != 0) {
    _exit(kSetupFailedExit);
  }
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (options.file_size_limit_bytes) {
    const auto limit = static_cast<rlim_t>(*options.file_size_limit_bytes);
    const rlimit file_size{limit, limit};
    if (setrlimit(RLIMIT_FSIZE, &file_size) != 0) _exit(kSetupFailedExit);
  }
  if (options.unprivileged && geteuid() == 0) {
    if (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) {
      static const char kMessage[] = "child_process: cannot become user nobody\n";
      [[maybe_unused]] const ssize_t ignored = write(err_fd, kMessage, sizeof kMessage - 1);
      _exit(kSetupFailedExit);
    }
  }
  execve(argv[0], argv, envp);
  _exit(127);
}

}  // namespace

ChildResult runChild(const std::string& program, const std::vector<std::string>& arguments,
                     const ChildOptions& options) {
  std::vector<std::string> argv_strings{program};
  argv_strings.insert(argv_strings.end(), arguments.begin(), arguments.end());
  const PreloadName preload(options.preload);
  std::vector<std::string> env_strings = childEnvironment(options, preload.name());
  std::vector<char*> argv = pointers(argv_strings);
  std::vector<char*> envp = pointers(env_strings);

  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0 || pipe2(err_pipe, O_CLOEXEC) != 0) std::abort();
  // A broken pipe: its reader closed before the child starts. A stalled one: held unread here.
  int held_reader = -1;
  if (options.stdout_to == ChildStdout::kBrokenPipe) close(out_pipe[0]);
  if (options.stdout_to == ChildStdout::kStalledPipe) held_reader = out_pipe[0];
  const bool reads_stdout = options.stdout_to == ChildStdout::kCaptured;
  const pid_t pid = fork();
  if (pid < 0) std::abort();
  if (pid == 0) becomeChild(options, out_pipe[1], err_pipe[1], argv.data(), envp.data());
  close(out_pipe[1]);
  close(err_pipe[1]);
  if (!reads_stdout && options.stdout_to != ChildStdout::kBrokenPipe &&
      options.stdout_to != ChildStdout::kStalledPipe) {
    close(out_pipe[0]);
  }

  ChildResult result;
  const auto deadline = std::chrono::steady_clock::now() + options.timeout;
  pollfd fds[2] = {{reads_stdout ? out_pipe[0] : -1, POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&result.out, &result.err};
  int open_pipes = reads_stdout ? 2 : 1;
  int status = 0;
  bool exited = false;
  std::chrono::steady_clock::time_point signal_time;
  while (!exited) {
    if (open_pipes > 0 && poll(fds, 2, 10) > 0) {
      for (int i = 0; i < 2; ++i) {
        if (fds[i].fd < 0 || fds[i].revents == 0) continue;
        char buffer[4096];
        const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
        if (n > 0) {
          sinks[i]->append(buffer, static_cast<std::size_t>(n));
        } else {
          close(fds[i].fd);
          fds[i].fd = -1;
          --open_pipes;
        }
      }
    } else if (open_pipes == 0) {
      usleep(10000);
    }
    if (options.signal_number != 0 && !result.signal_sent && options.ready_for_signal &&
        (!options.signal_once_caught || catchesSignal(pid, options.signal_number)) &&
        options.ready_for_signal()) {
      kill(pid, options.signal_number);
      result.signal_sent = true;
      signal_time = std::chrono::steady_clock::now();
    }
    if (std::chrono::steady_clock::now() > deadline && !result.timed_out) {
      kill(pid, SIGKILL);
      result.timed_out = true;
    }
    exited = waitpid(pid, &status, WNOHANG) == pid;
  }
  if (result.signal_sent) result.signal_to_exit = std::chrono::steady_clock::now() - signal_time;
  if (held_reader >= 0) close(held_reader);
  // Whatever is still in the pipes after the exit.
  for (int i = 0; i < 2; ++i) {
    if (fds[i].fd < 0) continue;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[i].fd, buffer, sizeof buffer)) > 0;) {
      sinks[i]->append(buffer, static_cast<std::size_t>(n));
    }
    close(fds[i].fd);
  }
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.killed_by_signal = WTERMSIG(status);
  return result;
}

bool catchesSignal(int pid, int signal_number) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    // "SigCgt:\t0000000000004002": a hexadecimal mask, bit N-1 for signal N.
    if (line.rfind("SigCgt:", 0) != 0) continue;
    const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
    return ((mask >> (signal_number - 1)) & 1u) != 0;
  }
  return false;
}

std::string describe(const ChildResult& result) {
  if (result.timed_out) return "hung (killed after the timeout)";
  if (result.killed_by_signal != 0) {
    return "killed by signal " + std::to_string(result.killed_by_signal) + " (" +
           strsignal(result.killed_by_signal) + ")";
  }
  return "exit " + std::to_string(result.exit_code);
}

}  // namespace collide::test
