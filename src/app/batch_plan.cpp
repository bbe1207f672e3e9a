#include "app/batch_plan.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include "core/error.hpp"
#include "text/language.hpp"

namespace collide::app {
namespace {

const std::vector<std::pair<BatchFormat, std::string>>& formatNames() {
  static const std::vector<std::pair<BatchFormat, std::string>> names = {
      {BatchFormat::kMp4, "mp4"},        {BatchFormat::kPng, "png"},
      {BatchFormat::kSvg, "svg"},        {BatchFormat::kPdf, "pdf"},
      {BatchFormat::kStrobe, "strobe"},  {BatchFormat::kCsv, "csv"},
      {BatchFormat::kJson, "json"},      {BatchFormat::kLesson, "lesson"},
      {BatchFormat::kWorking, "working"}};
  return names;
}

std::optional<double> parseNumber(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  if (result.ec != std::errc() || result.ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// 12 significant digits: removes the binary noise of A + k*STEP without losing a typed digit.
std::string sweepValueText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", value);
  double rounded = std::strtod(text, nullptr);
  if (rounded == 0.0) rounded = 0.0;  // no "-0"
  char shortest[32];
  const auto result = std::to_chars(shortest, shortest + sizeof shortest, rounded);
  return std::string(shortest, result.ptr);
}

// Output stems keep to letters, digits, '-', '_' and '.'.
std::string safeStem(std::string text) {
  for (char& c : text) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '-';
  }
  while (!text.empty() && text.front() == '.') text.erase(text.begin());
  return text.empty() ? "scene" : text;
}

std::string baseStem(const std::string& scene) {
  if (scene::findPreset(scene) != nullptr) return scene;
  return safeStem(std::filesystem::path(scene).stem().string());
}

bool stemEndsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// "manifest", "manifest-0-of-4": a stem whose .json would be the batch's manifest.
bool isManifestStem(const std::string& stem) {
  static const std::regex kManifest(R"(manifest(-[0-9]+-of-[0-9]+)?)");
  return stem.size() < 40 && std::regex_match(stem, kManifest);
}

// Whether the files of a job with stem `stem` could meet those of a stem already `claimed`:
// the same stem, or one that is the other's strobe picture ("x.strobe" + ".png" is x's
// "x.strobe.png"), or the manifest's.
bool clashes(const std::set<std::string>& claimed, const std::string& stem) {
  static const std::string kStrobe = ".strobe";
  return isManifestStem(stem) || claimed.count(stem) > 0 || claimed.count(stem + kStrobe) > 0 ||
         (stemEndsWith(stem, kStrobe) &&
          claimed.count(stem.substr(0, stem.size() - kStrobe.size())));
}

// Each scene's stem, unique across the batch: a scene keeps its own (the preset name or the
// file's stem) unless an earlier scene has it; then it gets the first "-2", "-3", ... that no scene
// has, nor will have by its own name ("a/x.toml b/x.toml c/x-2.toml": x, x-3, x-2).
std::vector<std::string> uniqueBaseStems(const std::vector<std::string>& names) {
  std::vector<std::string> natural;
  std::map<std::string, int> natural_later;  // own stems of the scenes not yet given one
  for (const std::string& name : names) {
    natural.push_back(baseStem(name));
    ++natural_later[natural.back()];
  }
  std::set<std::string> claimed;
  std::vector<std::string> stems;
  for (const std::string& own : natural) {
    --natural_later[own];
    std::string stem = own;
    for (int n = 2; clashes(claimed, stem) || (stem != own && natural_later[stem] > 0); ++n) {
      stem = own + "-" + std::to_string(n);
    }
    claimed.insert(stem);
    stems.push_back(stem);
  }
  return stems;
}

}  // namespace

std::string formatName(BatchFormat format) {
  for (const auto& [f, name] : formatNames()) {
    if (f == format) return name;
  }
  return "?";
}

std::string outputFileName(const std::string& stem, BatchFormat format) {
  switch (format) {
    case BatchFormat::kMp4:
      return stem + ".mp4";
    case BatchFormat::kPng:
      return stem + ".png";
    case BatchFormat::kSvg:
      return stem + ".svg";
    case BatchFormat::kPdf:
      return stem + ".pdf";
    case BatchFormat::kStrobe:
      return stem + ".strobe.png";
    case BatchFormat::kCsv:
      return stem + ".csv";
    case BatchFormat::kJson:
      return stem + ".json";
    case BatchFormat::kLesson:
      return stem + "/";
    case BatchFormat::kWorking:
      return stem + ".working.tex";
  }
  return stem;
}

std::string workingMarkdownName(const std::string& stem) {
  return stem + ".working.md";
}

std::vector<BatchFormat> parseFormats(const std::string& text) {
  const std::string allowed =
      "allowed: a comma-separated list of mp4, png, svg, pdf, strobe, csv, json, lesson, working";
  std::vector<BatchFormat> formats;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string word = text.substr(start, comma - start);
    const auto found = std::find_if(formatNames().begin(), formatNames().end(),
                                    [&](const auto& entry) { return entry.second == word; });
    if (found == formatNames().end()) {
      throw core::InputError("--formats: '" + text + "': '" + word + "' is not a format; " +
                             allowed);
    }
    if (std::find(formats.begin(), formats.end(), found->first) != formats.end()) {
      throw core::InputError("--formats: '" + text + "': '" + word + "' twice; " + allowed);
    }
    formats.push_back(found->first);
    start = comma + 1;
  }
  return formats;
}

Sweep parseSweep(const std::string& text) {
  const std::string allowed =
      "allowed: KEY=FROM:TO:STEP (e.g. restitution=0:1:0.25) or KEY=V1,V2,... with numbers";
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) {
    throw core::InputError("--sweep: '" + text + "': not KEY=VALUES; " + allowed);
  }
  Sweep sweep;
  sweep.key = text.substr(0, equals);
  const std::string values = text.substr(equals + 1);
  const auto bad = [&](const std::string& why) {
    return core::InputError("--sweep: '" + text + "': " + why + "; " + allowed);
  };
  static const std::regex kRange(R"(([^:]+):([^:]+):([^:]+))");
  std::smatch match;
  if (std::regex_match(values, match, kRange)) {
    const auto from = parseNumber(match[1]), to = parseNumber(match[2]),
               step = parseNumber(match[3]);
    if (!from || !to || !step) throw bad("not three numbers");
    if (*step <= 0.0 || *to < *from) throw bad("needs FROM <= TO and STEP > 0");
    const double count = std::floor((*to - *from) / *step * (1.0 + 1e-12) + 1e-9) + 1.0;
    if (count > kMaxSweepValues)
      throw bad("more than " + std::to_string(kMaxSweepValues) + " values");
    for (int k = 0; k < static_cast<int>(count); ++k) {
      sweep.values.push_back(sweepValueText(*from + k * *step));
    }
    return sweep;
  }
  std::size_t start = 0;
  std::set<std::string> seen;
  while (start <= values.size()) {
    const std::size_t comma = std::min(values.find(',', start), values.size());
    const auto value = parseNumber(values.substr(start, comma - start));
    if (!value) throw bad("'" + values.substr(start, comma - start) + "' is not a number");
    const std::string value_text = sweepValueText(*value);
    if (!seen.insert(value_text).second) throw bad("the value " + value_text + " twice");
    sweep.values.push_back(value_text);
    if (sweep.values.size() > kMaxSweepValues) throw bad("too many values");
    start = comma + 1;
  }
  return sweep;
}

Shard parseShard(const std::string& text) {
  static const std::regex kPattern(R"((\d{1,6})/(\d{1,6}))");
  std::smatch match;
  Shard shard;
  if (std::regex_match(text, match, kPattern)) {
    shard.index = std::stoi(match[1]);
    shard.count = std::stoi(match[2]);
    if (shard.count >= 1 && shard.index < shard.count) return shard;
  }
  throw core::InputError("--shard: '" + text +
                         "': allowed: I/N with N >= 1 and 0 <= I < N (e.g. 0/4 ... 3/4)");
}

std::vector<std::string> parseLanguages(const std::string& text) {
  std::vector<std::string> tags;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string typed = text.substr(start, comma - start);
    start = comma + 1;
    const std::string tag = text::findLanguage(typed, "--langs").tag;
    if (std::find(tags.begin(), tags.end(), tag) != tags.end()) {
      throw core::InputError("--langs '" + text + "': " + tag +
                             " is named twice; allowed: each language once, e.g. en,de,ar");
    }
    tags.push_back(tag);
  }
  return tags;
}

std::vector<BatchJob> planBatch(const std::vector<std::string>& scenes, bool all_presets,
                                const std::vector<Sweep>& sweeps,
                                const std::vector<scene::Override>& overrides,
                                const std::vector<std::string>& langs) {
  std::vector<std::string> names = scenes;
  if (all_presets) {
    for (const scene::PresetInfo& info : scene::presetList()) {
      if (std::find(names.begin(), names.end(), info.name) == names.end()) {
        names.push_back(info.name);
      }
    }
  }
  if (names.empty()) {
    throw core::InputError(
        "batch: no scenes; allowed: one or more SCENE arguments or --all-presets");
  }
  double total = static_cast<double>(names.size());
  for (const Sweep& sweep : sweeps) total *= static_cast<double>(sweep.values.size());
  total *= static_cast<double>(std::max<std::size_t>(1, langs.size()));
  if (total > kMaxBatchJobs) {
    throw core::InputError("batch: " + std::to_string(static_cast<long long>(total)) +
                           " jobs; allowed: at most " + std::to_string(kMaxBatchJobs) +
                           " (split the batch)");
  }
  std::vector<BatchJob> jobs;
  const std::vector<std::string> bases = uniqueBaseStems(names);
  for (std::size_t n = 0; n < names.size(); ++n) {
    const std::string& name = names[n];
    const std::string& base = bases[n];
    // Odometer over the sweeps, the last one varying fastest.
    std::vector<std::size_t> digit(sweeps.size(), 0);
    for (bool more = true; more;) {
      BatchJob job;
      job.index = static_cast<int>(jobs.size());
      job.scene = name;
      job.stem = base;
      job.overrides = overrides;
      for (std::size_t s = 0; s < sweeps.size(); ++s) {
        const std::string& value = sweeps[s].values[digit[s]];
        job.sweep.emplace_back(sweeps[s].key, value);
        job.stem += "_" + safeStem(sweeps[s].key) + "-" + value;
        job.overrides.push_back({sweeps[s].key, value, "--sweep " + sweeps[s].key + "=" + value,
                                 scene::Override::Kind::kValue});
      }
      if (langs.empty()) {
        jobs.push_back(std::move(job));
      } else {
        for (const std::string& lang : langs) {
          BatchJob in_language = job;
          in_language.index = static_cast<int>(jobs.size());
          in_language.lang = lang;
          in_language.stem += "." + lang;
          jobs.push_back(std::move(in_language));
        }
      }
      more = false;
      for (std::size_t s = sweeps.size(); s-- > 0;) {
        if (++digit[s] < sweeps[s].values.size()) {
          more = true;
          break;
        }
        digit[s] = 0;
      }
    }
  }
  return jobs;
}

std::vector<BatchJob> shardJobs(const std::vector<BatchJob>& jobs, const Shard& shard) {
  std::vector<BatchJob> mine;
  for (const BatchJob& job : jobs) {
    if (job.index % shard.count == shard.index) mine.push_back(job);
  }
  return mine;
}

}  // namespace collide::app
