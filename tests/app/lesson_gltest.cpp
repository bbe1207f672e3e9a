// SPDX-License-Identifier: MIT
// collide lesson: the folder's files, and the page's contract that a browser cannot check by
// itself: the caption track carries the .vtt beside it, word for word, and every file the page
// names is in the folder. tests/browser checks the page in Chromium.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "cli_runner.hpp"
#include "scratch.hpp"

namespace collide::lesson_test {
namespace {

using test::CliResult;
using test::run;

// RFC 4648 base64 decoded (the page's data: URL).
std::string fromBase64(const std::string& text) {
  static const std::string kDigits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  unsigned value = 0;
  int bits = 0;
  for (const char c : text) {
    const std::size_t digit = kDigits.find(c);
    if (digit == std::string::npos) break;  // '=' padding
    value = (value << 6) | static_cast<unsigned>(digit);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes += static_cast<char>((value >> bits) & 0xff);
    }
  }
  return bytes;
}

TEST(LessonGLTest, FolderHoldsThePageAndEveryFileItNames) {
  const test::ScratchDir dir("collide_lesson_");
  const std::string folder = dir.file("lesson") + "/";
  const CliResult r = run({"lesson", "worked-example", "-o", folder, "--size", "320x180", "--fps",
                           "10", "--duration", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = test::readFileBytes(dir / "lesson" / "index.html");
  ASSERT_FALSE(page.empty());
  EXPECT_NE(page.find("<html lang=\"en\" dir=\"ltr\">"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);  // nothing runs
  // Nothing is fetched from the network: every src and href names a file of the folder (the
  // captions ride in a data: URL; MathML's xmlns is a name, never fetched).
  const std::regex reference("(?:src|href|poster)=\"([^\"]+)\"");
  std::set<std::string> named;
  for (auto it = std::sregex_iterator(page.begin(), page.end(), reference);
       it != std::sregex_iterator(); ++it) {
    named.insert((*it)[1].str());
  }
  for (const char* file :
       {"video.mp4", "video.webm", "video.vtt", "start.png", "end.png", "strobe.png", "energy.svg",
        "data.csv", "summary.json", "tracker.txt", "vernier.txt"}) {
    EXPECT_EQ(named.count(file), 1u) << file;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "lesson" / file)) << file;
  }
  for (const std::string& ref : named) {
    if (ref.rfind("data:", 0) == 0) continue;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "lesson" / ref)) << ref;
  }
  // The <track default> is the .vtt, byte for byte.
  const std::smatch track = [&] {
    std::smatch m;
    std::regex_search(page, m,
                      std::regex("<track kind=\"captions\" srclang=\"en\" label=\"[^\"]*\" "
                                 "src=\"data:text/vtt;base64,([A-Za-z0-9+/=]+)\" "
                                 "default>"));
    return m;
  }();
  ASSERT_EQ(track.size(), 2u) << page;
  EXPECT_EQ(fromBase64(track[1].str()), test::readFileBytes(dir / "lesson" / "video.vtt"));
  // The Tracker model follows the lesson's video: 2 s at 10 frames per second.
  const std::string model = test::readFileBytes(dir / "lesson" / "tracker.txt");
  EXPECT_EQ(std::count(model.begin(), model.end(), '\n'), 2 + 20);
}

TEST(LessonGLTest, ArabicPageReadsRightToLeft) {
  const test::ScratchDir dir("collide_lesson_ar_");
  const CliResult r = run({"lesson", "worked-example", "--lang", "ar", "-o", dir.file("ar"),
                           "--size", "320x180", "--fps", "10", "--duration", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = test::readFileBytes(dir / "ar" / "index.html");
  EXPECT_NE(page.find("<html lang=\"ar\" dir=\"rtl\">"), std::string::npos);
  EXPECT_NE(page.find("srclang=\"ar\""), std::string::npos);
}

TEST(LessonGLTest, StdoutIsRefused) {
  const CliResult r = run({"lesson", "worked-example", "-o", "-"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "collide: -o: '-': a lesson is a folder of files; allowed: a folder path\n");
}

}  // namespace
}  // namespace collide::lesson_test
