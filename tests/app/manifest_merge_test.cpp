// SPDX-License-Identifier: MIT
// `collide batch --merge`: shard manifests written here by hand (a batch of 6 jobs in 3 shards)
// are merged, and what keeps the set from being whole is named: a missing shard, a failed job, a
// job not run, a manifest of another split or batch, a file that is not a manifest.
#include "app/manifest_merge.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/error.hpp"
#include "scratch.hpp"

namespace collide::app {
namespace {
using Json = nlohmann::ordered_json;

constexpr int kJobs = 6;
constexpr int kShards = 3;

Json job(int index, const std::string& status = "ok", const std::string& error = "") {
  Json entry = {{"index", index},
                {"scene", "elastic"},
                {"stem", "elastic_restitution-" + std::to_string(index)},
                {"status", status}};
  if (!error.empty()) entry["error"] = error;
  entry["outputs"] = Json::array({{{"format", "png"}, {"path", "x.png"}}});
  entry["seconds"] = 0.5;
  return entry;
}

// Shard `index` of `count` of a batch of `total` jobs, every job ok unless `jobs` is given.
Json shardManifest(int index, int count, int total = kJobs,
                   const std::string& fingerprint = "0123456789abcdef", Json jobs = nullptr) {
  if (jobs.is_null()) {
    jobs = Json::array();
    for (int k = index; k < total; k += count) jobs.push_back(job(k));
  }
  return {{"collide_version", "0.1.0"},
          {"formats", {"png"}},
          {"size", "160x90"},
          {"fps", 60},
          {"batch_fingerprint", fingerprint},
          {"shard", {{"index", index}, {"count", count}}},
          {"total_jobs", total},
          {"jobs_in_this_run", jobs.size()},
          {"succeeded", jobs.size()},
          {"failed", 0},
          {"jobs", jobs}};
}

class ManifestMergeTest : public ::testing::Test {
 protected:
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_.file(name)) << text;
  }
  void write(int index, int count, const Json& manifest) {
    write("manifest-" + std::to_string(index) + "-of-" + std::to_string(count) + ".json",
          manifest.dump(2));
  }
  void writeWholeSplit() {
    for (int shard = 0; shard < kShards; ++shard)
      write(shard, kShards, shardManifest(shard, kShards));
  }
  std::string dir() const { return dir_.path().string(); }

  test::ScratchDir dir_{"collide_manifest_merge_"};
};

TEST_F(ManifestMergeTest, AWholeSplitMergesToEveryJobInOrderAsOneUnshardedManifest) {
  writeWholeSplit();
  const MergedSet set = mergeShardManifests(dir());
  EXPECT_TRUE(set.whole());
  EXPECT_TRUE(set.shardsToRerun().empty());
  EXPECT_EQ(set.shard_count, kShards);
  ASSERT_EQ(set.manifest["jobs"].size(), static_cast<std::size_t>(kJobs));
  for (int k = 0; k < kJobs; ++k) EXPECT_EQ(set.manifest["jobs"][k]["index"], k);
  // The fields of an unsharded run's manifest: the batch as its one shard, counts of the whole.
  EXPECT_EQ(set.manifest["shard"], Json({{"index", 0}, {"count", 1}}));
  EXPECT_EQ(set.manifest["jobs_in_this_run"], kJobs);
  EXPECT_EQ(set.manifest["succeeded"], kJobs);
  EXPECT_EQ(set.manifest["failed"], 0);
  EXPECT_EQ(set.manifest["batch_fingerprint"], "0123456789abcdef");
  EXPECT_EQ(set.merged_files.size(), static_cast<std::size_t>(kShards));
  EXPECT_EQ(mergeReport(set).find("rerun"), std::string::npos) << mergeReport(set);
}

TEST_F(ManifestMergeTest, AMissingShardAFailedJobAndAStrayOfAnotherSplitAreEachReported) {
  Json shard1 = Json::array({job(1), job(4, "failed", "cannot write x.png: disk full")});
  write(0, kShards, shardManifest(0, kShards));
  write(1, kShards, shardManifest(1, kShards, kJobs, "0123456789abcdef", shard1));
  write(0, 2, shardManifest(0, 2));  // a split of 2 left over from an earlier run
  const MergedSet set = mergeShardManifests(dir());

  EXPECT_FALSE(set.whole());
  EXPECT_EQ(set.missing_shards, std::vector<int>({2}));
  ASSERT_EQ(set.failed.size(), 1u);
  EXPECT_EQ(set.failed[0].index, 4);
  // The missing shard's jobs, 2 and 5 (k % 3 == 2), are in the merged manifest as not run.
  ASSERT_EQ(set.not_run.size(), 2u);
  EXPECT_EQ(set.not_run[0].index, 2);
  EXPECT_EQ(set.not_run[1].index, 5);
  EXPECT_EQ(set.manifest["jobs"].size(), static_cast<std::size_t>(kJobs));
  EXPECT_EQ(set.manifest["jobs"][5]["status"], "failed");
  EXPECT_EQ(set.manifest["succeeded"], kJobs - 3);
  ASSERT_EQ(set.strays.size(), 1u);
  EXPECT_EQ(set.strays[0].file, "manifest-0-of-2.json");
  EXPECT_EQ(set.strays[0].why, "a split of 2, not 3");
  // Shard 1 (its failed job) and shard 2 (missing) rerun; shard 0 is whole.
  EXPECT_EQ(set.shardsToRerun(), std::vector<int>({1, 2}));
  const std::string report = mergeReport(set);
  EXPECT_NE(report.find("--array=1,2 SCRIPT"), std::string::npos) << report;
  EXPECT_NE(report.find("--shard 1/3, 2/3)"), std::string::npos) << report;
  EXPECT_NE(report.find("disk full"), std::string::npos) << report;
  EXPECT_NE(report.find("missing: shard 2/3 ("), std::string::npos) << report;
}

TEST_F(ManifestMergeTest, JobsStoppedBeforeTheyRanAreNotRunAndTheirShardRerun) {
  Json shard2 = Json::array({job(2), job(5, "failed", "not run: interrupted")});
  write(0, kShards, shardManifest(0, kShards));
  write(1, kShards, shardManifest(1, kShards));
  write(2, kShards, shardManifest(2, kShards, kJobs, "0123456789abcdef", shard2));
  const MergedSet set = mergeShardManifests(dir());
  EXPECT_TRUE(set.failed.empty());
  ASSERT_EQ(set.not_run.size(), 1u);
  EXPECT_EQ(set.not_run[0].index, 5);
  EXPECT_EQ(set.shardsToRerun(), std::vector<int>({2}));
}

TEST_F(ManifestMergeTest, AManifestOfAnotherBatchOrNoManifestAtAllIsNamedNotMerged) {
  writeWholeSplit();
  write(1, kShards, shardManifest(1, kShards, kJobs, "fedcba9876543210"));  // replaced by another
  write("manifest-5-of-3.json", "{}");
  write("manifest-7-of-9.json", "{\"shard\": ");  // cut short
  const MergedSet set = mergeShardManifests(dir());
  std::set<std::string> strays;
  for (const StrayManifest& stray : set.strays) strays.insert(stray.file + ": " + stray.why);
  EXPECT_EQ(strays.size(), 3u);
  EXPECT_TRUE(
      strays.count("manifest-1-of-3.json: another batch (other scenes, sweeps or "
                   "settings)"))
      << *strays.begin();
  EXPECT_TRUE(strays.count("manifest-7-of-9.json: not a manifest: not valid JSON"));
  EXPECT_EQ(set.missing_shards, std::vector<int>({1}));
}

TEST_F(ManifestMergeTest, AFolderWithoutShardManifestsIsBadInput) {
  write("manifest.json", shardManifest(0, 1).dump());
  EXPECT_THROW(mergeShardManifests(dir()), core::InputError);
  EXPECT_THROW(mergeShardManifests(dir_.file("no-such-folder")), core::InputError);
}

}  // namespace
}  // namespace collide::app
