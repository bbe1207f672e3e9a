#include "app/batch_pool.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string_view>
#include <thread>

#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/stop_signals.hpp"
#include "output/temp_file.hpp"
#include "report/json_writer.hpp"

extern char** environ;

namespace collide::app {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

// The directory for temporary files ($TMPDIR, else /tmp). Throws core::InputError naming TMPDIR
// when it names no directory.
fs::path temporaryDirectory() {
  std::error_code error;
  fs::path path = fs::temp_directory_path(error);
  if (!error) return path;
  const char* tmpdir = std::getenv("TMPDIR");
  throw core::InputError("TMPDIR: '" + core::echoTyped(tmpdir != nullptr ? tmpdir : "") +
                         "': not a directory (" + error.message() +
                         "); allowed: unset TMPDIR or point it at a directory you may write to");
}

// A private directory for the workers' logs, removed with everything in it.
class LogDirectory {
 public:
  LogDirectory() {
    const fs::path parent = temporaryDirectory();
    std::string pattern = (parent / "collide-batch-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      const int error_number = errno;
      throw core::RuntimeError("batch: cannot create a directory for worker logs in '" +
                               parent.string() + "': " + std::strerror(error_number));
    }
    path_ = pattern;
  }
  ~LogDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string logFor(int index) const {
    return (path_ / ("job-" + std::to_string(index) + ".log")).string();
  }

 private:
  fs::path path_;
};

// The environment for workers: llvmpipe's threads sized to a worker's share of the cores
// (batch_threads.hpp; more only contend), unless the user chose.
std::vector<std::string> workerEnvironment(int rasterizer_threads) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) env.emplace_back(*e);
  if (std::getenv("LP_NUM_THREADS") == nullptr) {
    env.push_back("LP_NUM_THREADS=" + std::to_string(rasterizer_threads));
  }
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> result;
  for (std::string& s : strings) result.push_back(s.data());
  result.push_back(nullptr);
  return result;
}

// A running worker: its process, the pool's end of its channel and the job it runs, if any.
struct Worker {
  pid_t pid = -1;
  int channel = -1;
  std::optional<std::size_t> slot;  // index into jobs
  Clock::time_point start;
  std::string answered;  // what it wrote on the channel, not yet a whole line
};

Worker spawnWorker(const PoolSettings& settings, const std::string& first_log,
                   std::vector<std::string>& env) {
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    throw core::RuntimeError(std::string("batch: cannot create a worker's channel: ") +
                             std::strerror(errno));
  }
  // The worker's end is moved above the descriptors the worker is given (0 to 3), so that it is
  // never already the descriptor it is dup2'd onto (which would keep its close-on-exec flag).
  if (const int moved = fcntl(ends[1], F_DUPFD_CLOEXEC, kWorkerChannelFd + 1); moved >= 0) {
    close(ends[1]);
    ends[1] = moved;
  }
  std::vector<std::string> args = {settings.executable};
  for (const std::string& a : settings.arguments) args.push_back(a);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  // Until its first job redirects them, the worker's output goes to that job's log (a worker
  // that cannot start says why there).
  posix_spawn_file_actions_addopen(&actions, 1, first_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_adddup2(&actions, ends[1], kWorkerChannelFd);
  pid_t pid = 0;
  std::vector<char*> argv = pointers(args);
  std::vector<char*> envp = pointers(env);
  const int error =
      posix_spawn(&pid, settings.executable.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  close(ends[1]);
  if (error != 0) {
    close(ends[0]);
    throw core::RuntimeError("batch: cannot start worker '" + settings.executable +
                             "': " + std::strerror(error));
  }
  Worker worker;
  worker.pid = pid;
  worker.channel = ends[0];
  return worker;
}

// Hands `worker` the job; false if it is gone (its exit is then reaped and the job fails).
bool handJob(Worker& worker, std::size_t slot, const BatchJob& job, const std::string& log) {
  worker.slot = slot;
  worker.start = Clock::now();
  const std::string line = std::to_string(job.index) + " " + log + "\n";
  std::size_t sent = 0;
  while (sent < line.size()) {
    const ssize_t n = send(worker.channel, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

// Reads what `worker` has answered so far; true once it reported its job done.
bool reportedDone(Worker& worker) {
  char buffer[256];
  for (;;) {
    const ssize_t n = recv(worker.channel, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    worker.answered.append(buffer, static_cast<std::size_t>(n));
  }
  const std::size_t end = worker.answered.find('\n');
  if (end == std::string::npos) return false;
  worker.answered.erase(0, end + 1);
  return true;
}

// A report line (see runBatchJob): its kind and its values, each a JSON string literal. nullopt
// for any other line (a library's message in the log).
std::optional<std::pair<std::string, std::vector<std::string>>> parseReportLine(
    const std::string& line) {
  const std::size_t space = line.find(' ');
  if (space == std::string::npos || space == 0) return std::nullopt;
  std::vector<std::string> values;
  std::string_view rest = std::string_view(line).substr(space);
  while (!rest.empty()) {
    if (rest[0] != ' ') return std::nullopt;
    std::size_t used = 0;
    std::optional<std::string> value = report::jsonUnquoted(rest.substr(1), used);
    if (!value) return std::nullopt;
    values.push_back(std::move(*value));
    rest.remove_prefix(1 + used);
  }
  return std::pair{line.substr(0, space), std::move(values)};
}

// Takes a report line's values into `outcome`; false when `line` is no report line.
bool takeReport(const std::string& line, JobOutcome& outcome) {
  const auto report = parseReportLine(line);
  if (!report) return false;
  const auto& [kind, values] = *report;
  if (kind == "scene" && values.size() == 1) {
    outcome.name = values[0];
  } else if (kind == "lang" && values.size() == 1) {
    outcome.lang = values[0];
  } else if (kind == "title" && values.size() == 1) {
    outcome.title = values[0];
  } else if (kind == "parameter" && values.size() == 2) {
    outcome.parameters.emplace_back(values[0], values[1]);
  } else if (kind == "output" && values.size() == 2) {
    outcome.outputs.emplace_back(values[0], values[1]);
  } else if (kind == "warning" && values.size() == 1) {
    outcome.warnings.push_back(values[0]);
  } else {
    return false;
  }
  return true;
}

// Why a worker that left no error line of its own ended: its exit status or the signal that ended
// it, and the last line it printed that was no report (a library's message), if any.
std::string workerEndText(int status, const std::string& last_message) {
  std::string text;
  if (WIFSIGNALED(status)) {
    const int signal_number = WTERMSIG(status);
    text = "the worker was killed by signal " + std::to_string(signal_number) + " (" +
           strsignal(signal_number) + ")";
    // Nobody on the machine sends SIGKILL to a worker but a user or the kernel's OOM killer.
    if (signal_number == SIGKILL) text += "; the system may have run out of memory";
  } else {
    text = "the worker exited with status " + std::to_string(WEXITSTATUS(status));
  }
  if (!last_message.empty()) text += ": " + core::echoTyped(last_message, 200);
  return text;
}

// Reads what a worker reported (see runBatchJob) and how it ended.
JobOutcome readOutcome(const BatchJob& job, const std::string& log, int status) {
  JobOutcome outcome;
  outcome.index = job.index;
  std::ifstream in(log);
  std::string last_message, error_line;
  for (std::string line; std::getline(in, line);) {
    if (takeReport(line, outcome)) continue;
    if (line.compare(0, 9, "collide: ") == 0) {
      error_line = line.substr(9);
    } else if (!line.empty()) {
      last_message = line;
    }
  }
  outcome.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (outcome.ok) return outcome;
  outcome.error = !error_line.empty() ? error_line : workerEndText(status, last_message);
  return outcome;
}

}  // namespace

void requireTemporaryDirectory() {
  temporaryDirectory();
}

std::string workerExecutable() {
  if (const char* chosen = std::getenv("COLLIDE_BATCH_WORKER"); chosen != nullptr && *chosen) {
    return chosen;
  }
  char path[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0)
    throw core::RuntimeError("batch: cannot find the collide executable (/proc/self/exe)");
  return std::string(path, static_cast<std::size_t>(n));
}

namespace {

// The pool's state while it runs: its workers, the jobs handed out so far and what came back.
class Pool {
 public:
  Pool(const std::vector<BatchJob>& jobs, const PoolSettings& settings)
      : jobs_(jobs),
        settings_(settings),
        env_(workerEnvironment(settings.rasterizer_threads)),
        outcomes_(jobs.size()),
        order_(settings.start_order) {
    if (order_.empty()) {
      for (std::size_t slot = 0; slot < jobs.size(); ++slot) order_.push_back(slot);
    }
    COLLIDE_ASSERT(order_.size() == jobs.size(), "runWorkerPool: start_order must name every job");
  }

  std::vector<JobOutcome> run() {
    while (next_ < jobs_.size() || busy()) {
      if (!stopping_ && output::StopSignals::received() != 0) {
        stopping_ = true;
        for (const Worker& worker : workers_) kill(worker.pid, SIGTERM);
      }
      handOutJobs();
      if (stopping_ && !busy()) break;
      const bool waited = collectAnswers();
      reapExited();
      if (!waited && busy()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    endWorkers();
    markNotRun();
    return outcomes_;
  }

 private:
  std::string logOf(std::size_t slot) const { return logs_.logFor(jobs_[slot].index); }

  bool busy() const {
    return std::any_of(workers_.begin(), workers_.end(), [](const Worker& w) { return w.slot; });
  }

  void finish(Worker& worker, int status) {
    const std::size_t slot = *worker.slot;
    worker.slot.reset();
    JobOutcome outcome = readOutcome(jobs_[slot], logOf(slot), status);
    outcome.seconds = std::chrono::duration<double>(Clock::now() - worker.start).count();
    outcomes_[slot] = outcome;
    if (settings_.on_done) settings_.on_done(outcomes_[slot]);
  }

  // Every idle worker gets the next job; a new worker starts while there are fewer than asked.
  void handOutJobs() {
    while (!stopping_ && next_ < jobs_.size()) {
      auto idle = std::find_if(workers_.begin(), workers_.end(),
                               [](const Worker& w) { return !w.slot && w.channel >= 0; });
      if (idle == workers_.end()) {
        if (static_cast<int>(workers_.size()) >= settings_.workers) break;
        workers_.push_back(spawnWorker(settings_, logOf(order_[next_]), env_));
        idle = workers_.end() - 1;
      }
      const std::size_t slot = order_[next_++];
      if (!handJob(*idle, slot, jobs_[slot], logOf(slot))) {
        // Gone before it read the job: its exit, reaped below, fails this job.
        close(idle->channel);
        idle->channel = -1;
      }
    }
  }

  // A job done is answered on its worker's channel. False when no worker had a channel to wait on.
  bool collectAnswers() {
    std::vector<pollfd> channels;
    for (const Worker& worker : workers_) {
      if (worker.slot && worker.channel >= 0) channels.push_back({worker.channel, POLLIN, 0});
    }
    if (!channels.empty()) poll(channels.data(), channels.size(), 5);
    for (Worker& worker : workers_) {
      if (worker.slot && worker.channel >= 0 && reportedDone(worker)) finish(worker, 0);
    }
    return !channels.empty();
  }

  // A job failed ends its worker: its exit status fails the job it held.
  void reapExited() {
    int status = 0;
    for (pid_t done; (done = waitpid(-1, &status, WNOHANG)) > 0;) {
      const auto found = std::find_if(workers_.begin(), workers_.end(),
                                      [&](const Worker& w) { return w.pid == done; });
      if (found == workers_.end()) continue;  // not one of ours
      // A worker killed outright (SIGKILL, the OOM killer) could not remove its temporary files.
      output::removeTemporaryFilesOf(settings_.output_directory, done);
      // It may have answered just before it exited.
      if (found->slot && found->channel >= 0 && reportedDone(*found)) finish(*found, 0);
      if (found->slot) finish(*found, status);
      if (found->channel >= 0) close(found->channel);
      workers_.erase(found);
    }
  }

  // Idle workers end when their channel closes.
  void endWorkers() {
    for (Worker& worker : workers_) {
      if (worker.channel >= 0) close(worker.channel);
    }
    for (const Worker& worker : workers_) {
      int status = 0;
      while (waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
  }

  void markNotRun() {
    for (; next_ < jobs_.size(); ++next_) {
      const std::size_t slot = order_[next_];
      outcomes_[slot].index = jobs_[slot].index;
      outcomes_[slot].error = "not run: interrupted";
    }
  }

  const std::vector<BatchJob>& jobs_;
  const PoolSettings& settings_;
  const LogDirectory logs_;
  std::vector<std::string> env_;
  std::vector<JobOutcome> outcomes_;
  std::vector<Worker> workers_;
  std::vector<std::size_t> order_;
  std::size_t next_ = 0;  // into order_
  bool stopping_ = false;
};

}  // namespace

std::vector<JobOutcome> runWorkerPool(const std::vector<BatchJob>& jobs,
                                      const PoolSettings& settings) {
  return Pool(jobs, settings).run();
}

}  // namespace collide::app
