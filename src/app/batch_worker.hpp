#pragma once
// One batch job, run in the current process: load and validate the scene with the job's overrides,
// then write each requested format through the same pipeline functions as `render`, `still` and
// `data`. The batch runs every job in a child process of its own (batch_pool.hpp), so a crash or
// an abort in one scene cannot stop the others.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "app/batch_plan.hpp"
#include "app/render_settings.hpp"

namespace collide::app {

struct JobSettings {
  std::vector<BatchFormat> formats;
  FrameSize size;                    // mp4 rounds it down to even
  int fps = 60;                      // mp4
  std::optional<double> at_s;        // png: simulated time; default half the duration
  std::optional<double> duration_s;  // overrides every scene's duration
  double csv_step_s = 0.01;          // csv: row spacing, s
  bool json_events = false;          // json: list every collision (--events)
  std::string directory;             // where the outputs go
  int cores = 0;       // cores this worker may keep busy (batch_threads.hpp); 0: as `render` uses
  bool force = false;  // --force: past the size bounds (output/output_plan.hpp)
};

// Runs `job`, writing its outputs into settings.directory. Reports on `out`, one line each, every
// value a JSON string literal ("..."), so a value holds no line break:
//   scene NAME            the scene's name, after loading
//   lang TAG              the language it was made in
//   title TITLE
//   parameter KEY VALUE   a preset parameter the scene was built with
//   output FORMAT FILE    a file written (relative to the directory)
//   warning TEXT          a physics warning (physicsWarnings), once per job
// Throws core::Error subclasses (the first failing format stops the job; files already written
// stay and are listed).
void runBatchJob(const BatchJob& job, const JobSettings& settings, std::ostream& out);

// A pool's worker (batch_pool.hpp): reads "INDEX LOG" lines from `channel_fd`, appends this
// process's stdout and stderr to LOG and runs the job all[INDEX] with `out` (which writes to
// stdout), answering "done" on the channel after each; returns when the channel closes. A failing
// job throws out of it, which ends the worker.
void serveBatchJobs(const std::vector<BatchJob>& all, const JobSettings& settings, int channel_fd,
                    std::ostream& out);

}  // namespace collide::app
