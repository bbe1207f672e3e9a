#include "app/batch_manifest.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "app/version.hpp"
#include "output/text_output.hpp"
#include "report/json_writer.hpp"

namespace collide::app {
namespace {

// A value reported as text: a number where it reads as one (a sweep value, a preset's parameter),
// else the text itself.
void numberOrText(report::JsonWriter& json, const std::string& text) {
  double number = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, number);
  if (error == std::errc() && stop == end && std::isfinite(number)) {
    json.value(number);
  } else {
    json.value(text);
  }
}

}  // namespace

std::string batchFingerprint(const std::vector<std::string>& worker_arguments) {
  // Options with a value, as "--output=DIR" or "-o DIR", and flags, that change no job's files.
  static const std::set<std::string> kIgnoredWithValue = {"-o", "--output", "--backend",
                                                          "--worker-cores"};
  static const std::set<std::string> kIgnoredFlags = {"--force", "--serve"};
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a's offset basis and prime
  for (std::size_t i = 0; i < worker_arguments.size(); ++i) {
    const std::string& argument = worker_arguments[i];
    const std::string name = argument.substr(0, argument.find('='));
    if (kIgnoredFlags.count(argument) > 0) continue;
    if (kIgnoredWithValue.count(name) > 0) {
      if (name == argument) ++i;  // the value is the next word
      continue;
    }
    for (const char c : argument + '\0') {
      hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    }
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

std::string manifestFileName(const Shard& shard) {
  if (shard.count == 1) return "manifest.json";
  return "manifest-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".json";
}

void writeManifest(const std::string& directory, const ManifestInfo& info,
                   const std::vector<BatchJob>& jobs, const std::vector<JobOutcome>& outcomes) {
  int succeeded = 0;
  for (const JobOutcome& outcome : outcomes) succeeded += outcome.ok ? 1 : 0;
  const std::string path =
      (std::filesystem::path(directory) / manifestFileName(info.shard)).string();
  std::ostringstream unused;
  output::writeTextOutput(path, unused, [&](std::ostream& out) {
    report::JsonWriter json(out);
    json.beginObject();
    json.key("collide_version").value(kVersion);
    json.key("formats").beginArray();
    for (const std::string& format : info.formats) json.value(format);
    json.endArray();
    if (!info.langs.empty()) {
      json.key("langs").beginArray();
      for (const std::string& lang : info.langs) json.value(lang);
      json.endArray();
    }
    json.key("size").value(info.size);
    json.key("fps").value(info.fps);
    json.key("batch_fingerprint").value(info.fingerprint);
    json.key("shard").beginObject();
    json.key("index").value(info.shard.index).key("count").value(info.shard.count).endObject();
    json.key("total_jobs").value(info.total_jobs);
    json.key("jobs_in_this_run").value(static_cast<int>(jobs.size()));
    json.key("succeeded").value(succeeded);
    json.key("failed").value(static_cast<int>(jobs.size()) - succeeded);
    json.key("jobs").beginArray();
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      const BatchJob& job = jobs[i];
      const JobOutcome& outcome = outcomes[i];
      json.beginObject();
      json.key("index").value(job.index);
      json.key("scene").value(job.scene);
      json.key("stem").value(job.stem);
      const std::string& lang = !job.lang.empty() ? job.lang : outcome.lang;
      if (!lang.empty()) json.key("lang").value(lang);
      if (!outcome.name.empty()) json.key("name").value(outcome.name);
      if (!outcome.title.empty()) json.key("title").value(outcome.title);
      json.key("sweep").beginObject();
      for (const auto& [key, value] : job.sweep) numberOrText(json.key(key), value);
      json.endObject();
      json.key("overrides").beginArray();
      for (const scene::Override& change : job.overrides) json.value(change.origin);
      json.endArray();
      json.key("parameters").beginObject();
      for (const auto& [key, value] : outcome.parameters) numberOrText(json.key(key), value);
      json.endObject();
      json.key("status").value(outcome.ok ? "ok" : "failed");
      if (!outcome.ok) json.key("error").value(outcome.error);
      json.key("outputs").beginArray();
      for (const auto& [format, file] : outcome.outputs) {
        json.beginObject().key("format").value(format).key("path").value(file).endObject();
      }
      json.endArray();
      json.key("warnings").beginArray();
      for (const std::string& warning : outcome.warnings) json.value(warning);
      json.endArray();
      json.key("seconds").value(outcome.seconds);
      json.endObject();
    }
    json.endArray();
    json.endObject();
    out << "\n";
  });
}

}  // namespace collide::app
