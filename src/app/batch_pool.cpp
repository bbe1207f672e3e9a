#include "app/batch_pool.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
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

// The environment for workers: llvmpipe limited to one thread per worker when several run at
// once (the pool already fills the cores; more threads only contend), unless the user chose.
std::vector<std::string> workerEnvironment(int workers) {
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) env.emplace_back(*e);
  if (workers > 1 && std::getenv("LP_NUM_THREADS") == nullptr) env.emplace_back("LP_NUM_THREADS=1");
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> result;
  for (std::string& s : strings) result.push_back(s.data());
  result.push_back(nullptr);
  return result;
}

pid_t spawnWorker(const PoolSettings& settings, const BatchJob& job, const std::string& log,
                  std::vector<std::string>& env) {
  std::vector<std::string> args = {settings.executable};
  for (std::string& a : settings.arguments(job)) args.push_back(std::move(a));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  std::vector<char*> argv = pointers(args);
  std::vector<char*> envp = pointers(env);
  const int error =
      posix_spawn(&pid, settings.executable.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    throw core::RuntimeError("batch: cannot start worker '" + settings.executable +
                             "': " + std::strerror(error));
  }
  return pid;
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

std::vector<JobOutcome> runWorkerPool(const std::vector<BatchJob>& jobs,
                                      const PoolSettings& settings) {
  const LogDirectory logs;
  std::vector<std::string> env = workerEnvironment(settings.workers);
  std::vector<JobOutcome> outcomes(jobs.size());
  struct Running {
    std::size_t slot;  // index into jobs
    Clock::time_point start;
  };
  std::map<pid_t, Running> running;
  std::vector<std::size_t> order = settings.start_order;
  if (order.empty()) {
    for (std::size_t slot = 0; slot < jobs.size(); ++slot) order.push_back(slot);
  }
  COLLIDE_ASSERT(order.size() == jobs.size(), "runWorkerPool: start_order must name every job");
  std::size_t next = 0;  // into order
  bool stopping = false;
  const auto finish = [&](std::size_t slot, JobOutcome outcome, Clock::time_point start) {
    outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    outcomes[slot] = outcome;
    if (settings.on_done) settings.on_done(outcomes[slot]);
  };
  while (next < jobs.size() || !running.empty()) {
    if (!stopping && StopSignals::received() != 0) {
      stopping = true;
      for (const auto& [pid, job] : running) kill(pid, SIGTERM);
    }
    while (!stopping && next < jobs.size() && static_cast<int>(running.size()) < settings.workers) {
      const std::size_t slot = order[next];
      const pid_t pid = spawnWorker(settings, jobs[slot], logs.logFor(jobs[slot].index), env);
      running[pid] = {slot, Clock::now()};
      ++next;
    }
    if (stopping && running.empty()) break;
    int status = 0;
    const pid_t done = waitpid(-1, &status, WNOHANG);
    if (done <= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    const auto found = running.find(done);
    if (found == running.end()) continue;  // not one of ours
    const Running job = found->second;
    running.erase(found);
    finish(job.slot, readOutcome(jobs[job.slot], logs.logFor(jobs[job.slot].index), status),
           job.start);
  }
  for (; next < jobs.size(); ++next) {
    const std::size_t slot = order[next];
    outcomes[slot].index = jobs[slot].index;
    outcomes[slot].error = "not run: interrupted";
  }
  return outcomes;
}

}  // namespace collide::app
