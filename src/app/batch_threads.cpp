#include "app/batch_threads.hpp"

#include <sched.h>

#include <algorithm>
#include <thread>

#include "core/error.hpp"

namespace collide::app {

WorkerThreads workerThreads(int cores_each) {
  COLLIDE_ASSERT(cores_each >= 1, "workerThreads: need a core");
  WorkerThreads plan;
  plan.cores_each = cores_each;
  // On one core, threads only take turns: handing each frame from thread to thread costs wake-ups
  // and cache misses and gains nothing.
  plan.overlap = cores_each >= 2;
  plan.encoder_threads = cores_each;
  plan.rasterizer_threads = plan.overlap ? cores_each : 0;
  return plan;
}

WorkerThreads planWorkerThreads(std::optional<int> jobs, int cores, std::size_t job_count) {
  COLLIDE_ASSERT(cores >= 1 && (!jobs || *jobs >= 1), "planWorkerThreads: need a core");
  const int budget = jobs.value_or(cores);
  const int workers = static_cast<int>(
      std::min<std::size_t>(static_cast<std::size_t>(budget), std::max<std::size_t>(1, job_count)));
  // An uneven budget leaves its remainder unused rather than overcommit a worker: "at most N".
  WorkerThreads plan = workerThreads(budget / workers);
  plan.workers = workers;
  return plan;
}

int usableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace collide::app
