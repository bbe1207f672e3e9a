// SPDX-License-Identifier: MIT
#pragma once
// `collide batch --merge DIR`: the shards' manifests (manifest-I-of-N.json) of one batch read
// back, checked against each other and merged into DIR/manifest.json, with the same fields an
// unsharded run writes. What keeps the set from being whole is listed: jobs that failed, jobs that
// never ran (a task stopped while rendering), shards with no manifest (a task cancelled, killed or
// refused before work), and manifests of another split or batch, which are named, not merged.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace collide::app {

struct JobProblem {
  int index = 0;      // the job's place in the whole batch
  std::string stem;   // empty for a job of a missing shard
  std::string error;  // as the manifest says, or why the job has no entry
};

struct StrayManifest {
  std::string file;  // its name in the folder
  std::string why;   // "a split of 8, not 32", "another batch", "not a manifest: ..."
};

struct MergedSet {
  int shard_count = 0;      // N of the split merged
  int total_jobs = 0;       // in the whole batch
  std::string fingerprint;  // the batch's, as its manifests carry it
  std::vector<std::string> merged_files;
  std::vector<int> missing_shards;  // I of each shard with no manifest
  std::vector<JobProblem> failed;   // rendered and failed
  std::vector<JobProblem> not_run;  // in a manifest as not run, or in a missing shard
  std::vector<StrayManifest> strays;
  nlohmann::ordered_json manifest;  // what DIR/manifest.json gets

  bool whole() const { return missing_shards.empty() && failed.empty() && not_run.empty(); }
  // The shards to render again so that the set is whole, in order.
  std::vector<int> shardsToRerun() const;
};

// Reads every manifest-I-of-N.json in `directory` and merges the split that most of them share.
// Throws core::InputError when `directory` is not a folder or holds no shard manifest that can be
// read.
MergedSet mergeShardManifests(const std::string& directory);

// Writes `set.manifest` to DIR/manifest.json (temporary name, then rename).
void writeMergedManifest(const std::string& directory, const MergedSet& set);

// The report for the terminal: a summary line, then one line per problem, then the command that
// reruns what is missing ("rerun: sbatch --array=1,3 ... (collide batch ... --shard 1/4, 3/4)").
std::string mergeReport(const MergedSet& set);

}  // namespace collide::app
