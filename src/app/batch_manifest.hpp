#pragma once
// DIR/manifest.json (or DIR/manifest-I-of-N.json for a shard): every job of the batch (or shard)
// with its scene, parameters, status and outputs, so a course's set can be checked and re-run.
#include <string>
#include <vector>

#include "app/batch_plan.hpp"
#include "app/batch_pool.hpp"

namespace collide::app {

struct ManifestInfo {
  std::vector<std::string> formats;  // as asked, e.g. {"mp4", "png"}
  std::string size;                  // "1280x720"
  int fps = 60;
  Shard shard;
  int total_jobs = 0;              // in the whole, unsharded batch
  std::vector<std::string> langs;  // --langs, as tags; empty: not given
  std::string fingerprint;         // batchFingerprint: the same for every shard of one batch
};

// 16 hex digits that tell one batch from another: a hash (FNV-1a, 64 bits) of the arguments that
// decide its jobs and their files (`worker_arguments`: scenes, sweeps, formats, size, every
// setting), leaving out those that do not (the output folder, the backend, --force, the cores).
// `collide batch --merge` merges only manifests of the same batch.
std::string batchFingerprint(const std::vector<std::string>& worker_arguments);

// "manifest.json", or "manifest-I-of-N.json" when the batch is split into N > 1 shards (so
// shards writing into one shared directory do not overwrite one another's manifest).
std::string manifestFileName(const Shard& shard);

// Writes the manifest into `directory` (temporary name, then rename). `jobs` and `outcomes` are
// parallel, in job order. Paths in it are relative to the directory.
void writeManifest(const std::string& directory, const ManifestInfo& info,
                   const std::vector<BatchJob>& jobs, const std::vector<JobOutcome>& outcomes);

}  // namespace collide::app
