// --jobs as a core budget (app/batch_threads.hpp): how many workers, and how each runs its jobs.
#include "app/batch_threads.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace collide::app {
namespace {

TEST(BatchThreadsTest, JobsOneIsOneWorkerOnOneThread) {
  // A teacher on a shared 8-core lab machine asks for one core.
  const WorkerThreads plan = planWorkerThreads(1, 8, 19);
  EXPECT_EQ(plan.workers, 1);
  EXPECT_EQ(plan.cores_each, 1);
  EXPECT_FALSE(plan.overlap);
  EXPECT_EQ(plan.encoder_threads, 1);
  EXPECT_EQ(plan.rasterizer_threads, 0) << "llvmpipe draws on the calling thread";
}

TEST(BatchThreadsTest, TheDefaultIsOneSingleThreadedWorkerPerCore) {
  const WorkerThreads plan = planWorkerThreads(std::nullopt, 2, 19);
  EXPECT_EQ(plan.workers, 2);
  EXPECT_EQ(plan.cores_each, 1);
  EXPECT_FALSE(plan.overlap);
}

TEST(BatchThreadsTest, FewerJobsThanTheBudgetGiveEachWorkerMoreCoresAndItsOverlap) {
  // 8 cores for 2 jobs: 2 workers of 4 cores, each with a render's own threads sized to 4.
  const WorkerThreads plan = planWorkerThreads(8, 8, 2);
  EXPECT_EQ(plan.workers, 2);
  EXPECT_EQ(plan.cores_each, 4);
  EXPECT_TRUE(plan.overlap);
  EXPECT_EQ(plan.encoder_threads, 4);
  EXPECT_EQ(plan.rasterizer_threads, 4);
  // One job: the whole machine, as `collide render` would use it.
  EXPECT_EQ(planWorkerThreads(std::nullopt, 2, 1).cores_each, 2);
}

TEST(BatchThreadsTest, TheBudgetIsWhatTheUserSaysEvenAboveTheCores) {
  // As make -j4 on 2 cores: four workers, each on one thread.
  const WorkerThreads plan = planWorkerThreads(4, 2, 19);
  EXPECT_EQ(plan.workers, 4);
  EXPECT_EQ(plan.cores_each, 1);
}

TEST(BatchThreadsTest, NeverMoreCoresBusyThanTheBudgetAndNoWorkerWithoutAJob) {
  for (int cores = 1; cores <= 8; ++cores) {
    for (int budget = 1; budget <= 17; ++budget) {
      for (std::size_t jobs = 0; jobs <= 20; ++jobs) {
        const WorkerThreads plan = planWorkerThreads(budget, cores, jobs);
        SCOPED_TRACE(testing::Message()
                     << budget << " cores asked, " << cores << " cores, " << jobs << " jobs");
        EXPECT_LE(plan.workers * plan.cores_each, budget);
        // As many workers as the budget allows, but none idle for want of a job (a shard with
        // no jobs still starts its one worker, which then has nothing to do).
        EXPECT_EQ(plan.workers, std::min<int>(budget, std::max<int>(1, static_cast<int>(jobs))));
        // The budget's remainder after an even split is less than one more core for each.
        EXPECT_LT(budget - plan.workers * plan.cores_each, plan.workers);
        EXPECT_EQ(plan.overlap, plan.cores_each >= 2);
        EXPECT_EQ(plan.encoder_threads, plan.cores_each);
        EXPECT_EQ(plan.rasterizer_threads, plan.overlap ? plan.cores_each : 0);
      }
    }
  }
}

TEST(BatchThreadsTest, UsableCoresIsAtLeastOne) {
  EXPECT_GE(usableCores(), 1);
}

}  // namespace
}  // namespace collide::app
