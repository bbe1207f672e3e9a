#pragma once
// The batch's worker pool: at most `workers` child processes (the collide binary again, with
// `--serve`), each running the jobs it is handed one after the other. A worker loads the GL and
// video modules, the fonts and the language data once for all its jobs (a fresh process per job
// spent a sixth of a batch's CPU on that). A job that fails ends its worker, and so does a crash:
// the job it was running fails, the next job gets a fresh worker, and no job after a failure runs
// in a process that one touched.
//
// The protocol, on the worker's descriptor 3 (a socket): the pool writes "INDEX LOG\n" (the job's
// BatchJob::index and the file for its report lines, see runBatchJob) and the worker, its stdout
// and stderr appended to LOG, answers "done\n" once the job succeeded; it exits when the socket
// closes or a job fails (exit status and stderr as `collide` gives them).
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
  // Where the jobs write: a worker that dies leaves its temporary files there, which the pool
  // removes (output/temp_file.hpp).
  std::string output_directory;
  int workers = 1;
  // llvmpipe's LP_NUM_THREADS in every worker (batch_threads.hpp), unless the user set it.
  int rasterizer_threads = 0;
  // Positions into the jobs in the order to start them (batch_order.hpp: the longest first);
  // empty: the jobs' own order.
  std::vector<std::size_t> start_order;
  // The arguments (after the executable) that start a worker.
  std::vector<std::string> arguments;
  // Called in the parent as each job finishes, in completion order.
  std::function<void(const JobOutcome&)> on_done;
};

// Throws core::InputError (exit 2) naming TMPDIR when it names no directory: the workers' logs
// go there, so a batch checks it before it makes its output folder.
void requireTemporaryDirectory();

// The binary to run workers with: $COLLIDE_BATCH_WORKER if set (tests that run the CLI
// in-process), otherwise this process's own executable.
std::string workerExecutable();

// The descriptor a worker reads its jobs from and answers on.
constexpr int kWorkerChannelFd = 3;

// Runs every job; returns the outcomes in job order. A SIGINT or SIGTERM stops new jobs from
// starting, passes SIGTERM to the running ones and waits for them; jobs never started come back
// with error "not run: interrupted". Throws core::RuntimeError when no worker can be started.
std::vector<JobOutcome> runWorkerPool(const std::vector<BatchJob>& jobs,
                                      const PoolSettings& settings);

}  // namespace collide::app
