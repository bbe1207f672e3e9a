// SPDX-License-Identifier: MIT
// Nothing dropped (issue 37 item 5), read from the layout as `collide layout --json` writes it
// (render::drawnItems, what the painters draw): every text the frame description asks for is
// among the drawn items, whole, wrapped onto lines or drawn smaller, never silently left out.
// Every shipped language at 1280x720 and 640x360, at the instants the issue names: the ballistic
// pendulum at the top of its swing (its speed worked out from the rise h is the point of the
// preset; German lost it at 0.52 s), the worked example and Newton's cradle after their impacts
// (their info lines hold vectors). No line parts a number from its unit or a vector inside its
// brackets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "language_params.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"
#include "text/language.hpp"
#include "text/number_format.hpp"

namespace collide {
namespace {

// Runs of spaces as one, none at either end: a text wrapped between clauses ("a   b") reads
// "a b" across its lines.
std::string squeezed(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == ' ' && (out.empty() || out.back() == ' ')) continue;
    out += c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// `text` without its spaces: Chinese and Japanese lines break between characters with nothing
// added, Latin runs inside them at spaces, so a wrapped text is compared without them.
std::string spaceless(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c != ' ') out += c;
  }
  return out;
}

// An item's text as a reader reads it: its lines joined by a space, and without spaces.
std::vector<std::string> readings(const frame::DrawnItem& item) {
  std::string spaced;
  for (const std::string& line : item.lines) spaced += (spaced.empty() ? "" : " ") + line;
  return {squeezed(spaced), spaceless(spaced)};
}

// The texts of the frame description a screen must show: its title and time, each panel's
// heading, info, scale, caption, energy labels, body and velocity labels, a measured height's
// label and notes, and each chart's title and axis labels.
std::vector<std::string> askedFor(const frame::FrameModel& frame) {
  std::vector<std::string> out{frame.title, frame.time_readout, frame.subtitle};
  for (const frame::PanelModel& panel : frame.panels) {
    out.insert(out.end(), {panel.heading, panel.info, panel.scale_arrow_label});
    // A comparison grid shows no captions (its alt text does).
    if (frame.panels.size() == 1) out.push_back(panel.caption);
    if (panel.show_energy_bar) {
      for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
        out.push_back(segment.label);
      }
    }
    for (const frame::BodyModel& body : panel.bodies) {
      out.insert(out.end(), {body.label, body.velocity_label});
    }
    for (const frame::DimensionModel& dim : panel.dimensions) {
      out.push_back(dim.label);
      out.insert(out.end(), dim.notes.begin(), dim.notes.end());
    }
  }
  for (const frame::ChartModel& chart : frame.charts) {
    out.insert(out.end(), {chart.title, chart.x_label, chart.y_label});
  }
  out.erase(std::remove(out.begin(), out.end(), std::string()), out.end());
  return out;
}

// Whether `wanted` is drawn whole: one item reads it, or reads it among more (a label and its
// number drawn as one item).
bool drawnWhole(const std::string& wanted, const std::vector<frame::DrawnItem>& items) {
  const std::string text = squeezed(wanted), bare = spaceless(wanted);
  for (const frame::DrawnItem& item : items) {
    const std::vector<std::string> read = readings(item);
    if (read[0].find(text) != std::string::npos || read[1].find(bare) != std::string::npos)
      return true;
  }
  return false;
}

// The last code point of a UTF-8 text (0 where it is empty).
char32_t lastCodePoint(const std::string& text) {
  std::size_t at = text.size();
  while (at > 0 && (static_cast<unsigned char>(text[at - 1]) & 0xC0) == 0x80) --at;
  if (at == 0) return 0;
  const auto lead = static_cast<unsigned char>(text[at - 1]);
  const int length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
  char32_t c = length == 1 ? lead : lead & (0x7F >> length);
  for (std::size_t k = at; k < text.size(); ++k) c = (c << 6) | (text[k] & 0x3F);
  return c;
}

// A digit of the scripts numbers are written in: ASCII, Arabic-Indic, Devanagari.
bool isDigit(char32_t c) {
  return (c >= U'0' && c <= U'9') || (c >= 0x0660 && c <= 0x0669) || (c >= 0x06F0 && c <= 0x06F9) ||
         (c >= 0x0966 && c <= 0x096F);
}

// Whether `line` starts with a direction: an angle, "2°" or "−143°" (a sign, digits, "°").
bool startsWithAngle(const std::string& line) {
  const std::size_t word_end = std::min(line.find(' '), line.size());
  std::string word = line.substr(0, word_end);
  while (!word.empty() && (word.back() == ',' || word.back() == ';')) word.pop_back();
  for (const std::string sign : {"\u061C", "\u2212", "+"}) {
    if (word.starts_with(sign)) word.erase(0, sign.size());
  }
  // The first code point: its digits are the ones lastCodePoint reads of a text that short.
  std::size_t first_end = 1;
  while (first_end < word.size() && (static_cast<unsigned char>(word[first_end]) & 0xC0) == 0x80)
    ++first_end;
  return word.ends_with("°") && isDigit(lastCodePoint(word.substr(0, first_end)));
}

// Where an item's lines part a number from its unit ("1.38 | J"), a vector inside its brackets
// ("(2,00; | 0) kg·m/s") or from its unit ("(0, 0)" | "kg·m/s": no unit stands alone on a
// line), or a speed from its direction ("1.98 m/s," | "2°"), described; none: empty.
std::string partedNumber(const frame::DrawnItem& item) {
  static const char* const kUnits[] = {"J", "kJ", "mJ",    "µJ", "m/s", "kg", "kg·m/s",
                                       "m", "s",  "rad/s", "N",  "%",   "°"};
  int depth = 0;
  for (std::size_t k = 0; k < item.lines.size(); ++k) {
    std::string alone = item.lines[k];
    while (!alone.empty() && (alone.back() == ',' || alone.back() == ';')) alone.pop_back();
    for (const char* unit : kUnits) {
      if (item.lines.size() > 1 && alone == unit) {
        return item.id + ": \"" + item.lines[k] + "\" (a unit alone on a line)";
      }
    }
    if (k + 1 == item.lines.size()) break;
    const std::string& line = item.lines[k];
    const std::string& next = item.lines[k + 1];
    if ((line.ends_with("/s,") || line.ends_with("/s\uFF0C") || line.ends_with("/s\u060C")) &&
        startsWithAngle(next)) {
      return item.id + ": \"" + line + "\" | \"" + next + "\" (a speed and its direction)";
    }
    for (const char c : line) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    bool unit_next = false;
    for (const char* unit : kUnits) {
      const std::string u(unit);
      unit_next = unit_next || next == u || next.starts_with(u + " ") ||
                  next.starts_with(u + ",") || next.starts_with(u + "،") ||
                  next.starts_with(u + "·");
    }
    if (depth > 0 && isDigit(lastCodePoint(line.substr(0, line.find_last_not_of("; ,") + 1)))) {
      return item.id + ": \"" + line + "\" | \"" + next + "\" (inside a vector)";
    }
    if (unit_next && isDigit(lastCodePoint(line))) {
      return item.id + ": \"" + line + "\" | \"" + next + "\" (a number and its unit)";
    }
  }
  return {};
}

std::string drawnTexts(const std::vector<frame::DrawnItem>& items) {
  std::string all;
  for (const frame::DrawnItem& item : items) {
    if (!item.lines.empty()) all += "\n  " + item.id + ": " + readings(item).front();
  }
  return all;
}

// The first panel's caption is drawn whole among `items`.
void expectCaptionDrawnWhole(const frame::FrameModel& frame,
                             const std::vector<frame::DrawnItem>& items) {
  ASSERT_FALSE(frame.panels.empty());
  const std::string& caption = frame.panels.front().caption;
  ASSERT_FALSE(caption.empty());
  EXPECT_TRUE(drawnWhole(caption, items))
      << "\"" << caption << "\" is not drawn whole; drawn:" << drawnTexts(items);
}

struct Instant {
  const char* preset;
  double t_s;
};

// The frames the issue reads: each preset at an instant after its first impact (TextFitTest
// checks every preset's on the painter's canvas).
const Instant kInstants[] = {
    {"ballistic-pendulum", 0.52}, {"worked-example", 2.5}, {"newtons-cradle", 0.4}};

// The ballistic pendulum at the top of its swing asks for its speed from h (else the check of
// the layout has nothing to ask): the block and bullet rise together with the momentum the
// bullet brought, m·v = (m + M)·V, and keep their energy on the way up, V² = 2gh, so
// (m + M)/m · √(2gh) is the bullet's own 200 m/s.
void expectSpeedFromRise(const frame::FrameModel& frame) {
  const std::string speed = text::withLocalDigits("200", text::defaultStyle()) + " m/s";
  std::vector<std::string> notes;
  for (const frame::PanelModel& panel : frame.panels) {
    for (const frame::DimensionModel& dim : panel.dimensions) {
      notes.insert(notes.end(), dim.notes.begin(), dim.notes.end());
      EXPECT_FALSE(dim.label.empty()) << "the rise h has no label";
    }
  }
  ASSERT_EQ(notes.size(), 2u) << "the speed from h and the true speed";
  EXPECT_NE(notes.front().find(speed), std::string::npos) << notes.front();
}

class LayoutKeepsTextTest : public ::testing::TestWithParam<std::string> {};

TEST_P(LayoutKeepsTextTest, EveryTextTheFrameAsksForIsDrawn) {
  const text::ScopedLanguage language(GetParam());
  for (const Instant& instant : kInstants) {
    const scene::SceneDesc scene = scene::loadPreset(instant.preset);
    for (const auto& [width_px, height_px] : {std::pair{1280, 720}, std::pair{640, 360}}) {
      SCOPED_TRACE(std::string(instant.preset) + " at " + std::to_string(instant.t_s) + " s, " +
                   std::to_string(width_px) + "x" + std::to_string(height_px));
      const app::Animation animation = app::animate(scene, {width_px, height_px});
      const frame::FrameModel frame = animation.frames.frameAtSimulated(instant.t_s);
      const std::vector<frame::DrawnItem> items = render::drawnItems(frame, width_px, height_px);
      for (const std::string& wanted : askedFor(frame)) {
        EXPECT_TRUE(drawnWhole(wanted, items))
            << "\"" << wanted << "\" is not drawn whole; drawn:" << drawnTexts(items);
      }
      for (const frame::DrawnItem& item : items) {
        if (item.kind == "chart") continue;  // chart: ticks, names
        EXPECT_EQ(partedNumber(item), "");
      }
      if (std::string(instant.preset) == "ballistic-pendulum") expectSpeedFromRise(frame);
    }
  }
}

// The ideal gas at 640x360 has room for two lines of info, and its momentum readout ("Σp: start
// (−0.253, 0.181) kg·m/s, now (…) kg·m/s") took three: its last value was cut with "…".
// English, German (its longer words) and Chinese (its breaks between characters); about a
// second each.
TEST(LayoutKeepsGasTextTest, TheWholeMomentumReadoutAt640x360) {
  const scene::SceneDesc scene = scene::loadPreset("ideal-gas");
  for (const char* tag : {"en", "de", "zh-Hans"}) {
    SCOPED_TRACE(tag);
    const text::ScopedLanguage language(tag);
    const app::Animation animation = app::animate(scene, {640, 360});
    const frame::FrameModel frame = animation.frames.frameAtSimulated(1.0);
    const std::vector<frame::DrawnItem> items = render::drawnItems(frame, 640, 360);
    ASSERT_FALSE(frame.panels.empty());
    EXPECT_TRUE(drawnWhole(frame.panels.front().info, items))
        << "\"" << frame.panels.front().info
        << "\" is not drawn whole; drawn:" << drawnTexts(items);
  }
}

// The ballistic pendulum's notes ("speed from h: (m₁ + m₂)/m₂ · √(2gh) = 200 m/s") in German at
// 640x360, through the whole swing: they were wrapped anew in frames where the block swung near
// them, narrower than "200 m/s" ("200 m/" | "s"). Every tenth of a second; about a second.
TEST(LayoutKeepsNotesTest, TheSpeedFromHKeepsItsUnitAndItsLinesThroughTheSwing) {
  const text::ScopedLanguage language("de");
  const app::Animation animation =
      app::animate(scene::loadPreset("ballistic-pendulum"), {640, 360});
  const compose::FrameSource& source = animation.frames;
  std::size_t notes_lines = 0;
  for (double t_s = 0.0; t_s <= source.simulatedDuration_s(); t_s += 0.1) {
    SCOPED_TRACE("t = " + std::to_string(t_s) + " s");
    const std::vector<frame::DrawnItem> items =
        render::drawnItems(source.frameAtSimulated(t_s), 640, 360);
    for (const frame::DrawnItem& item : items) {
      if (item.id.find("notes") == std::string::npos) continue;
      EXPECT_EQ(partedNumber(item), "");
      if (notes_lines == 0) notes_lines = item.lines.size();
      EXPECT_EQ(item.lines.size(), notes_lines) << readings(item).front();
    }
  }
  EXPECT_GT(notes_lines, 0u) << "no notes drawn";
}

// The thrown ball's drag caption in German: the layout kept the lines of the video's widest
// caption, and a narrower one of another shape that breaks into a line more lost its end
// (1.5-1.6 s). Each size about a second.
TEST(LayoutKeepsCaptionTest, TheWholeDragCaptionInGerman) {
  const scene::SceneDesc scene = scene::loadPreset("air-drag-throw");
  const text::ScopedLanguage language("de");
  for (const auto& [width_px, height_px] : {std::pair{1280, 720}, std::pair{640, 360}}) {
    const app::Animation animation = app::animate(scene, {width_px, height_px});
    for (const double t_s : {1.5, 1.55, 1.6}) {
      SCOPED_TRACE(std::to_string(width_px) + "x" + std::to_string(height_px) + " at " +
                   std::to_string(t_s) + " s");
      const frame::FrameModel frame = animation.frames.frameAtSimulated(t_s);
      const std::vector<frame::DrawnItem> items = render::drawnItems(frame, width_px, height_px);
      expectCaptionDrawnWhole(frame, items);
    }
  }
}

// The break in the pseudo-language at 640x360: the energy bar's legend stands in a staircase of
// rows under the side column's bar, and the caption's room is what those rows leave. The
// caption's last clause (the cloth's share, written nowhere else) was cut after "(49.2%)…" just
// after the first collision and at the end; the column is now widened until the caption fits.
// About a second.
TEST(LayoutKeepsCaptionTest, TheWholeBreakCaptionUnderAStaircaseLegend) {
  // The preset's title in the language too (it takes two lines there).
  const text::ScopedLanguage language("en-XA");
  const scene::SceneDesc scene = scene::loadPreset("billiards-break");
  const app::Animation animation = app::animate(scene, {640, 360});
  const compose::FrameSource& source = animation.frames;
  ASSERT_FALSE(source.timeline().collisions().empty());
  const double first_s = source.timeline().collisions().front().time_s;
  for (const double t_s : {first_s + 1e-3, source.simulatedDuration_s()}) {
    SCOPED_TRACE("at " + std::to_string(t_s) + " s");
    const frame::FrameModel frame = source.frameAtSimulated(t_s);
    const std::vector<frame::DrawnItem> items = render::drawnItems(frame, 640, 360);
    // The legend's entries in more than one row: the case the caption shares its column with.
    std::vector<double> rows_y;
    for (const frame::DrawnItem& item : items) {
      if (item.id.rfind("energy.", 0) != 0) continue;
      const bool seen = std::any_of(rows_y.begin(), rows_y.end(),
                                    [&](double y) { return std::abs(y - item.box.y0) < 1.0; });
      if (!seen) rows_y.push_back(item.box.y0);
    }
    EXPECT_GE(rows_y.size(), 2u) << "the legend is not a staircase; drawn:" << drawnTexts(items);
    expectCaptionDrawnWhole(frame, items);
  }
}

// ballistic-pendulum at 480x270 before its impact: the info reads the start momentum and the
// momentum now, the same vector (nothing acts on the bullet before it strikes). Wherever a line
// holds the start vector whole, the vector and its unit fit a line, and the now vector is not
// parted either: it was broken "(2.00," | "0) kg·m/s" like the widest vector of its shape in the
// whole video (the swing's "(−0.0476," | "−0.0356) kg·m/s"), which no frame of this shot shows.
// Under a second.
TEST(LayoutKeepsVectorTest, AVectorThatFitsALineThroughItsShotIsNotParted) {
  const app::Animation animation =
      app::animate(scene::loadPreset("ballistic-pendulum"), {480, 270});
  const double impact_s = animation.frames.timeline().collisions().front().time_s;
  int checked = 0;
  for (const double share : {0.0, 0.4, 0.8}) {
    const double t_s = share * impact_s;
    const std::vector<frame::DrawnItem> items =
        render::drawnItems(animation.frames.frameAtSimulated(t_s), 480, 270);
    const auto info = std::find_if(items.begin(), items.end(),
                                   [](const frame::DrawnItem& item) { return item.id == "info"; });
    ASSERT_NE(info, items.end());
    bool start_whole = false;
    for (const std::string& line : info->lines) {
      const bool whole = line.find(") kg") != std::string::npos && line.find('(') < line.find(')');
      start_whole = start_whole || whole;
    }
    if (!start_whole) continue;
    ++checked;
    for (const std::string& line : info->lines) {
      const bool opens = line.find('(') != std::string::npos;
      const bool closes = line.find(')') != std::string::npos;
      EXPECT_EQ(opens, closes) << "t = " << t_s << " s: a vector parted at \"" << line << "\"";
    }
  }
  EXPECT_EQ(checked, 3) << "a vector whole on a line before the impact";
}

INSTANTIATE_TEST_SUITE_P(Languages, LayoutKeepsTextTest, ::testing::ValuesIn(test::languageTags()),
                         test::languageName);

}  // namespace
}  // namespace collide
