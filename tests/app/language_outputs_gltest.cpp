// Outputs in several languages through the real binary: `batch --langs` makes each job once per
// language (the tag in each output's name and in the manifest; an unknown code is exit 2 listing
// the shipped languages), and a video's subtitle and audio streams and its WebVTT carry the
// language tag, read back with libavformat as ffprobe reads them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "output/media_probe.hpp"
#include "scratch.hpp"

namespace collide::language_outputs_test {
namespace {
namespace fs = std::filesystem;

test::ShellRun runCollide(const test::ScratchDir& dir, const std::string& arguments) {
  return test::runShellCaptured(dir.path(), test::shellQuoted(COLLIDE_BINARY) + " " + arguments);
}

// Two equal carts, e = 0: 1 kg at 2.5 m/s onto 1 kg at rest; momentum conserved, they move on
// together at 2.5 / 2 = 1.25 m/s (German "1,25 m/s"), from t = (0 − (−2) − 0.5) / 2.5 = 0.6 s.
const char* const kPair =
    "name = \"pair\"\nduration = 2.0\nrestitution = 0.0\n"
    "[[body]]\nname = \"a\"\nmass = 1.0\nsize = 0.5\nposition = -2.0\nvelocity = 2.5\n"
    "[[body]]\nname = \"b\"\nmass = 1.0\nsize = 0.5\nposition = 0.0\nvelocity = 0.0\n";

TEST(LanguageOutputsGLTest, BatchLangsMakesEachJobInEachLanguageNamedByItsTag) {
  const test::ScratchDir dir("collide_batch_langs_");
  std::ofstream(dir.file("pair.toml")) << kPair;
  const std::string out = dir.file("course");
  const test::ShellRun run =
      runCollide(dir, "batch " + dir.shellFile("pair.toml") +
                          " --langs en,DE --formats svg,csv --size 320x180 --at 1.5 "
                          "--jobs 1 -o " +
                          test::shellQuoted(out));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  for (const char* file : {"pair.en.svg", "pair.en.alt.txt", "pair.en.csv", "pair.de.svg",
                           "pair.de.alt.txt", "pair.de.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::path(out) / file)) << file;
  }
  // One run: the German picture and alt text write the decimal comma, its CSV a dot.
  EXPECT_NE(test::readFileBytes(fs::path(out) / "pair.de.alt.txt").find("1,25 m/s"),
            std::string::npos);
  EXPECT_NE(test::readFileBytes(fs::path(out) / "pair.en.alt.txt").find("1.25 m/s"),
            std::string::npos);
  const std::string csv = test::readFileBytes(fs::path(out) / "pair.de.csv");
  EXPECT_NE(csv.find(",1.25,"), std::string::npos);
  EXPECT_EQ(csv, test::readFileBytes(fs::path(out) / "pair.en.csv"));
  // The SVG declares its language.
  EXPECT_NE(test::readFileBytes(fs::path(out) / "pair.de.svg").find("xml:lang=\"de\""),
            std::string::npos);

  const nlohmann::json manifest =
      nlohmann::json::parse(test::readFileBytes(fs::path(out) / "manifest.json"));
  EXPECT_EQ(manifest.at("langs"), nlohmann::json::array({"en", "de"}));
  ASSERT_EQ(manifest.at("jobs").size(), 2u);
  std::map<std::string, std::string> lang_of;
  for (const nlohmann::json& job : manifest.at("jobs")) {
    lang_of[job.at("stem").get<std::string>()] = job.at("lang").get<std::string>();
  }
  EXPECT_EQ(lang_of, (std::map<std::string, std::string>{{"pair.en", "en"}, {"pair.de", "de"}}));
}

TEST(LanguageOutputsGLTest, AnUnknownLanguageInLangsIsExitTwoListingTheShippedOnes) {
  const test::ScratchDir dir("collide_batch_langs_bad_");
  const std::string out = dir.file("course");
  const test::ShellRun run = runCollide(
      dir, "batch worked-example --langs en,xx --formats csv -o " + test::shellQuoted(out));
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_EQ(run.err.rfind("collide: --langs 'xx': not a shipped language; shipped languages: en "
                          "(English), ",
                          0),
            0u)
      << run.err;
  EXPECT_NE(run.err.find(", de (Deutsch), "), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;  // one line
  EXPECT_FALSE(fs::exists(out));
  const test::ShellRun twice = runCollide(
      dir, "batch worked-example --langs de,de-AT --formats csv -o " + test::shellQuoted(out));
  EXPECT_EQ(twice.exit_code, 2) << twice.err;
  EXPECT_NE(twice.err.find("de is named twice"), std::string::npos) << twice.err;
}

// ISO 639-2 in the containers: MP4 (ISO/IEC 14496-12) takes the terminology code, "deu";
// Matroska and WebM the bibliographic one, "ger" (the two differ for German, French and Chinese).
TEST(LanguageOutputsGLTest, SubtitleAndAudioStreamsAndTheWebVttCarryTheLanguage) {
  const test::ScratchDir dir("collide_track_langs_");
  std::ofstream(dir.file("pair.toml")) << kPair;
  for (const auto& [container, code] :
       std::vector<std::pair<std::string, std::string>>{{"mp4", "deu"}, {"webm", "ger"}}) {
    const std::string video = dir.file("pair." + container);
    const test::ShellRun run = runCollide(
        dir, "render " + dir.shellFile("pair.toml") + " --lang de --size 160x90 --fps 10 " +
                 "--sound --captions --embed-captions -q -o " + test::shellQuoted(video));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const output::test::MediaFacts facts = output::test::probeMedia(video);
    for (const char* type : {"audio", "subtitle"}) {
      const output::test::StreamFacts* stream = output::test::findStream(facts, type);
      ASSERT_NE(stream, nullptr) << container << " " << type;
      EXPECT_EQ(stream->metadata.count("language") ? stream->metadata.at("language") : "", code)
          << container << " " << type;
    }
    const std::string vtt = test::readFileBytes(dir.file("pair.vtt"));
    EXPECT_EQ(vtt.rfind("WEBVTT - pair\nKind: captions\nLanguage: de\n\n", 0), 0u) << vtt;
  }
}

}  // namespace
}  // namespace collide::language_outputs_test
