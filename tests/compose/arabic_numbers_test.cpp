// SPDX-License-Identifier: MIT
// Arabic numbers as a frame shows them (issue 37, docs/translations.md): in every text a frame
// asks for in Arabic (render::drawnItems: labels, readouts, legends, captions, ruler numbers), a
// number's decimal sign is the Arabic one (٫, U+066B), never the list comma's look-alike; a
// minus sign is drawn left of its digits, in a left-to-right line of symbols as in an Arabic
// sentence; and no line ends in a number whose unit starts the next. Every preset but the gas
// (its readouts are its chart's) at 1280x720 and 640x360, at the start, just after its first
// collision and at its end, each line shaped with the Arabic fonts. About 2 s in Release.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "render/frame_layout.hpp"
#include "render/text/font_set.hpp"
#include "render/text/script_fonts.hpp"
#include "render/text/shaper.hpp"
#include "render/text/text_metrics.hpp"
#include "render/text/utf8.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"
#include "text/language.hpp"

namespace collide {
namespace {

constexpr double kSize_px = 24.0;
constexpr char32_t kMinus = U'\u2212';

bool arabicDigit(char32_t c) {
  return c >= U'\u0660' && c <= U'\u0669';
}

// The x of the glyph drawn for the character at `index` of `line`; nothing where none is.
std::optional<double> glyphX(const render::ShapedLine& line, std::size_t index) {
  for (const render::ShapedGlyph& glyph : line.glyphs) {
    if (glyph.cluster_begin == index) return glyph.x_px;
  }
  return std::nullopt;
}

// What is wrong with the numbers of one line, described; empty where nothing is.
std::string lineFault(render::FontSet& fonts, const std::string& shown) {
  const std::u32string text = render::decodeUtf8(shown);
  for (std::size_t i = 1; i + 1 < text.size(); ++i) {
    if (arabicDigit(text[i - 1]) && arabicDigit(text[i + 1]) &&
        (text[i] == U'.' || text[i] == U',' || text[i] == U'\u060C')) {
      return "a comma or point between digits, not the Arabic decimal sign";
    }
  }
  const render::ShapedLine line = render::shapeLine(fonts, shown, kSize_px);
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] != kMinus || !arabicDigit(text[i + 1])) continue;
    const std::optional<double> minus = glyphX(line, i), digit = glyphX(line, i + 1);
    if (!minus || !digit) return "no glyph for a minus or its digit";
    if (*minus >= *digit) return "the minus right of its digits";
  }
  return {};
}

// The units a number stands before in a frame's texts.
const std::set<std::string>& units() {
  static const std::set<std::string> all = {"m/s", "m/s,", "m/s;", "J",      "J,",      "J;", "kJ",
                                            "mJ",  "µJ",   "kg",   "kg·m/s", "kg·m/s,", "m",  "s",
                                            "s:",  "N",    "N·s",  "W",      "rad/s",   "%",  "°"};
  return all;
}

// Whether a line ends in an Arabic number and the next starts with its unit.
bool unitBrokenOff(const std::string& line, const std::string& next) {
  const std::u32string end = render::decodeUtf8(line);
  if (end.empty() || !arabicDigit(end.back())) return false;
  return units().count(next.substr(0, next.find(' '))) > 0;
}

int checkFrame(const frame::FrameModel& frame, int width_px, int height_px,
               render::FontSet& fonts) {
  int numbers = 0;
  for (const frame::DrawnItem& item : render::drawnItems(frame, width_px, height_px)) {
    for (std::size_t k = 0; k < item.lines.size(); ++k) {
      const std::string& line = item.lines[k];
      const std::u32string text = render::decodeUtf8(line);
      if (std::none_of(text.begin(), text.end(), arabicDigit)) continue;
      ++numbers;
      const std::string fault = lineFault(fonts, line);
      EXPECT_TRUE(fault.empty()) << item.id << ": \"" << line << "\": " << fault;
      if (k + 1 < item.lines.size()) {
        EXPECT_FALSE(unitBrokenOff(line, item.lines[k + 1]))
            << item.id << ": \"" << line << "\" | \"" << item.lines[k + 1] << "\"";
      }
    }
  }
  return numbers;
}

TEST(ArabicNumbersTest, DecimalSignMinusAndUnitsReadRight) {
  const text::ScopedLanguage arabic("ar");
  render::FontSet fonts(render::textFontsFor(render::defaultFontPath(), "ar"));
  int numbers = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    if (scene.bodies.size() > 40) continue;
    for (const auto& [width_px, height_px] : {std::pair{1280, 720}, std::pair{640, 360}}) {
      SCOPED_TRACE(preset.name + " at " + std::to_string(width_px));
      const app::Animation animation = app::animate(scene, {width_px, height_px});
      const compose::FrameSource& source = animation.frames;
      std::vector<double> instants = {0.0, source.simulatedDuration_s()};
      if (!source.timeline().collisions().empty()) {
        instants.push_back(source.timeline().collisions().front().time_s + 0.05);
      }
      for (double t_s : instants) {
        numbers += checkFrame(source.frameAtSimulated(t_s), width_px, height_px, fonts);
      }
    }
  }
  EXPECT_GT(numbers, 100) << "too few Arabic numbers drawn: are the digits Arabic-Indic?";
}

// Whether `text` holds a digit 0-9 (ASCII).
bool asciiDigit(const std::string& text) {
  return std::any_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The numbers a preset writes into its own words, its title ("Counting pi: 3 digits, mass ratio
// 10⁴", "Newton's cradle: 1 in, 1 out") and its bodies' names ("ball 3"), in the language's
// digits too, as every number a frame formats is: pi-blocks' Arabic title read "عدّ 3" beside
// "التصادمات: ٣١٣".
TEST(ArabicNumbersTest, PresetsWriteTheirOwnNumbersInArabicDigits) {
  const text::ScopedLanguage arabic("ar");
  int with_numbers = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    EXPECT_FALSE(asciiDigit(scene.title)) << preset.name << ": \"" << scene.title << "\"";
    const std::u32string title = render::decodeUtf8(scene.title);
    with_numbers += std::any_of(title.begin(), title.end(), arabicDigit) ? 1 : 0;
    for (const scene::BodyDesc& body : scene.bodies) {
      EXPECT_FALSE(asciiDigit(body.name)) << preset.name << ": body \"" << body.name << "\"";
    }
  }
  EXPECT_GE(with_numbers, 2) << "pi-blocks' and newtons-cradle's titles hold numbers";
}

}  // namespace
}  // namespace collide
