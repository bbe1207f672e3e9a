#pragma once
// `collide batch`: the list of jobs (scenes x sweep values), the formats each job writes, and the
// deterministic share of the jobs that one shard renders. Everything here is pure: the same
// arguments give the same jobs, in the same order, with the same output names, on every machine,
// which is what lets shards on a cluster split one batch without talking to one another.
#include <string>
#include <vector>

#include "scene/scene_io.hpp"

namespace collide::app {

inline constexpr int kMaxBatchJobs = 100000;
inline constexpr int kMaxSweepValues = 1000;

enum class BatchFormat { kMp4, kPng, kSvg, kPdf, kStrobe, kCsv, kJson, kLesson, kWorking };

// "mp4", "png", ...: the name on the command line and in the manifest.
std::string formatName(BatchFormat format);
// The file a job writes for `format`: "<stem>.mp4", "<stem>.png", "<stem>.strobe.png", ...; a
// lesson (collide lesson) is the folder "<stem>/"; the working (collide solve) is
// "<stem>.working.tex", with "<stem>.working.md" beside it (workingMarkdownName).
std::string outputFileName(const std::string& stem, BatchFormat format);

std::string workingMarkdownName(const std::string& stem);

// Parses --formats "mp4,png,json" (no repeats). Throws core::InputError naming the bad word.
std::vector<BatchFormat> parseFormats(const std::string& text);

// One --sweep: a scene key and the values it takes, in order.
struct Sweep {
  std::string key;
  std::vector<std::string> values;  // as TOML numbers, e.g. "0.25"
};

// Parses "KEY=A:B:STEP" (A, A+STEP, ... up to B, each rounded to 12 significant digits so that
// 0:1:0.1 gives 0.3, not 0.30000000000000004) or "KEY=V1,V2,...". Throws core::InputError.
Sweep parseSweep(const std::string& text);

// --shard I/N: this process renders the jobs whose index k has k % N == I (0 <= I < N).
struct Shard {
  int index = 0;
  int count = 1;
};
Shard parseShard(const std::string& text);

struct BatchJob {
  int index = 0;      // position in the whole (unsharded) batch, from 0
  std::string scene;  // the SCENE argument: a preset name or a file path
  std::string stem;   // output file stem, unique within the batch
  std::vector<std::pair<std::string, std::string>> sweep;  // key, value of each sweep
  std::vector<scene::Override> overrides;  // the batch's --set and shortcuts, then the sweep
  std::string lang;  // BCP 47 tag from --langs; empty: the scene's own language
};

// Parses --langs "en,de,ar" into shipped languages' tags, in order. Throws core::InputError naming
// an unknown code (with the shipped languages) or one given twice.
std::vector<std::string> parseLanguages(const std::string& text);

// Every job of the batch, in order: scenes in the order given, then (with all_presets) every
// preset not already named, each crossed with every combination of sweep values (the first sweep
// varies slowest). Stems are the preset name or the file's stem, then "_KEY-VALUE" per sweep, with
// "-2", "-3", ... added to a scene whose stem an earlier one has, choosing one that no scene of
// the batch has by its own name, so no two jobs write the same file (nor the manifest). With
// `langs` (--langs) each of those jobs is made once per language, in the order given, ".TAG" ending
// the stem ("worked-example.de"). Throws core::InputError when there are no scenes or more than
// kMaxBatchJobs jobs.
std::vector<BatchJob> planBatch(const std::vector<std::string>& scenes, bool all_presets,
                                const std::vector<Sweep>& sweeps,
                                const std::vector<scene::Override>& overrides,
                                const std::vector<std::string>& langs = {});

// The jobs of `shard`, in order.
std::vector<BatchJob> shardJobs(const std::vector<BatchJob>& jobs, const Shard& shard);

}  // namespace collide::app
