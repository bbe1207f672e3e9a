// collide batch SCENE... -o DIR: many scenes (and sweeps of their values) in many formats on a
// pool of worker processes, with DIR/manifest.json; --shard I/N for a cluster scheduler.
#include <malloc.h>
#include <sys/prctl.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>

#include "app/backend_option.hpp"
#include "app/batch_manifest.hpp"
#include "app/batch_order.hpp"
#include "app/batch_plan.hpp"
#include "app/batch_pool.hpp"
#include "app/batch_threads.hpp"
#include "app/batch_worker.hpp"
#include "app/command.hpp"
#include "app/lesson_pipeline.hpp"
#include "app/manifest_merge.hpp"
#include "app/output_checks.hpp"
#include "app/scene_options.hpp"
#include "app/simulation_progress.hpp"
#include "core/bounded_read.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/output_target.hpp"
#include "output/stop_signals.hpp"
#include "text/language.hpp"

namespace collide::app {
namespace fs = std::filesystem;
namespace {

constexpr int kMaxWorkers = 256;
// Seconds the batch parent has, after a stop signal, to see its workers stop (each within its own
// kStopGraceSeconds) and write the manifest.
constexpr unsigned kParentStopGraceSeconds = 4 * output::kStopGraceSeconds;
// Free heap top a one-thread worker keeps (see runWorker).
constexpr int kOneThreadTrimThreshold_bytes = 64 << 20;

std::string plain(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

class BatchCommand : public Command {
 public:
  explicit BatchCommand(CLI::App& root)
      : app_(*root.add_subcommand("batch", "Render many scenes, sweeps and formats in parallel")) {
    app_.add_option("SCENE", scenes_, "Preset names or scene files (.toml)");
    app_.add_option("-o,--output", directory_, "Output directory (created if missing)");
    app_.add_option(
        "--merge", merge_directory_,
        "Merge the shard manifests (manifest-I-of-N.json) in DIR into DIR/manifest.json "
        "and say what failed or is missing, and how to rerun it");
    jobs_option_ =
        app_.add_option("--jobs", jobs_,
                        "Cores to keep busy, 1 to 256, as make -j: N worker processes, or fewer "
                        "for fewer jobs, each on its share (default: one per core)");
    app_.add_option("--formats", formats_,
                    "Comma-separated: mp4, png, svg, pdf, strobe, csv, json, lesson (a folder, and "
                    "DIR/index.html), working (STEM.working.tex and STEM.working.md: the first "
                    "impact's working, as collide solve writes it)")
        ->capture_default_str();
    app_.add_flag("--all-presets", all_presets_, "Add every built-in preset to the scenes");
    app_.add_flag("--force", force_,
                  "Write the files even if one would be larger than 10 GB, or all of them more "
                  "than the free space left for them");
    app_.add_option("--langs", langs_,
                    "Comma-separated languages, each job made in each (STEM.TAG.mp4, ...): " +
                        text::shippedLanguageList());
    app_.add_option("--sweep", sweeps_,
                    "KEY=FROM:TO:STEP or KEY=V1,V2,...: one output per value (repeatable; "
                    "several sweeps give every combination)");
    app_.add_option("--shard", shard_, "I/N: render only jobs k with k % N == I (0 <= I < N)");
    size_.addTo(app_);
    app_.add_option("--fps", fps_, "mp4: frames per second, 1 to 240")->capture_default_str();
    at_option_ = app_.add_option(
        "--at", at_s_, "png, svg, pdf: simulated time of the still, s (default: mid-scene)");
    duration_option_ =
        app_.add_option("--duration", duration_s_, "Simulated seconds for every scene");
    csv_step_option_ =
        app_.add_option("--csv-step", csv_step_s_, "csv: seconds between rows, 0.0005 to 0.05")
            ->capture_default_str();
    app_.add_flag("--events", events_,
                  "json: list every collision too (as 'collide data --events'; pi-blocks makes "
                  "millions)");
    changes_.addTo(app_);
    backend_.addTo(app_);
    app_.add_option("--worker", worker_, "Internal: run job K of the batch in this process")
        ->group("");
    app_.add_flag("--serve", serve_,
                  "Internal: run the jobs a batch hands this process on descriptor 3")
        ->group("");
    app_.add_option("--worker-cores", worker_cores_,
                    "Internal: the cores a worker may keep busy (0: as many as a render uses)")
        ->group("");
    app_.footer(
        "Writes DIR/STEM.mp4, .png, .svg, .pdf, .strobe.png, .csv, .json per job and\n"
        "DIR/manifest.json (with --shard I/N: DIR/manifest-I-of-N.json; --merge DIR merges them).\n"
        "STEM is the preset name "
        "or file stem, then _KEY-VALUE per sweep. A failing job never stops the others; the exit "
        "status is 1 if any\n"
        "failed.\n"
        "--jobs N is a core budget: the batch keeps at most N cores busy. A worker whose share\n"
        "is one core composes, draws and encodes on one thread; a larger share keeps a render's\n"
        "own overlap. On a shared machine, --jobs 1 takes one core. Examples:\n"
        "  collide batch --all-presets -o course/ --formats mp4,png\n"
        "  collide batch bouncing-ball -o sweep/ --sweep restitution=0:1:0.25 --formats png,json\n"
        "  collide batch lessons/*.toml -o out/ --shard 2/8   # one of 8 cluster tasks\n"
        "See docs/cluster.md for Slurm and GNU parallel.");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    if (!merge_directory_.empty()) return runMerge(streams);
    if (directory_.empty()) {
      throw core::InputError(
          "batch: no -o DIR: give the folder for the outputs (or --merge DIR to merge the shard "
          "manifests in it)");
    }
    const std::vector<BatchFormat> formats = parseFormats(formats_);
    JobSettings settings = jobSettings(formats);
    std::vector<Sweep> sweeps;
    for (const std::string& text : sweeps_) sweeps.push_back(parseSweep(text));
    const std::vector<std::string> langs =
        langs_.empty() ? std::vector<std::string>{} : parseLanguages(langs_);
    const std::vector<BatchJob> all =
        planBatch(scenes_, all_presets_, sweeps, changes_.overrides(), langs);
    if (worker_ >= 0 || serve_) return runWorker(all, settings, streams);

    const Shard shard = shard_.empty() ? Shard{} : parseShard(shard_);
    const std::vector<BatchJob> jobs = shardJobs(all, shard);
    if (jobs_option_->count() > 0 && (jobs_ < 1 || jobs_ > kMaxWorkers)) {
      throw core::InputError("--jobs: " + std::to_string(jobs_) + ": allowed: 1 to " +
                             std::to_string(kMaxWorkers));
    }
    // Every sweep value is checked on its job's scene before the first job starts: a bad value is
    // exit 2 now, not a failed job an hour into the batch. (A scene that is bad by itself stays
    // one failed job that never stops the others.)
    for (const BatchJob& job : jobs) {
      if (!job.sweep.empty()) scene::loadScene(job.scene, job.overrides);
    }
    // The workers' log directory goes under $TMPDIR: a bad TMPDIR is exit 2 before -o is made.
    requireTemporaryDirectory();
    const bool made_directory = prepareDirectory();
    output::OutputPlan outputs;  // watches the folders the files go to while the jobs run
    std::vector<std::size_t> start_order;
    try {
      // Every job's files and the manifest checked before the first job starts: a path no output
      // may take, two jobs' files that are one, a scene file among them, more than fits.
      noteSceneFiles();
      const std::vector<JobShape> shapes = jobShapes(jobs, settings);
      outputs = output::OutputPlan(
          batchOutputs(jobs, shapes, settings,
                       (fs::path(directory_) / manifestFileName(shard)).string()),
          force_);
      start_order = longestFirst(shapes, settings);
    } catch (...) {
      // Refused before any job ran: the folder this run made is taken back (it is still empty).
      std::error_code ignored;
      if (made_directory) fs::remove(directory_, ignored);
      throw;
    }
    const WorkerThreads plan =
        planWorkerThreads(jobs_option_->count() > 0 ? std::optional<int>(jobs_) : std::nullopt,
                          usableCores(), jobs.size());
    worker_cores_ = plan.cores_each;
    return runParent(all, jobs, shard, plan, start_order, streams);
  }

 private:
  JobSettings jobSettings(const std::vector<BatchFormat>& formats) const {
    checkFps(fps_);
    JobSettings settings;
    settings.formats = formats;
    settings.size = size_.parse();
    settings.fps = fps_;
    settings.directory = directory_;
    if (at_option_->count() > 0) {
      if (!std::isfinite(at_s_) || at_s_ < 0.0) {
        throw core::InputError("--at: " + core::echoTyped(at_option_->results().back()) +
                               ": allowed: a time of 0 s or more (later than a scene's end "
                               "shows its end)");
      }
      settings.at_s = at_s_;
    }
    if (duration_option_->count() > 0) {
      checkDuration(duration_s_, "--duration", duration_option_->results().back());
      settings.duration_s = duration_s_;
    }
    if (!std::isfinite(csv_step_s_) || csv_step_s_ < 0.0005 || csv_step_s_ > 0.05) {
      throw core::InputError("--csv-step: " + core::echoTyped(csv_step_option_->results().back()) +
                             ": allowed: 0.0005 to 0.05 seconds");
    }
    settings.csv_step_s = csv_step_s_;
    settings.json_events = events_;
    if (worker_cores_ < 0 || worker_cores_ > kMaxWorkers) {
      throw core::InputError("--worker-cores: " + std::to_string(worker_cores_) +
                             ": allowed: 0 to " + std::to_string(kMaxWorkers));
    }
    settings.cores = worker_cores_;
    settings.force = force_;
    return settings;
  }

  // Makes the -o folder where it is missing; true when this run made it.
  bool prepareDirectory() const {
    std::error_code error;
    if (fs::is_directory(directory_, error)) return false;
    std::string trimmed = directory_;
    while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
    output::requireParentDirectory("-o", trimmed);
    std::error_code exists_error;
    if (!fs::create_directory(trimmed, error) && !fs::is_directory(trimmed, exists_error)) {
      throw core::InputError("-o: '" + directory_ + "': cannot create the directory (" +
                             error.message() + "); allowed: a directory path");
    }
    return true;
  }

  // The scene files named on the command line, as inputs no output may replace (the workers read
  // them; this process may not have).
  void noteSceneFiles() const {
    for (const std::string& scene : scenes_) {
      if (scene::findPreset(scene) == nullptr) core::noteInputFile(scene);
    }
  }

  int runWorker(const std::vector<BatchJob>& all, const JobSettings& settings,
                CommandStreams& streams) {
    if (!serve_ && worker_ >= static_cast<int>(all.size())) {
      throw core::InputError("--worker: " + std::to_string(worker_) + ": no such job");
    }
    backend_.apply();
    // A worker never outlives its batch: killed (SIGKILL) or gone, the parent's end sends it
    // SIGTERM, which stops its job cleanly.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (worker_cores_ == 1) {
      // llvmpipe rasterising on this thread (LP_NUM_THREADS=0) frees a frame's whole binned
      // scene, 16-64 MiB for ideal-gas at 640x360 or 720p, at the top of the heap after each
      // flush; above main.cpp's 4 MiB trim threshold glibc hands it back to the kernel and the
      // next frame faults it in again, zero-filled. Kept instead, the page faults drop by more
      // than ten times and the peak RSS stays the same, since it grows to its scene's size
      // either way (bench/results.md, "Figures behind the code").
      mallopt(M_TRIM_THRESHOLD, kOneThreadTrimThreshold_bytes);
    }
    // A worker's stderr is its log, read back for the job's outcome: no simulation progress there
    // (the parent reports each job as it ends).
    const SimulationReportScope silent(streams.err, core::ProgressStyle::kSilent);
    if (serve_) {
      serveBatchJobs(all, settings, kWorkerChannelFd, streams.out);
    } else {
      runBatchJob(all[static_cast<std::size_t>(worker_)], settings, streams.out);
    }
    return 0;
  }

  // The arguments that start a worker that runs jobs exactly as this batch would.
  std::vector<std::string> workerArguments() const {
    std::vector<std::string> args = {"batch"};
    // One word each, OPTION=VALUE: a value that starts with '-' (an output folder "-out", a
    // speed --v1 -3) is never read as an option.
    const auto add = [&](const std::string& option, const std::string& value) {
      args.push_back(option + "=" + value);
    };
    add("--output", directory_);
    add("--formats", formats_);
    add("--size", size_.text);
    add("--fps", std::to_string(fps_));
    if (at_option_->count() > 0) add("--at", plain(at_s_));
    if (duration_option_->count() > 0) add("--duration", plain(duration_s_));
    add("--csv-step", plain(csv_step_s_));
    if (events_) args.push_back("--events");
    if (force_) args.push_back("--force");
    if (all_presets_) args.push_back("--all-presets");
    if (!langs_.empty()) add("--langs", langs_);
    for (const std::string& sweep : sweeps_) add("--sweep", sweep);
    for (const std::string& set : changes_.sets) add("--set", set);
    const std::pair<const char*, const std::string*> shortcuts[] = {
        {"--m1", &changes_.m1},        {"--m2", &changes_.m2}, {"--v1", &changes_.v1},
        {"--v2", &changes_.v2},        {"--e", &changes_.e},   {"--theta1", &changes_.theta1},
        {"--theta2", &changes_.theta2}};
    for (const auto& [option, value] : shortcuts) {
      if (!value->empty()) add(option, *value);
    }
    if (!backend_.name.empty()) add("--backend", backend_.name);
    if (worker_cores_ > 0) add("--worker-cores", std::to_string(worker_cores_));
    args.push_back("--serve");
    // The scenes last, after "--": a scene file named like an option ("-s.toml") stays a scene.
    args.push_back("--");
    for (const std::string& scene : scenes_) args.push_back(scene);
    return args;
  }

  int runParent(const std::vector<BatchJob>& all, const std::vector<BatchJob>& jobs,
                const Shard& shard, const WorkerThreads& plan, std::vector<std::size_t> start_order,
                CommandStreams& streams) {
    // Longer than a worker's: the workers stop first, then the manifest is written.
    const output::StopSignals stop_signals(kParentStopGraceSeconds);
    int finished = 0;
    PoolSettings pool;
    pool.executable = workerExecutable();
    pool.output_directory = directory_;
    pool.workers = plan.workers;
    pool.rasterizer_threads = plan.rasterizer_threads;
    pool.start_order = std::move(start_order);
    pool.arguments = workerArguments();
    pool.on_done = [&](const JobOutcome& outcome) {
      ++finished;
      const BatchJob& job = *std::find_if(
          jobs.begin(), jobs.end(), [&](const BatchJob& j) { return j.index == outcome.index; });
      std::ostream& stream = outcome.ok ? streams.out : streams.err;
      stream << "[" << finished << "/" << jobs.size() << "] " << (outcome.ok ? "ok " : "FAILED ")
             << job.stem;
      if (outcome.ok) {
        stream << ":";
        for (const auto& [format, file] : outcome.outputs) stream << " " << file;
      } else {
        stream << ": " << core::echoTyped(outcome.error, 1000);
      }
      stream << " (" << std::fixed << std::setprecision(1) << outcome.seconds << " s)\n";
      for (const std::string& warning : outcome.warnings) {
        streams.err << "warning: " << job.stem << ": " << core::echoTyped(warning, 1000) << "\n";
      }
      stream.flush();
    };
    const std::vector<JobOutcome> outcomes = runWorkerPool(jobs, pool);

    ManifestInfo info;
    std::istringstream names(formats_);
    for (std::string name; std::getline(names, name, ',');) info.formats.push_back(name);
    info.size = size_.text;
    info.fps = fps_;
    info.shard = shard;
    info.total_jobs = static_cast<int>(all.size());
    info.fingerprint = batchFingerprint(workerArguments());
    if (!langs_.empty()) info.langs = parseLanguages(langs_);
    writeManifest(directory_, info, jobs, outcomes);
    // A batch of lessons lists them in DIR/index.html; a shard, which holds part of them, not.
    if (shard.count == 1 && formats_.find("lesson") != std::string::npos) {
      std::vector<report::LessonEntry> lessons;
      for (const JobOutcome& outcome : outcomes) {
        const BatchJob& job = all.at(static_cast<std::size_t>(outcome.index));
        if (!outcome.ok) continue;
        lessons.push_back(lessonEntry(directory_, job.stem + "/",
                                      outcome.title.empty() ? outcome.name : outcome.title,
                                      size_.parse()));
      }
      streams.out << "wrote " << writeLessonIndex(directory_, lessons) << "\n";
    }

    int failed = 0;
    for (const JobOutcome& outcome : outcomes) failed += outcome.ok ? 0 : 1;
    const std::string manifest = (fs::path(directory_) / manifestFileName(shard)).string();
    (failed > 0 ? streams.err : streams.out)
        << "batch: " << jobs.size() - failed << " ok, " << failed << " failed of " << jobs.size()
        << " job" << (jobs.size() == 1 ? "" : "s")
        << (shard.count > 1 ? " (shard " + shard_ + " of " + std::to_string(all.size()) + ")" : "")
        << " on " << plan.workers << " worker" << (plan.workers == 1 ? "" : "s") << "; manifest "
        << manifest << "\n";
    if (const int signal_number = output::StopSignals::received()) {
      throw output::InterruptedError(signal_number,
                                     "unfinished jobs were stopped; the manifest lists them");
    }
    return failed > 0 ? static_cast<int>(core::ExitCode::kRuntimeFailure) : 0;
  }

  // --merge DIR: nothing is rendered, so nothing else may be asked for.
  int runMerge(CommandStreams& streams) const {
    if (!scenes_.empty() || !directory_.empty() || all_presets_ || !shard_.empty() ||
        !sweeps_.empty()) {
      throw core::InputError(
          "batch --merge DIR: no scenes, -o, --shard or --sweep with it; it only reads the "
          "manifests the shards wrote into DIR (collide batch --merge DIR)");
    }
    const MergedSet set = mergeShardManifests(merge_directory_);
    writeMergedManifest(merge_directory_, set);
    (set.whole() ? streams.out : streams.err) << mergeReport(set);
    return set.whole() ? 0 : static_cast<int>(core::ExitCode::kRuntimeFailure);
  }

  CLI::App& app_;
  std::vector<std::string> scenes_;
  std::string directory_;
  std::string merge_directory_;
  int jobs_ = 1;
  CLI::Option* jobs_option_ = nullptr;
  std::string formats_ = "mp4,png,json";
  bool all_presets_ = false;
  std::string langs_;
  std::vector<std::string> sweeps_;
  std::string shard_;
  SizeOption size_;
  int fps_ = 60;
  double at_s_ = 0.0;
  CLI::Option* at_option_ = nullptr;
  CLI::Option* csv_step_option_ = nullptr;  // the value as typed, for a message
  double duration_s_ = 0.0;
  CLI::Option* duration_option_ = nullptr;
  double csv_step_s_ = 0.01;
  bool events_ = false;
  bool force_ = false;
  OverrideOptions changes_;
  BackendOption backend_;
  int worker_ = -1;
  bool serve_ = false;
  int worker_cores_ = 0;  // a worker's share of the --jobs budget; 0: as `render` uses
};

}  // namespace

std::unique_ptr<Command> makeBatchCommand(CLI::App& root) {
  return std::make_unique<BatchCommand>(root);
}

}  // namespace collide::app
