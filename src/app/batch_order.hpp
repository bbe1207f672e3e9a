#pragma once
// The order in which the batch's workers start its jobs: the longest first. With a few workers
// and one long job (ideal-gas: 300 disks, several times as long as any other preset's job),
// starting it last leaves the other workers idle while it runs alone; started first, the short
// jobs fill in around it (longest processing time first, the classic greedy rule for scheduling
// independent jobs on identical machines).
#include <cstddef>
#include <vector>

#include "app/batch_plan.hpp"
#include "app/batch_worker.hpp"

namespace collide::app {

// What a job's scene is, as far as its cost and its outputs' sizes go; loaded once per job.
struct JobShape {
  bool loaded = false;      // false: the scene did not load (its worker will fail at once)
  double duration_s = 0.0;  // the batch's --duration, else the scene's
  std::size_t bodies = 0;
  int dimensions = 1;
};

// Each job's scene, loaded (with its overrides) to know its shape.
std::vector<JobShape> jobShapes(const std::vector<BatchJob>& jobs, const JobSettings& settings);

// A job's work relative to the others of the same batch (same size and formats): the frames its
// video has (1 without a video) times (1 + bodies / 70), fitted to each preset's job time in a
// batch of every preset (bench/results.md, "Figures behind the code"). A scene that does not load
// counts 0 (its worker fails at once).
double estimatedWork(const BatchJob& job, const JobSettings& settings);
double estimatedWork(const JobShape& shape, const JobSettings& settings);

// Positions into `jobs`, the largest estimatedWork first; equal estimates keep the batch's order.
std::vector<std::size_t> longestFirst(const std::vector<BatchJob>& jobs,
                                      const JobSettings& settings);
std::vector<std::size_t> longestFirst(const std::vector<JobShape>& shapes,
                                      const JobSettings& settings);

}  // namespace collide::app
