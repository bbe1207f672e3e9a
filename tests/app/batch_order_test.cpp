// The order the batch starts its jobs in: the most work first (batch_order.hpp), and a pool that
// starts them in that order.
#include "app/batch_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

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

// Stems are unique across the batch however scene files are named: a later scene whose stem an
// earlier one has gets the first "-N" that no scene has by its own name; none is the manifest's
// or another job's strobe picture ("x.strobe" + ".png" is x's "x.strobe.png").
TEST(BatchPlanTest, StemsAreUniqueWhateverTheSceneFilesAreNamed) {
  const auto stems = [](const std::vector<std::string>& scenes) {
    std::vector<std::string> out;
    for (const BatchJob& job : planBatch(scenes, false, {}, {})) out.push_back(job.stem);
    return out;
  };
  EXPECT_EQ(stems({"a/x.toml", "b/x.toml", "c/x-2.toml"}),
            (std::vector<std::string>{"x", "x-3", "x-2"}));
  EXPECT_EQ(stems({"a/x.toml", "b/x.toml", "c/x.toml"}),
            (std::vector<std::string>{"x", "x-2", "x-3"}));
  EXPECT_EQ(stems({"a/manifest.toml"}), (std::vector<std::string>{"manifest-2"}));
  EXPECT_EQ(stems({"a/x.toml", "b/x.strobe.toml"}), (std::vector<std::string>{"x", "x.strobe-2"}));
  EXPECT_EQ(stems({"worked-example", "worked-example"}),
            (std::vector<std::string>{"worked-example", "worked-example-2"}));
}

// A stand-in worker speaking the pool's protocol (batch_pool.hpp): for each job it reports the
// scene "jobINDEX" and its process id as the title; job 1 fails (exit 3, an error line), job 2
// dies by SIGKILL.
PoolSettings shellPool(int workers) {
  PoolSettings pool;
  pool.executable = "/bin/sh";
  pool.workers = workers;
  pool.arguments = {
      "-c",
      "while read -r index log <&3; do"
      "  printf 'scene \"job%s\"\\ntitle \"%s\"\\n' \"$index\" $$ >> \"$log\";"
      "  if [ \"$index\" = 1 ]; then echo 'collide: job 1 broke' >> \"$log\"; exit 3; fi;"
      "  if [ \"$index\" = 2 ]; then kill -KILL $$; fi;"
      "  echo done >&3;"
      "done"};
  return pool;
}

TEST(BatchPoolTest, WithOneWorkerJobsStartAndEndInTheGivenOrder) {
  const std::vector<BatchJob> jobs = planBatch({"a", "b", "c", "d"}, false, {}, {});
  PoolSettings pool = shellPool(1);
  pool.start_order = {3, 0, 2, 1};
  std::vector<int> ended;
  pool.on_done = [&](const JobOutcome& outcome) { ended.push_back(outcome.index); };
  const std::vector<JobOutcome> outcomes = runWorkerPool(jobs, pool);
  EXPECT_EQ(ended, (std::vector<int>{jobs[3].index, jobs[0].index, jobs[2].index, jobs[1].index}));
  // Outcomes come back in the batch's order whatever the start order.
  ASSERT_EQ(outcomes.size(), 4u);
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    EXPECT_EQ(outcomes[i].index, jobs[i].index);
    EXPECT_EQ(outcomes[i].name, "job" + std::to_string(jobs[i].index));
  }
}

TEST(BatchPoolTest, AWorkerRunsJobsInTurnUntilOneFailsAndTheNextGetsAFreshOne) {
  const std::vector<BatchJob> jobs = planBatch({"a", "b", "c", "d", "e"}, false, {}, {});
  ASSERT_EQ(jobs[1].index, 1);
  ASSERT_EQ(jobs[2].index, 2);
  const std::vector<JobOutcome> outcomes = runWorkerPool(jobs, shellPool(1));
  ASSERT_EQ(outcomes.size(), 5u);
  EXPECT_TRUE(outcomes[0].ok) << outcomes[0].error;
  EXPECT_FALSE(outcomes[1].ok);
  EXPECT_EQ(outcomes[1].error, "job 1 broke");
  EXPECT_FALSE(outcomes[2].ok);
  EXPECT_NE(outcomes[2].error.find("worker was killed by signal 9 (Killed)"), std::string::npos)
      << outcomes[2].error;
  // Its report lines are no part of the message.
  EXPECT_EQ(outcomes[2].error.find("title"), std::string::npos) << outcomes[2].error;
  EXPECT_TRUE(outcomes[3].ok) << outcomes[3].error;
  EXPECT_TRUE(outcomes[4].ok) << outcomes[4].error;
  // Jobs 0 and 1 ran in the first worker, 2 in the second, 3 and 4 in the third.
  EXPECT_EQ(outcomes[0].title, outcomes[1].title);
  EXPECT_NE(outcomes[1].title, outcomes[2].title);
  EXPECT_NE(outcomes[2].title, outcomes[3].title);
  EXPECT_NE(outcomes[0].title, outcomes[3].title);
  EXPECT_EQ(outcomes[3].title, outcomes[4].title);
}

TEST(BatchPoolTest, TwoWorkersShareTheJobsAndEveryJobEndsOnce) {
  const std::vector<BatchJob> jobs = planBatch({"a", "d", "e", "f", "g", "h"}, false, {}, {});
  std::vector<int> ended;
  PoolSettings pool = shellPool(2);
  pool.on_done = [&](const JobOutcome& outcome) { ended.push_back(outcome.index); };
  // Index 1 and 2 fail (above); the rest succeed, in two worker processes.
  const std::vector<JobOutcome> outcomes = runWorkerPool(jobs, pool);
  std::sort(ended.begin(), ended.end());
  EXPECT_EQ(ended, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  std::set<std::string> processes;
  for (const JobOutcome& outcome : outcomes) {
    if (outcome.index != 1 && outcome.index != 2) {
      EXPECT_TRUE(outcome.ok) << outcome.index << ": " << outcome.error;
    }
    processes.insert(outcome.title);
  }
  EXPECT_LE(processes.size(), 4u) << "2 workers, and one more after each of the 2 failures";
}

}  // namespace
}  // namespace collide::app
