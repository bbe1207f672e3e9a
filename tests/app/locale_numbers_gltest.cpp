// Numbers as the chosen language writes them: `--lang de` puts "1,25 m/s" on the frame (the
// SVG's text, drawn from the frame description), in the captions and in the alt text, while the
// data of the same scene keeps "1.25" (CSV and JSON are never localised).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cli_runner.hpp"
#include "scratch.hpp"

namespace collide {
namespace {

// Each <text> element of an SVG as the string it reads (its tspans joined).
std::vector<std::string> svgTexts(const std::string& svg) {
  std::vector<std::string> texts;
  static const std::regex element(R"(<text[^>]*>([\s\S]*?)</text>)");
  static const std::regex tag(R"(<[^>]*>)");
  for (std::sregex_iterator it(svg.begin(), svg.end(), element), end; it != end; ++it) {
    texts.push_back(std::regex_replace((*it)[1].str(), tag, ""));
  }
  return texts;
}

bool anyContains(const std::vector<std::string>& texts, const std::string& wanted) {
  for (const std::string& text : texts) {
    if (text.find(wanted) != std::string::npos) return true;
  }
  return false;
}

std::string decimal(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// Two equal carts, e = 0: the first, at v₁, hits the second at rest and they move on together.
struct Pair {
  double mass_kg = 1.0;
  double v1_mps = 2.5;
  double size_m = 0.5;
  double x1_m = -2.0, x2_m = 0.0;
  // Momentum conserved, one common velocity after: (m·v₁ + m·0) / 2m.
  double after_mps() const { return mass_kg * v1_mps / (2.0 * mass_kg); }
  // The gap between the facing sides closes at v₁.
  double contact_s() const { return (x2_m - x1_m - size_m) / v1_mps; }

  std::string toml() const {
    std::ostringstream scene;
    scene << "name = \"pair\"\nduration = 2.0\nrestitution = 0.0\n";
    for (const auto& [name, x, v] : {std::tuple{"a", x1_m, v1_mps}, {"b", x2_m, 0.0}}) {
      scene << "[[body]]\nname = \"" << name << "\"\nmass = " << mass_kg << "\nsize = " << size_m
            << "\nposition = " << x << "\nvelocity = " << v << "\n";
    }
    return scene.str();
  }
};

TEST(LocaleNumbersGLTest, GermanFramesCaptionsAndAltTextWriteADecimalCommaWhileTheCsvKeepsADot) {
  const test::ScratchDir dir("collide_locale_numbers_");
  const Pair pair;
  ASSERT_EQ(pair.after_mps(), 1.25);  // exact in binary: the CSV can show it exactly
  const std::string scene = dir.file("pair.toml");
  std::ofstream(scene) << pair.toml();
  // Three figures, as a German reader writes them: decimal comma.
  std::string german = decimal(pair.after_mps(), 2) + " m/s";
  german[german.find('.')] = ',';
  ASSERT_EQ(german, "1,25 m/s");
  const std::string english = decimal(pair.after_mps(), 2) + " m/s";
  const std::string after = decimal(pair.contact_s() + 0.9, 2);  // well after the impact

  for (const auto& [lang, shown, not_shown] :
       {std::tuple{"de", german, english}, std::tuple{"en", english, german}}) {
    const std::string still = dir.file(std::string(lang) + ".svg");
    const test::CliResult drawn = test::run(
        {"still", scene, "--lang", lang, "--at", after, "--size", "320x180", "-o", still});
    ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
    const std::vector<std::string> frame_text = svgTexts(test::readFileBytes(still));
    EXPECT_TRUE(anyContains(frame_text, shown)) << lang << ": " << test::readFileBytes(still);
    EXPECT_FALSE(anyContains(frame_text, not_shown)) << lang;
    const std::string alt = test::readFileBytes(dir.file(std::string(lang) + ".alt.txt"));
    EXPECT_NE(alt.find(shown), std::string::npos) << lang << ": " << alt;
    EXPECT_EQ(alt.find(not_shown), std::string::npos) << lang << ": " << alt;

    const std::string video = dir.file(std::string(lang) + ".mp4");
    const test::CliResult rendered =
        test::run({"render", scene, "--lang", lang, "--captions", "--size", "160x90", "--fps", "10",
                   "-q", "-o", video});
    ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
    const std::string captions = test::readFileBytes(dir.file(std::string(lang) + ".vtt"));
    EXPECT_NE(captions.find(shown), std::string::npos) << lang << ": " << captions;
    EXPECT_EQ(captions.find(not_shown), std::string::npos) << lang << ": " << captions;
  }

  // The data of the scene: dot decimals, English column names, the common velocity exactly.
  const std::string csv_path = dir.file("pair.csv");
  const test::CliResult data = test::run({"data", scene, "--csv", csv_path});
  ASSERT_EQ(data.exit_code, 0) << data.err;
  std::istringstream csv(test::readFileBytes(csv_path));
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t_s,a_x_m,a_v_mps,", 0), 0u) << header;
  int rows_after = 0;
  for (std::string row; std::getline(csv, row);) {
    std::vector<std::string> fields;
    std::istringstream cells(row);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    ASSERT_GE(fields.size(), 3u) << row;
    if (std::stod(fields[0]) <= pair.contact_s() + 0.01) continue;
    EXPECT_EQ(fields[2], "1.25") << row;
    ++rows_after;
  }
  EXPECT_GT(rows_after, 100);  // 2 s at the default 0.01 s step, the impact at 0.6 s
}

}  // namespace
}  // namespace collide
