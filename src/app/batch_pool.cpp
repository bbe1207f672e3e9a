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
#include <thread>

#include "app/signals.hpp"
#include "core/error.hpp"

extern char** environ;

namespace collide::app {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

// A private directory for the workers' logs, removed with everything in it.
class LogDirectory {
 public:
  LogDirectory() {
    std::string pattern = (fs::temp_directory_path() / "collide-batch-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw core::RuntimeError("batch: cannot create a directory for worker logs in " +
                               fs::temp_directory_path().string() + ": " + std::strerror(errno));
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

// Reads what a worker reported (see runBatchJob) and how it ended.
JobOutcome readOutcome(const BatchJob& job, const std::string& log, int status) {
  JobOutcome outcome;
  outcome.index = job.index;
  std::ifstream in(log);
  std::string last_line, error_line;
  for (std::string line; std::getline(in, line);) {
    const auto take = [&](const char* prefix) -> std::optional<std::string> {
      const std::size_t n = std::strlen(prefix);
      if (line.compare(0, n, prefix) == 0) return line.substr(n);
      return std::nullopt;
    };
    if (auto v = take("scene ")) {
      outcome.name = *v;
    } else if (auto v = take("lang ")) {
      outcome.lang = *v;
    } else if (auto v = take("title ")) {
      outcome.title = *v;
    } else if (auto v = take("parameter ")) {
      const std::size_t space = v->find(' ');
      outcome.parameters.emplace_back(v->substr(0, space),
                                      space == std::string::npos ? "" : v->substr(space + 1));
    } else if (auto v = take("output ")) {
      const std::size_t space = v->find(' ');
      outcome.outputs.emplace_back(v->substr(0, space), v->substr(space + 1));
    } else if (auto v = take("warning ")) {
      outcome.warnings.push_back(*v);
    } else if (auto v = take("collide: ")) {
      error_line = *v;
    }
    if (!line.empty()) last_line = line;
  }
  outcome.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (outcome.ok) return outcome;
  if (!error_line.empty()) {
    outcome.error = error_line;
  } else if (WIFSIGNALED(status)) {
    outcome.error = std::string("worker killed by signal ") + std::to_string(WTERMSIG(status)) +
                    " (" + strsignal(WTERMSIG(status)) + ")" +
                    (last_line.empty() ? "" : ": " + last_line);
  } else {
    outcome.error = "worker exited with status " + std::to_string(WEXITSTATUS(status)) +
                    (last_line.empty() ? "" : ": " + last_line);
  }
  return outcome;
}

}  // namespace

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
      if (!stopping_ && StopSignals::received() != 0) {
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
