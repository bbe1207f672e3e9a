// `collide batch` through the real binary: a batch with a failing scene, a sweep, the manifest,
// and shards (run one after another, and by GNU parallel) whose union equals the unsharded run
// byte for byte for PNG and data outputs. Small frames and short scenes keep it quick.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

// Every file under `dir` except manifests, by name, with its bytes.
std::map<std::string, std::string> outputs(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("manifest", 0) != 0) files[name] = test::readFileBytes(entry.path());
  }
  return files;
}

class BatchGLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir(
        "collide_batch_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs a shell command line (killed after 5 minutes); `{bin}` is replaced by the collide binary,
  // as one shell word.
  test::ShellRun shell(std::string command) {
    for (std::size_t at; (at = command.find("{bin}")) != std::string::npos;) {
      command.replace(at, 5, test::shellQuoted(COLLIDE_BINARY));
    }
    return test::runShellCaptured(dir_, command);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // The same path as one word of a command line.
  std::string word(const std::string& name) const { return test::shellQuoted(path(name)); }

  fs::path dir_;
};

// Scenes and options shared by the shard tests: 2 presets x 3 sweep values = 6 jobs.
const std::string kShardBatch =
    "worked-example heavy-light --sweep restitution=0:1:0.5 --formats png,csv,json "
    "--size 160x90 --duration 1.5";

TEST_F(BatchGLTest, OneFailingSceneNeverStopsTheOthers) {
  std::ofstream(path("bad.toml")) << "[[body]]\nmass = -1\nsize = 1\nposition = 0\n";
  const test::ShellRun run =
      shell("{bin} batch worked-example " + word("bad.toml") + " elastic -o " + word("out") +
            " --jobs 2 --formats mp4,png,strobe,json --size 160x90 --fps 10 --duration 1");
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  EXPECT_NE(run.err.find("FAILED bad: " + path("bad.toml") + ":2:8: body.1.mass: -1: "),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("batch: 2 ok, 1 failed of 3 jobs on 2 workers"), std::string::npos)
      << run.err;
  for (const char* file : {"worked-example.mp4", "worked-example.png", "worked-example.json",
                           "worked-example.strobe.png", "elastic.mp4", "elastic.png",
                           "elastic.json", "elastic.strobe.png"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / file)) << file;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "bad.png"));
  const std::string text = test::readFileBytes(dir_ / "out" / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(text);
  EXPECT_EQ(manifest.at("total_jobs"), 3) << text;
  EXPECT_EQ(manifest.at("succeeded"), 2) << text;
  EXPECT_EQ(manifest.at("failed"), 1) << text;
  ASSERT_EQ(manifest.at("jobs").size(), 3u) << text;
  std::map<std::string, nlohmann::json> jobs;
  for (const nlohmann::json& job : manifest.at("jobs")) jobs[job.at("stem")] = job;
  ASSERT_EQ(jobs.count("bad"), 1u) << text;
  EXPECT_EQ(jobs["bad"].at("status"), "failed");
  EXPECT_EQ(jobs["worked-example"].at("status"), "ok");
  EXPECT_EQ(jobs["elastic"].at("status"), "ok");
  EXPECT_EQ(jobs["elastic"].at("title"), "A cart bounces back off a heavier one, e = 1");
  std::vector<std::string> elastic_paths;
  for (const nlohmann::json& output : jobs["elastic"].at("outputs")) {
    elastic_paths.push_back(output.at("path"));
  }
  EXPECT_NE(std::find(elastic_paths.begin(), elastic_paths.end(), "elastic.mp4"),
            elastic_paths.end())
      << text;
}

// A scene whose run stops early (two disks come to rest stacked, which the 2D model does not
// follow) still succeeds; its warning is printed and listed in the manifest once, although
// three formats simulated it.
TEST_F(BatchGLTest, APhysicsWarningIsReportedOncePerJob) {
  std::ofstream(path("stack.toml")) << "dimensions = 2\nduration = 1\ngravity = [0, -9.81]\n"
                                       "restitution = 0\n[box]\nmin = [-1, 0]\nmax = [1, 3]\n"
                                       "[[body]]\nmass = 1\nsize = 0.2\nposition = [0, 0.2]\n"
                                       "[[body]]\nmass = 1\nsize = 0.2\nposition = [0, 0.8]\n";
  const test::ShellRun run = shell("{bin} batch " + word("stack.toml") + " -o " + word("out") +
                                   " --formats png,json,csv --size 160x90");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.err.find("warning: stack: stopped at t = "), std::string::npos) << run.err;
  const std::string manifest = test::readFileBytes(dir_ / "out" / "manifest.json");
  const std::size_t warnings = manifest.find("\"warnings\": [");
  ASSERT_NE(warnings, std::string::npos) << manifest;
  const std::size_t end = manifest.find(']', warnings);
  const std::string list = manifest.substr(warnings, end - warnings);
  EXPECT_NE(list.find("stopped at t = "), std::string::npos) << manifest;
  EXPECT_EQ(list.find("stopped at t = "), list.rfind("stopped at t = ")) << manifest;  // once
}

// A file's bytes with the digits of a PDF's creation date (the clock's, a fixed length) zeroed.
std::string withoutCreationDate(std::string pdf) {
  const std::string key = "/CreationDate (D:";
  const std::size_t at = pdf.find(key);
  if (at == std::string::npos) return pdf;
  for (std::size_t i = at + key.size(); i < pdf.size() && pdf[i] != ')'; ++i) {
    if (pdf[i] >= '0' && pdf[i] <= '9') pdf[i] = '0';
  }
  return pdf;
}

// A worker process runs job after job (the GL and video modules, fonts and language data load once
// per worker), and a job's files are the same whether it ran alone or after others in its worker:
// nothing an earlier job leaves in the process reaches them. The worker after others runs with
// glibc's MALLOC_PERTURB_, so the heap it reuses holds other bytes than fresh pages' zeros (x264's
// AVX-512 code read such leftovers: at this size its MP4 changed with them; Cairo numbered an SVG's
// surfaces by the process). The worker binary is a script that counts its starts.
TEST_F(BatchGLTest, OneWorkerProcessRunsEveryJobInTurnWithTheSameFiles) {
  const std::string wrapper = path("worker.sh");
  std::ofstream(wrapper) << "#!/bin/sh\necho started >> '" << path("starts") << "'\nexec '"
                         << COLLIDE_BINARY << "' \"$@\"\n";
  fs::permissions(wrapper, fs::perms::owner_all);
  const std::string options =
      " --formats mp4,png,svg,pdf,strobe,csv,json --size 192x108 --fps 10 --duration 1";
  const test::ShellRun three =
      shell("MALLOC_PERTURB_=165 COLLIDE_BATCH_WORKER=" + test::shellQuoted(wrapper) +
            " {bin} batch worked-example elastic clay -o " + word("three") + options + " --jobs 1");
  ASSERT_EQ(three.exit_code, 0) << three.out << three.err;
  EXPECT_EQ(test::readFileBytes(dir_ / "starts"), "started\n") << "one worker for three jobs";
  // The same core budget: x264 writes its thread count into the stream (batch_threads.hpp).
  const test::ShellRun alone =
      shell("{bin} batch clay -o " + word("alone") + options + " --jobs 1");
  ASSERT_EQ(alone.exit_code, 0) << alone.out << alone.err;
  for (const char* file : {"clay.mp4", "clay.png", "clay.svg", "clay.pdf", "clay.strobe.png",
                           "clay.csv", "clay.json", "clay.alt.txt"}) {
    const std::string expected = withoutCreationDate(test::readFileBytes(dir_ / "alone" / file));
    EXPECT_FALSE(expected.empty()) << file;
    EXPECT_TRUE(withoutCreationDate(test::readFileBytes(dir_ / "three" / file)) == expected)
        << file << " differs after two other jobs in the same worker";
  }
}

TEST_F(BatchGLTest, ASweepWritesOneOutputPerValue) {
  const test::ShellRun run =
      shell("{bin} batch worked-example -o " + word("sweep") +
            " --sweep restitution=0:1:0.25 --formats json --events --jobs 2");
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  for (const char* value : {"0", "0.25", "0.5", "0.75", "1"}) {
    const fs::path file =
        dir_ / "sweep" / ("worked-example_restitution-" + std::string(value) + ".json");
    ASSERT_TRUE(fs::is_regular_file(file)) << file;
    // Its one collision was computed with the swept restitution.
    const nlohmann::json summary = nlohmann::json::parse(test::readFileBytes(file));
    ASSERT_EQ(summary.at("events").size(), 1u) << test::readFileBytes(file);
    EXPECT_EQ(summary.at("events")[0].at("restitution").get<double>(), std::stod(value))
        << test::readFileBytes(file);
  }
  const std::string text = test::readFileBytes(dir_ / "sweep" / "manifest.json");
  const nlohmann::json manifest = nlohmann::json::parse(text);
  std::vector<double> swept;
  for (const nlohmann::json& job : manifest.at("jobs")) {
    ASSERT_EQ(job.at("sweep").size(), 1u) << text;
    swept.push_back(job.at("sweep").at("restitution").get<double>());
  }
  std::sort(swept.begin(), swept.end());
  EXPECT_EQ(swept, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0})) << text;
  // A preset parameter sweeps too: Galperin's blocks count 3, 31, 314.
  const test::ShellRun pi = shell("{bin} batch pi-blocks -o " + word("pi") +
                                  " --sweep digits=1:3:1 --formats json --jobs 1");
  ASSERT_EQ(pi.exit_code, 0) << pi.err;
  for (const auto& [digits, count] : {std::pair{1, 3}, std::pair{2, 31}, std::pair{3, 314}}) {
    const std::string text =
        test::readFileBytes(dir_ / "pi" / ("pi-blocks_digits-" + std::to_string(digits) + ".json"));
    const nlohmann::json summary = nlohmann::json::parse(text);
    EXPECT_EQ(summary.at("collision_count"), count) << text;
    // Without --events the summary leaves out the list of events (millions for more digits).
    EXPECT_FALSE(summary.contains("events")) << text;
  }
}

TEST_F(BatchGLTest, BadBatchOptionsAreRefusedBeforeAnythingRuns) {
  for (const std::string& options :
       {std::string("--sweep restitution=1:0:0.1"), std::string("--shard 3/3"),
        std::string("--formats mp4,avi"), std::string("--jobs 0"), std::string("--at -1")}) {
    const test::ShellRun run =
        shell("{bin} batch worked-example -o " + word("never") + " " + options);
    EXPECT_EQ(run.exit_code, 2) << options << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "never")) << options;
  }
  EXPECT_EQ(shell("{bin} batch -o " + word("never")).exit_code, 2);
}

TEST_F(BatchGLTest, EachFileAJobWritesIsListedOnceInTheManifest) {
  // png and svg show the same instant and share STEM.alt.txt: written by both, listed once.
  const test::ShellRun run = shell("{bin} batch elastic --formats png,svg,csv --size 160x90 -o " +
                                   path("out") + " --duration 1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json manifest =
      nlohmann::json::parse(test::readFileBytes(dir_ / "out" / "manifest.json"));
  std::vector<std::string> listed;
  for (const nlohmann::json& output : manifest["jobs"][0]["outputs"]) {
    listed.push_back(output["path"].get<std::string>());
  }
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(listed, std::vector<std::string>(
                        {"elastic.alt.txt", "elastic.csv", "elastic.png", "elastic.svg"}));
}

// --formats lesson: one lesson folder per job (collide lesson's files), listed in the manifest,
// and DIR/index.html linking each lesson's page with its poster.
TEST_F(BatchGLTest, LessonsAreFoldersListedOnAnIndexPage) {
  const test::ShellRun r = shell("{bin} batch worked-example heavy-light -o " + word("out") +
                                 " --formats lesson --size 160x90 --fps 5 --duration 1 --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string index = test::readFileBytes(dir_ / "out" / "index.html");
  for (const std::string stem : {"worked-example", "heavy-light"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / stem / "index.html")) << stem;
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / stem / "video.mp4")) << stem;
    EXPECT_NE(index.find("<a href=\"" + stem + "/index.html\">"), std::string::npos) << index;
    EXPECT_NE(index.find("<img src=\"" + stem + "/start.png\""), std::string::npos) << index;
  }
  const nlohmann::json manifest =
      nlohmann::json::parse(test::readFileBytes(dir_ / "out" / "manifest.json"));
  for (const nlohmann::json& job : manifest.at("jobs")) {
    ASSERT_EQ(job.at("outputs").size(), 1u) << job;
    EXPECT_EQ(job.at("outputs")[0].at("format"), "lesson");
  }
}

TEST_F(BatchGLTest, ShardsUnionEqualsTheUnshardedRunByteForByte) {
  const test::ShellRun whole =
      shell("{bin} batch " + kShardBatch + " -o " + word("whole") + " --jobs 2");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  for (int i = 0; i < 3; ++i) {
    const test::ShellRun shard = shell("{bin} batch " + kShardBatch + " -o " + word("sharded") +
                                       " --jobs 1 --shard " + std::to_string(i) + "/3");
    ASSERT_EQ(shard.exit_code, 0) << shard.err;
    EXPECT_NE(
        shard.out.find("batch: 2 ok, 0 failed of 2 jobs (shard " + std::to_string(i) + "/3 of 6)"),
        std::string::npos)
        << shard.out;
    EXPECT_TRUE(
        fs::is_regular_file(dir_ / "sharded" / ("manifest-" + std::to_string(i) + "-of-3.json")));
  }
  const auto expected = outputs(dir_ / "whole");
  EXPECT_EQ(expected.size(), 24u);  // 6 jobs x png (and its alt text), csv, json
  EXPECT_TRUE(expected == outputs(dir_ / "sharded"));

  // The three manifests merge into the unsharded run's manifest, job for job (timings aside).
  const test::ShellRun merge = shell("{bin} batch --merge " + path("sharded"));
  EXPECT_EQ(merge.exit_code, 0) << merge.err;
  const auto untimed = [](const fs::path& file) {
    nlohmann::json manifest = nlohmann::json::parse(test::readFileBytes(file));
    manifest.erase("merged_from");
    for (nlohmann::json& job : manifest["jobs"]) job.erase("seconds");
    return manifest;
  };
  EXPECT_EQ(untimed(dir_ / "whole" / "manifest.json"), untimed(dir_ / "sharded" / "manifest.json"));

  // Without shard 2's manifest (its task never ran) the merge names it and how to rerun it.
  fs::remove(dir_ / "sharded" / "manifest-2-of-3.json");
  const test::ShellRun partial = shell("{bin} batch --merge " + path("sharded"));
  EXPECT_EQ(partial.exit_code, 1);
  EXPECT_NE(partial.err.find("missing: shard 2/3 (manifest-2-of-3.json)"), std::string::npos)
      << partial.err;
  EXPECT_NE(partial.err.find("--array=2 "), std::string::npos) << partial.err;
  EXPECT_EQ(untimed(dir_ / "sharded" / "manifest.json")["succeeded"], 4);
}

TEST_F(BatchGLTest, GnuParallelSpreadsShardsOverLocalWorkers) {
  if (test::runShellBounded("command -v parallel >" + word("which.txt"),
                            std::chrono::seconds(10)) != 0) {
    GTEST_SKIP() << "GNU parallel is not installed (apt-get install parallel); the Slurm and "
                    "parallel forms in docs/cluster.md are not exercised";
  }
  const test::ShellRun whole =
      shell("{bin} batch " + kShardBatch + " -o " + word("whole") + " --jobs 2");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  // The command docs/cluster.md gives, with three local workers. parallel joins its command's
  // words with spaces for a shell of its own: a path is quoted once for each shell.
  const test::ShellRun spread =
      shell("parallel --will-cite --halt never -j 3 " +
            test::shellQuoted(test::shellQuoted(COLLIDE_BINARY)) + " batch " + kShardBatch +
            " -o " + test::shellQuoted(word("parallel")) + " --jobs 1 --shard {}/3 ::: 0 1 2");
  ASSERT_EQ(spread.exit_code, 0) << spread.out << spread.err;
  EXPECT_TRUE(outputs(dir_ / "whole") == outputs(dir_ / "parallel"));
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(
        fs::is_regular_file(dir_ / "parallel" / ("manifest-" + std::to_string(i) + "-of-3.json")));
  }
}

}  // namespace
}  // namespace collide
