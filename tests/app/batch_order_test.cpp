// The order the batch starts its jobs in: the most work first (batch_order.hpp), and a pool that
// starts them in that order.
#include "app/batch_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "app/batch_pool.hpp"
#include "scene/scene_io.hpp"

namespace collide::app {
namespace {

JobSettings videoAndStill(double duration_s) {
  JobSettings settings;
  settings.formats = {BatchFormat::kMp4, BatchFormat::kPng};
  settings.size = {640, 360};
  settings.fps = 30;
  settings.duration_s = duration_s;
  return settings;
}

std::size_t bodiesOf(const BatchJob& job) {
  return scene::loadScene(job.scene, job.overrides).bodies.size();
}

TEST(BatchOrderTest, EveryPresetWithTheMostBodiesFirstTiesInBatchOrder) {
  const std::vector<BatchJob> jobs = planBatch({}, true, {}, {});
  ASSERT_GE(jobs.size(), 10u);
  const std::vector<std::size_t> order = longestFirst(jobs, videoAndStill(5.0));
  // The same duration for every job: the work grows with the bodies alone, so the order is the
  // presets sorted by their body count (read from the scenes here), most first, stable.
  std::vector<std::size_t> expected(jobs.size());
  std::iota(expected.begin(), expected.end(), std::size_t{0});
  std::stable_sort(expected.begin(), expected.end(), [&](std::size_t a, std::size_t b) {
    return bodiesOf(jobs[a]) > bodiesOf(jobs[b]);
  });
  EXPECT_EQ(order, expected);
  EXPECT_EQ(jobs[order.front()].scene, "ideal-gas");
}

TEST(BatchOrderTest, WorkGrowsWithTheVideosFramesAndNotWithoutAVideo) {
  const BatchJob job = planBatch({"worked-example"}, false, {}, {}).front();
  EXPECT_DOUBLE_EQ(estimatedWork(job, videoAndStill(10.0)),
                   2.0 * estimatedWork(job, videoAndStill(5.0)));
  JobSettings still = videoAndStill(10.0);
  still.formats = {BatchFormat::kPng, BatchFormat::kJson};
  JobSettings shorter = still;
  shorter.duration_s = 5.0;
  EXPECT_DOUBLE_EQ(estimatedWork(job, still), estimatedWork(job, shorter));
  EXPECT_GT(estimatedWork(job, still), 0.0);
}

TEST(BatchOrderTest, ASceneThatDoesNotLoadGoesLastAndEqualJobsKeepTheirOrder) {
  const std::vector<BatchJob> jobs = planBatch(
      {"worked-example", "no-such-scene-file.toml", "worked-example", "elastic"}, false, {}, {});
  ASSERT_EQ(jobs.size(), 4u);
  const std::vector<std::size_t> order = longestFirst(jobs, videoAndStill(5.0));
  EXPECT_EQ(estimatedWork(jobs[1], videoAndStill(5.0)), 0.0);
  // worked-example and elastic have two bodies each: equal work, batch order.
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 2, 3, 1}));
}

TEST(BatchPoolTest, WithOneWorkerJobsStartAndEndInTheGivenOrder) {
  const std::vector<BatchJob> jobs = planBatch({"a", "b", "c", "d"}, false, {}, {});
  PoolSettings pool;
  pool.executable = "/bin/sh";
  pool.workers = 1;
  pool.start_order = {2, 0, 3, 1};
  pool.arguments = [](const BatchJob& job) {
    return std::vector<std::string>{"-c", "echo scene " + job.stem};
  };
  std::vector<int> ended;
  pool.on_done = [&](const JobOutcome& outcome) { ended.push_back(outcome.index); };
  const std::vector<JobOutcome> outcomes = runWorkerPool(jobs, pool);
  EXPECT_EQ(ended, (std::vector<int>{jobs[2].index, jobs[0].index, jobs[3].index, jobs[1].index}));
  // Outcomes come back in the batch's order whatever the start order.
  ASSERT_EQ(outcomes.size(), 4u);
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    EXPECT_TRUE(outcomes[i].ok) << outcomes[i].error;
    EXPECT_EQ(outcomes[i].index, jobs[i].index);
    EXPECT_EQ(outcomes[i].name, jobs[i].stem);
  }
}

}  // namespace
}  // namespace collide::app
