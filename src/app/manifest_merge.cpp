// SPDX-License-Identifier: MIT
#include "app/manifest_merge.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

#include "core/bounded_read.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/text_output.hpp"

namespace collide::app {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
namespace {

// A manifest of a few thousand jobs is a few megabytes; anything far larger is not one.
constexpr std::size_t kMaxManifestBytes = std::size_t{256} << 20;
constexpr const char* kNotRunPrefix = "not run";

std::string quoted(const std::string& typed) {
  return "'" + core::echoTyped(typed) + "'";
}

struct ShardManifest {
  std::string file;
  int index = 0;
  int count = 0;
  std::string fingerprint;
  int total_jobs = 0;
  Json json;
};

// The fields a shard manifest must have for merging, checked against its file name.
std::optional<std::string> shardManifestProblem(const Json& json, int index, int count) {
  if (!json.is_object()) return "not a JSON object";
  const auto shard = json.find("shard");
  if (shard == json.end() || !shard->is_object() || shard->value("index", -1) != index ||
      shard->value("count", -1) != count) {
    return "its \"shard\" is not " + std::to_string(index) + "/" + std::to_string(count);
  }
  if (!json.contains("total_jobs") || !json["total_jobs"].is_number_integer()) {
    return "no \"total_jobs\"";
  }
  if (!json.contains("jobs") || !json["jobs"].is_array()) return "no \"jobs\" list";
  for (const Json& job : json["jobs"]) {
    if (!job.is_object() || !job.contains("index") || !job["index"].is_number_integer() ||
        !job.contains("status") || !job["status"].is_string()) {
      return "a job without \"index\" or \"status\"";
    }
    const int job_index = job["index"].get<int>();
    if (job_index < 0 || job_index % count != index) {
      return "job " + std::to_string(job_index) + " does not belong to shard " +
             std::to_string(index) + "/" + std::to_string(count);
    }
  }
  return std::nullopt;
}

// Reads one manifest-I-of-N.json; a file that is not a shard manifest becomes a stray.
std::optional<ShardManifest> readShardManifest(const fs::path& path, int index, int count,
                                               std::vector<StrayManifest>& strays) {
  const std::string file = path.filename().string();
  const core::BoundedRead read = core::readBounded(path.string(), kMaxManifestBytes);
  if (read.outcome != core::ReadOutcome::kRead) {
    strays.push_back({file, "not read: " + core::describeRefusal(read, kMaxManifestBytes)});
    return std::nullopt;
  }
  ShardManifest manifest{file, index, count, "", 0, Json::parse(read.bytes, nullptr, false)};
  if (manifest.json.is_discarded()) {
    strays.push_back({file, "not a manifest: not valid JSON"});
    return std::nullopt;
  }
  if (const auto problem = shardManifestProblem(manifest.json, index, count)) {
    strays.push_back({file, "not a manifest: " + *problem});
    return std::nullopt;
  }
  manifest.fingerprint = manifest.json.value("batch_fingerprint", "");
  manifest.total_jobs = manifest.json["total_jobs"].get<int>();
  return manifest;
}

std::vector<ShardManifest> readShardManifests(const std::string& directory,
                                              std::vector<StrayManifest>& strays) {
  static const std::regex kName(R"(manifest-([0-9]{1,6})-of-([0-9]{1,6})\.json)");
  std::vector<ShardManifest> manifests;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    std::smatch match;
    if (!std::regex_match(name, match, kName)) continue;
    const int index = std::stoi(match[1].str());
    const int count = std::stoi(match[2].str());
    if (count < 2 || index >= count) {
      strays.push_back({name, "not a shard of a split (I must be below N, N at least 2)"});
      continue;
    }
    if (auto manifest = readShardManifest(entry.path(), index, count, strays)) {
      manifests.push_back(std::move(*manifest));
    }
  }
  if (error) {
    throw core::InputError("batch --merge: cannot read the folder " + quoted(directory) + ": " +
                           error.message());
  }
  std::sort(manifests.begin(), manifests.end(),
            [](const ShardManifest& a, const ShardManifest& b) { return a.file < b.file; });
  return manifests;
}

using SplitKey = std::tuple<int, std::string, int>;  // shard count, fingerprint, total jobs
SplitKey splitOf(const ShardManifest& manifest) {
  return {manifest.count, manifest.fingerprint, manifest.total_jobs};
}

// The split most manifests share (ties: the finer split); the others are named as strays.
std::vector<ShardManifest> chooseSplit(std::vector<ShardManifest> manifests,
                                       std::vector<StrayManifest>& strays) {
  std::map<SplitKey, int> members;
  for (const ShardManifest& manifest : manifests) ++members[splitOf(manifest)];
  SplitKey chosen = members.begin()->first;
  for (const auto& [key, count] : members) {
    if (count > members[chosen] ||
        (count == members[chosen] && std::get<0>(key) > std::get<0>(chosen))) {
      chosen = key;
    }
  }
  std::vector<ShardManifest> kept;
  for (ShardManifest& manifest : manifests) {
    if (splitOf(manifest) == chosen) {
      kept.push_back(std::move(manifest));
    } else if (manifest.count != std::get<0>(chosen)) {
      strays.push_back({manifest.file, "a split of " + std::to_string(manifest.count) + ", not " +
                                           std::to_string(std::get<0>(chosen))});
    } else {
      strays.push_back({manifest.file, "another batch (other scenes, sweeps or settings)"});
    }
  }
  return kept;
}

bool notRun(const Json& job) {
  return job.value("error", "").rfind(kNotRunPrefix, 0) == 0;
}

// Files each job of the kept manifests under its status; returns the jobs by index.
std::map<int, Json> collectJobs(const std::vector<ShardManifest>& kept, MergedSet& set) {
  std::map<int, Json> jobs;
  for (const ShardManifest& manifest : kept) {
    for (const Json& job : manifest.json["jobs"]) {
      const int index = job["index"].get<int>();
      if (index >= set.total_jobs) continue;
      jobs[index] = job;
      if (job["status"] == "ok") continue;
      JobProblem problem{index, job.value("stem", ""), job.value("error", "")};
      (notRun(job) ? set.not_run : set.failed).push_back(std::move(problem));
    }
  }
  return jobs;
}

// The jobs of the shards with no manifest, as jobs not run.
void addMissingShards(const std::vector<ShardManifest>& kept, std::map<int, Json>& jobs,
                      MergedSet& set) {
  std::vector<bool> present(static_cast<std::size_t>(set.shard_count), false);
  for (const ShardManifest& manifest : kept)
    present[static_cast<std::size_t>(manifest.index)] = true;
  for (int shard = 0; shard < set.shard_count; ++shard) {
    if (present[static_cast<std::size_t>(shard)]) continue;
    set.missing_shards.push_back(shard);
    const std::string why = std::string(kNotRunPrefix) + ": shard " + std::to_string(shard) + "/" +
                            std::to_string(set.shard_count) + " left no manifest";
    for (int index = shard; index < set.total_jobs; index += set.shard_count) {
      Json job;
      job["index"] = index;
      job["status"] = "failed";
      job["error"] = why;
      jobs[index] = std::move(job);
      set.not_run.push_back({index, "", why});
    }
  }
  const auto by_index = [](const JobProblem& a, const JobProblem& b) { return a.index < b.index; };
  std::sort(set.failed.begin(), set.failed.end(), by_index);
  std::sort(set.not_run.begin(), set.not_run.end(), by_index);
}

// The merged manifest: the shards' common fields in their order, the whole batch as its one
// shard, the job counts of the whole, every job in order, and the files it came from.
Json mergedManifest(const ShardManifest& first, const std::map<int, Json>& jobs,
                    const MergedSet& set) {
  int succeeded = 0;
  Json list = Json::array();
  for (const auto& [index, job] : jobs) {
    succeeded += job["status"] == "ok" ? 1 : 0;
    list.push_back(job);
  }
  Json merged = first.json;
  merged["shard"] = Json{{"index", 0}, {"count", 1}};
  merged["jobs_in_this_run"] = static_cast<int>(list.size());
  merged["succeeded"] = succeeded;
  merged["failed"] = static_cast<int>(list.size()) - succeeded;
  merged["jobs"] = std::move(list);
  merged["merged_from"] = set.merged_files;
  return merged;
}

std::string joined(const std::vector<int>& numbers, const std::string& separator,
                   const std::string& suffix = "") {
  std::string text;
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    text += (i > 0 ? separator : "") + std::to_string(numbers[i]) + suffix;
  }
  return text;
}

}  // namespace

std::vector<int> MergedSet::shardsToRerun() const {
  std::vector<int> shards = missing_shards;
  for (const std::vector<JobProblem>* problems : {&failed, &not_run}) {
    for (const JobProblem& problem : *problems) shards.push_back(problem.index % shard_count);
  }
  std::sort(shards.begin(), shards.end());
  shards.erase(std::unique(shards.begin(), shards.end()), shards.end());
  return shards;
}

MergedSet mergeShardManifests(const std::string& directory) {
  std::error_code error;
  if (!fs::is_directory(directory, error)) {
    throw core::InputError("batch --merge " + quoted(directory) +
                           ": not a folder; give the folder the shards wrote into (their -o)");
  }
  MergedSet set;
  std::vector<ShardManifest> manifests = readShardManifests(directory, set.strays);
  if (manifests.empty()) {
    throw core::InputError("batch --merge " + quoted(directory) +
                           ": no shard manifest (manifest-I-of-N.json) in it to merge");
  }
  std::vector<ShardManifest> kept = chooseSplit(std::move(manifests), set.strays);
  set.shard_count = kept.front().count;
  set.fingerprint = kept.front().fingerprint;
  set.total_jobs = kept.front().total_jobs;
  for (const ShardManifest& manifest : kept) set.merged_files.push_back(manifest.file);
  std::map<int, Json> jobs = collectJobs(kept, set);
  addMissingShards(kept, jobs, set);
  set.manifest = mergedManifest(kept.front(), jobs, set);
  return set;
}

void writeMergedManifest(const std::string& directory, const MergedSet& set) {
  const std::string path = (fs::path(directory) / "manifest.json").string();
  std::ostringstream unused;
  output::writeTextOutput(path, unused,
                          [&](std::ostream& out) { out << set.manifest.dump(2) << "\n"; });
}

std::string mergeReport(const MergedSet& set) {
  std::ostringstream report;
  const int ok = set.total_jobs - static_cast<int>(set.failed.size() + set.not_run.size());
  report << "batch --merge: " << set.merged_files.size() << " of " << set.shard_count << " shards, "
         << ok << " of " << set.total_jobs << " jobs ok";
  if (!set.whole()) {
    report << "; " << set.failed.size() << " failed, " << set.not_run.size() << " not run";
  }
  report << "\n";
  for (const int shard : set.missing_shards) {
    report << "missing: shard " << shard << "/" << set.shard_count << " (manifest-" << shard
           << "-of-" << set.shard_count << ".json): its task left no manifest\n";
  }
  for (const JobProblem& job : set.failed) {
    report << "failed: job " << job.index << " " << job.stem << ": "
           << core::echoTyped(job.error, 300) << "\n";
  }
  for (const JobProblem& job : set.not_run) {
    if (!job.stem.empty()) report << "not run: job " << job.index << " " << job.stem << "\n";
  }
  for (const StrayManifest& stray : set.strays) {
    report << "not merged: " << stray.file << ": " << stray.why << "\n";
  }
  if (!set.whole()) {
    const std::vector<int> shards = set.shardsToRerun();
    report << "rerun: sbatch --array=" << joined(shards, ",") << " SCRIPT   (collide batch ... "
           << "--shard " << joined(shards, ", ", "/" + std::to_string(set.shard_count)) << ")\n";
  }
  return report.str();
}

}  // namespace collide::app
