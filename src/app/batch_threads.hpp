#pragma once
// `collide batch --jobs N` is a core budget, as make's and ninja's -j are: the batch keeps at most
// N cores busy, so a teacher on a shared lab machine who says --jobs 1 gets one core. The budget
// is split evenly among the worker processes. A worker whose share is one core does all of a
// job's work on one thread: it composes, draws (llvmpipe rasterising on the calling thread,
// LP_NUM_THREADS=0), converts and encodes (x264 with one thread) in turn. A worker with a larger
// share keeps a render's own overlap (compose-ahead, conversion and encoding threads), with x264
// and llvmpipe sized to its share. A pure function of the numbers, so tests need no machine.
#include <cstddef>
#include <optional>

namespace collide::app {

struct WorkerThreads {
  int workers = 1;             // worker processes
  int cores_each = 1;          // cores each worker may keep busy
  bool overlap = false;        // compose, draw and encode on threads of their own (cores_each >= 2)
  int encoder_threads = 1;     // x264 threads of each worker's MP4
  int rasterizer_threads = 0;  // llvmpipe's LP_NUM_THREADS; 0: it draws on the calling thread
};

// How a worker whose share is `cores_each` (>= 1) cores runs its jobs; `workers` is left at 1.
WorkerThreads workerThreads(int cores_each);

// The plan for a batch of `job_count` jobs on a machine with `cores` cores (>= 1): `jobs` is the
// --jobs budget (none: one per core, the default). At most one worker per job, so that a batch
// of one job still gets the whole budget.
WorkerThreads planWorkerThreads(std::optional<int> jobs, int cores, std::size_t job_count);

// The cores this process may run on (its CPU affinity, which a cluster scheduler such as Slurm
// narrows), at least 1.
int usableCores();

}  // namespace collide::app
