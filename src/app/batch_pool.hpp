#pragma once
// The batch's worker pool: every job runs in a child process of its own (the collide binary again,
// with `--worker K`), at most `workers` at a time. A process per job gives each its own GL context
// and encoder, and keeps a crash, an abort or a leak in one scene from touching the others.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "app/batch_plan.hpp"

namespace collide::app {

struct JobOutcome {
  int index = 0;  // BatchJob::index
  bool ok = false;
  std::string error;        // one line when !ok
  std::string name, title;  // the scene's, when it loaded
  std::string lang;         // the language it was made in (BCP 47), when it loaded
  std::vector<std::pair<std::string, std::string>> parameters;  // preset parameters
  std::vector<std::pair<std::string, std::string>> outputs;     // format, file
  std::vector<std::string> warnings;                            // physics warnings, once each
  double seconds = 0.0;                                         // wall-clock time of the job
};

struct PoolSettings {
  std::string executable;  // the collide binary the workers run
  int workers = 1;
  // Positions into the jobs in the order to start them (batch_order.hpp: the longest first);
  // empty: the jobs' own order.
  std::vector<std::size_t> start_order;
  // The arguments (after the executable) that run one job in a worker.
  std::function<std::vector<std::string>(const BatchJob&)> arguments;
  // Called in the parent as each job finishes, in completion order.
  std::function<void(const JobOutcome&)> on_done;
};

// The binary to run workers with: $COLLIDE_BATCH_WORKER if set (tests that run the CLI
// in-process), otherwise this process's own executable.
std::string workerExecutable();

// Runs every job; returns the outcomes in job order. A SIGINT or SIGTERM stops new jobs from
// starting, passes SIGTERM to the running ones and waits for them; jobs never started come back
// with error "not run: interrupted". Throws core::RuntimeError when no worker can be started.
std::vector<JobOutcome> runWorkerPool(const std::vector<BatchJob>& jobs,
                                      const PoolSettings& settings);

}  // namespace collide::app
