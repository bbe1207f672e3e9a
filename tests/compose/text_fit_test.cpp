// Every line of text a frame draws (titles, headings, info lines, legend entries, captions, body
// and velocity labels, the scale arrow's label, ruler and chart tick labels, chart titles) checked
// on the canvas the painters draw from, no pixels read: no two lines overlap, none reaches outside
// the frame or outside the clip of what it is drawn in, and no text of the frame description is
// shortened without an ellipsis (a wrapped line counts as kept); on a screen no info line is
// shortened at all. Every preset, on screen (480x270, 640x360, 1280x720) and printed from 6 to
// 18 cm wide at 150 to 600 dpi; and every preset in every shipped language and the
// pseudo-language en-XA (strings 40 % longer) at 640x360, with the language's fonts and
// direction. At 640x360 no text is smaller than 10 px (em), the least a projected lesson or a
// small video window reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "frame/layout.hpp"
#include "language_params.hpp"
#include "pixel_rects.hpp"
#include "render/draw/canvas.hpp"
#include "render/draw/frame_drawing.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text_metrics.hpp"
#include "scene/scene_desc.hpp"
#include "text/language.hpp"
#include "text/wording.hpp"

namespace collide::text_fit {
namespace {

using frame::PixelRect;

const std::string kEllipsis = "\u2026";

struct DrawnText {
  std::string text;
  double size_px = 0.0;           // em size it is drawn at
  PixelRect box;                  // advance × line height, as the painter measures it
  std::optional<PixelRect> clip;  // the batch's clip
};

// Records every line of text (and where the batch clips it); shapes go to a MeshCanvas unseen.
class RecordingCanvas final : public render::Canvas {
 public:
  explicit RecordingCanvas(render::TextPainter& painter) : Canvas(painter), shapes_(painter) {}
  void clear() override {
    texts.clear();
    shapes_.clear();
  }
  void beginBatch(std::optional<PixelRect> clip) override {
    clip_ = clip;
    shapes_.beginBatch(clip);
  }
  void finish() override { shapes_.finish(); }
  render::ShapeSink& shapes() override { return shapes_.shapes(); }
  PixelRect text(std::string_view text, const core::Vec2& anchor_px, double size_px,
                 const frame::Rgba&, render::HAlign h, render::VAlign v) override {
    const PixelRect box = painter().place(text, anchor_px, size_px, h, v).box;
    texts.push_back({std::string(text), size_px, box, clip_});
    return box;
  }
  std::vector<DrawnText> texts;

 private:
  render::MeshCanvas shapes_;
  std::optional<PixelRect> clip_;
};

struct Size {
  std::string name;
  int width_px, height_px;
  double text_floor_px = 0.0;
  double least_text_px = 0.0;  // no text drawn smaller (em), 0: not checked
};

// The cramped screen size: text there is at least 10 px.
const Size kSmallScreen{"640x360", 640, 360, 0.0, 10.0};

// A figure printed width_cm wide at dpi with --print's default 3:2 aspect.
Size printed(double width_cm, double dpi) {
  const double width_px = width_cm / 2.54 * dpi;
  return {std::to_string(static_cast<int>(width_cm)) + "cm@" + std::to_string(int(dpi)),
          static_cast<int>(std::lround(width_px)),
          static_cast<int>(std::lround(width_px * 2.0 / 3.0)), frame::printTextFloorPx(dpi)};
}

// The text of the frame description that the painter must show (whole, wrapped or elided).
std::vector<std::string> requiredTexts(const frame::FrameModel& frame,
                                       const frame::FrameLayout& layout, bool on_screen) {
  std::vector<std::string> out{frame.title, frame.time_readout, frame.subtitle};
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    out.push_back(panel.heading);
    // (A printed figure's info gives way to its values where its scene is short:
    // PanelLayout::info_lines 0.)
    if (layout.panels[p].info_lines > 0) out.push_back(panel.info);
    // The velocity scale, stated once (the caption's end, or a grid's heading line) where the
    // panel draws its scene with arrows.
    const frame::PixelRect area = frame::worldArea(panel, layout.panels[p], layout);
    if (panel.scale_arrow_mps > 0.0 && panel.arrow_m_per_mps > 0.0 && area.width() > 1.0 &&
        area.height() > 1.0) {
      out.push_back(panel.scale_arrow_label);
    }
    // A comparison grid shows no captions (its alt text does).
    if (frame.panels.size() == 1) out.push_back(panel.caption);
    if (panel.show_energy_bar) {
      for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
        out.push_back(segment.label);
      }
    }
    for (const frame::BodyModel& body : panel.bodies) {
      out.push_back(body.label);
      out.push_back(body.velocity_label);
    }
    // On a screen a measured height's label and its notes (the speed the rise gives back: the
    // point of the ballistic pendulum) are drawn whole, wrapped or smaller, never left out (a
    // printed figure too small for them says them in its caption).
    for (const frame::DimensionModel& dim : panel.dimensions) {
      if (!on_screen) continue;
      out.push_back(dim.label);
      out.insert(out.end(), dim.notes.begin(), dim.notes.end());
    }
  }
  for (const frame::ChartModel& chart : frame.charts) {
    out.insert(out.end(), {chart.title, chart.x_label, chart.y_label});
    // A series is labelled at its line's end, so only once some of it is drawn (up to the cursor).
    for (const frame::ChartSeries& series : chart.series) {
      const bool drawn = !series.points.empty() &&
                         (!chart.cursor_x || series.points.front().x() <= *chart.cursor_x);
      if (drawn) out.push_back(series.label);
    }
  }
  out.erase(std::remove(out.begin(), out.end(), std::string()), out.end());
  return out;
}

using test::inside;
using test::overlaps;

// Runs of spaces as one: a text wrapped between clauses ("a   b") reads "a b" across its lines.
std::string squeezed(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c != ' ' || out.empty() || out.back() != ' ') out += c;
  }
  return out;
}

// The most lines one text is drawn in: a side column's caption down a tall printed figure.
constexpr std::size_t kMostLinesOfOneText = 40;

// Whether up to kMostLinesOfOneText consecutive drawn lines, joined
// where the text was wrapped (by a space, or by nothing after a break in Chinese or Japanese,
// text::ideographicLineBreaks), are `wanted`; with `elided`, whether they are its beginning
// followed by an ellipsis (the last line's "…").
bool wrappedRunIs(const std::vector<DrawnText>& texts, const std::string& wanted, bool elided) {
  for (std::size_t i = 0; i < texts.size(); ++i) {
    std::vector<std::string> runs{""};
    for (std::size_t j = i; j < texts.size() && j < i + kMostLinesOfOneText && !runs.empty(); ++j) {
      const std::string line = squeezed(texts[j].text);
      std::vector<std::string> longer;
      for (const std::string& run : runs) {
        for (const std::string joint : {" ", ""}) {
          const std::string joined = run.empty() ? line : run + joint + line;
          if (!elided && joined == wanted) return true;
          if (elided && line.ends_with(kEllipsis)) {
            const std::string kept = joined.substr(0, joined.size() - kEllipsis.size());
            if (kept.size() > 1 && wanted.starts_with(kept)) return true;
          }
          if (wanted.starts_with(joined)) longer.push_back(joined);
          if (run.empty()) break;
        }
      }
      runs = std::move(longer);
    }
  }
  return false;
}

// The numbers written in `text` as a reader parses them: an optional sign ("-", "\u2212", "+")
// and digits with at most one decimal mark ("." or "," between digits), so a German "0,159"
// and an English "0.159" read alike and brackets or accents around a number do not matter.
std::vector<double> numbersIn(std::string_view text) {
  std::vector<double> out;
  const std::string_view kMinus = "\u2212";
  auto digit = [&](std::size_t i) {
    return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]));
  };
  for (std::size_t i = 0; i < text.size();) {
    if (!digit(i)) {
      ++i;
      continue;
    }
    double sign = 1.0;
    if (i > 0 && text[i - 1] == '-') sign = -1.0;
    if (i >= kMinus.size() && text.substr(i - kMinus.size(), kMinus.size()) == kMinus) sign = -1.0;
    std::string number;
    while (digit(i)) number += text[i++];
    if (i + 1 < text.size() && (text[i] == '.' || text[i] == ',') && digit(i + 1)) {
      number += '.';
      ++i;
      while (digit(i)) number += text[i++];
    }
    out.push_back(sign * std::stod(number));
  }
  return out;
}

// Whether every number of `wanted` is among `numbers` (each one used once).
bool containsAll(std::vector<double> numbers, const std::vector<double>& wanted) {
  for (double w : wanted) {
    const auto found = std::find(numbers.begin(), numbers.end(), w);
    if (found == numbers.end()) return false;
    numbers.erase(found);
  }
  return true;
}

// What a text that ends in an ellipsis leaves out of `wanted`: the parts (clauses and list
// items, split at the language's separators) after the longest beginning of `wanted` that a run
// of consecutive drawn lines shows, with the indices of that run's lines; nothing left out (or
// no such run): {{}, {}}.
std::pair<std::vector<std::string>, std::vector<std::size_t>> leftOut(
    const std::vector<DrawnText>& texts, const std::string& wanted) {
  std::string best_kept;
  std::vector<std::size_t> best_run;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    std::string run;
    for (std::size_t j = i; j < texts.size() && j < i + kMostLinesOfOneText; ++j) {
      const std::string line = squeezed(texts[j].text);
      // Joined as wrapped: by a space, or by nothing (Chinese, Japanese, a word parted).
      const std::string bare =
          line.ends_with(kEllipsis) ? line.substr(0, line.size() - kEllipsis.size()) : line;
      const std::string joined =
          run.empty() || !wanted.starts_with(run + " " + bare) ? run + line : run + " " + line;
      if (line.ends_with(kEllipsis)) {
        const std::string kept = joined.substr(0, joined.size() - kEllipsis.size());
        if (kept.size() > best_kept.size() && wanted.starts_with(kept)) {
          best_kept = kept;
          best_run.clear();
          for (std::size_t k = i; k <= j; ++k) best_run.push_back(k);
        }
        break;
      }
      if (!wanted.starts_with(joined)) break;
      run = joined;
    }
  }
  if (best_run.empty()) return {};
  std::vector<std::string> parts{wanted.substr(best_kept.size())};
  for (const std::string& separator : {text::clauseSeparator(), text::listSeparator(),
                                       std::string("; "), std::string(", "), std::string("   ")}) {
    std::vector<std::string> split;
    for (const std::string& part : parts) {
      std::size_t from = 0;
      for (std::size_t at = part.find(separator); at != std::string::npos;
           at = part.find(separator, from)) {
        split.push_back(part.substr(from, at - from));
        from = at + separator.size();
      }
      split.push_back(part.substr(from));
    }
    parts = std::move(split);
  }
  std::vector<std::string> out;
  for (std::string& part : parts) {
    while (part.starts_with(" ")) part.erase(0, 1);
    while (part.ends_with(" ") || part.ends_with(".")) part.pop_back();
    if (!part.empty()) out.push_back(part);
  }
  return {out, best_run};
}

std::string describe(const DrawnText& t) {
  char where[96];
  std::snprintf(where, sizeof where, " [%.0f,%.0f]-[%.0f,%.0f]", t.box.x0, t.box.y0, t.box.x1,
                t.box.y1);
  return "\"" + t.text + "\"" + where;
}

// Returns the number of lines checked.
std::size_t checkFrame(const frame::FrameModel& frame, const Size& size,
                       render::TextPainter& painter) {
  const bool notes_required = size.text_floor_px == 0.0;  // on a screen
  const frame::FrameLayout layout = frame::layoutFrame(
      frame, size.width_px, size.height_px, size.text_floor_px,
      [&painter](std::string_view text, double px) { return painter.width(text, px); });
  RecordingCanvas canvas(painter);
  render::drawFrame(frame, layout, canvas);
  const std::vector<DrawnText>& texts = canvas.texts;
  // Half a pixel: boxes are measured on fractional pens, glyphs land on whole pixels.
  constexpr double kSlack = 0.5;
  const PixelRect whole{0.0, 0.0, double(size.width_px), double(size.height_px)};
  for (const DrawnText& t : texts) {
    EXPECT_GE(t.size_px, size.least_text_px)
        << describe(t) << " is drawn at " << t.size_px << " px";
    EXPECT_TRUE(inside(t.box, whole, kSlack)) << describe(t) << " reaches outside the frame";
    if (t.clip) {
      EXPECT_TRUE(inside(t.box, *t.clip, kSlack)) << describe(t) << " is cut by its clip";
    }
  }
  for (std::size_t a = 0; a < texts.size(); ++a) {
    for (std::size_t b = a + 1; b < texts.size(); ++b) {
      EXPECT_FALSE(overlaps(texts[a].box, texts[b].box, kSlack))
          << describe(texts[a]) << " overlaps " << describe(texts[b]);
    }
  }
  std::string all = " ";
  for (const DrawnText& t : texts) all += squeezed(t.text) + " ";
  // A chart's title says what it shows and is never shortened; its notes (the force chart's
  // impulse and when the contact began) are shown whole, on a screen always.
  for (const frame::ChartModel& chart : frame.charts) {
    if (!chart.title.empty()) {
      EXPECT_TRUE(wrappedRunIs(texts, squeezed(chart.title), false))
          << "the chart title \"" << chart.title << "\" is not shown whole; drawn:" << all;
    }
    for (const std::string& note : chart.notes) {
      const bool whole = wrappedRunIs(texts, squeezed(note), false);
      EXPECT_TRUE(whole || (!notes_required && !wrappedRunIs(texts, squeezed(note), true)))
          << "the chart note \"" << note << "\" is not shown whole; drawn:" << all;
    }
  }
  // A side column's caption gives way only where it repeats what the frame writes elsewhere:
  // each part it leaves out (a clause or an item after its last line's ellipsis) is a value
  // that another drawn line states (a velocity written beside its arrow: the same numbers, as a
  // reader parses them); words (a clause without a number) are written nowhere else. The list's
  // own "…" (more values than a caption lists) says only that something follows.
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    const std::string caption = squeezed(frame.panels[p].caption);
    if (caption.empty() || layout.panels[p].scale_row.height() <= 0.0) continue;
    if (wrappedRunIs(texts, caption, false)) continue;
    const auto [parts, run] = leftOut(texts, caption);
    for (const std::string& part : parts) {
      if (part == kEllipsis) continue;
      const std::vector<double> numbers = numbersIn(part);
      bool elsewhere = false;
      for (std::size_t k = 0; k < texts.size() && !elsewhere; ++k) {
        if (std::find(run.begin(), run.end(), k) != run.end()) continue;
        const std::string line = squeezed(texts[k].text);
        elsewhere = numbers.empty() ? line.find(part) != std::string::npos
                                    : containsAll(numbersIn(line), numbers);
      }
      EXPECT_TRUE(elsewhere) << "the side column's caption leaves out \"" << part
                             << "\", written nowhere else; drawn:" << all;
    }
  }
  // On a screen an info line states quantities no other text repeats (collisions, ω, Σp): it is
  // shown whole, never cut (stick-2d at 640x360 lost its Σp after "ω = −1.60 rad/s…").
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size() && notes_required;
       ++p) {
    const std::string info = squeezed(frame.panels[p].info);
    if (info.empty() || layout.panels[p].info_lines == 0) continue;
    EXPECT_TRUE(wrappedRunIs(texts, info, false))
        << "the info \"" << info << "\" is not shown whole; drawn:" << all;
  }
  // Shown whole: a run of consecutive drawn lines (a wrapped text) is it; or
  // shortened visibly: a drawn line is its beginning followed by an ellipsis.
  // (Only runs of lines, never text that merely happens to follow another on the canvas.)
  // (compose clears a measured height's label only where it gives way on a printed figure.)
  for (const frame::PanelModel& panel : frame.panels) {
    for (const frame::DimensionModel& dim : panel.dimensions) {
      EXPECT_TRUE(!notes_required || !dim.label.empty()) << "a measured height lost its label";
    }
  }
  for (const std::string& whole : requiredTexts(frame, layout, notes_required)) {
    const std::string wanted = squeezed(whole);
    if (wrappedRunIs(texts, wanted, false)) continue;
    // The drawn line with the ellipsis may end a wrapped run (a caption's second line).
    const bool elided = wrappedRunIs(texts, wanted, true);
    EXPECT_TRUE(elided) << "\"" << wanted << "\" is shortened without an ellipsis; drawn:" << all;
  }
  return texts.size();
}

void checkPreset(const scene::PresetInfo& preset, const Size& size, render::TextPainter& painter,
                 bool every_instant) {
  const scene::SceneDesc scene = scene::loadPreset(preset.name);
  const app::Animation animation =
      app::animate(scene, {size.width_px, size.height_px, size.text_floor_px});
  const compose::FrameSource& source = animation.frames;
  const double end = source.simulatedDuration_s();
  const double first = source.timeline().collisions().empty()
                           ? 0.5 * end
                           : source.timeline().collisions().front().time_s;
  std::vector<std::pair<std::string, double>> instants{{"after", first + 1e-3}, {"end", end}};
  if (every_instant) instants.insert(instants.begin(), {{"start", 0.0}, {"middle", 0.5 * end}});
  std::size_t lines = 0;
  for (const auto& [name, t] : instants) {
    SCOPED_TRACE(preset.name + " " + name + " at " + size.name);
    lines += checkFrame(source.frameAtSimulated(std::clamp(t, 0.0, end)), size, painter);
  }
  SCOPED_TRACE(preset.name + " strobe at " + size.name);
  lines += checkFrame(source.strobeFrame(scene.view.strobe_rate_hz), size, painter);
  EXPECT_GT(lines, 0u) << "no text drawn";
}

class TextFitTest : public ::testing::TestWithParam<Size> {};

TEST_P(TextFitTest, EveryLineInsideTheFrameApartAndWhole) {
  const Size size = GetParam();
  // An atlas per size: glyphs of a 600 dpi figure are large.
  render::FontSet fonts(render::textFontsFor(render::defaultFontPath(), "en"));
  render::GlyphAtlas atlas(fonts);
  render::TextPainter painter(atlas);
  const bool screen = size.text_floor_px == 0.0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    // A crowd (the gas) takes seconds to simulate and its panel draws no body labels: the
    // cramped print size alone checks its readouts and chart.
    const bool crowd = scene::loadPreset(preset.name).bodies.size() > 40;
    if (crowd && size.name != "6cm@150") continue;
    checkPreset(preset, size, painter, screen);
  }
}

// Every preset after its first collision, at its end and as a strobe, in one language at 640x360
// (the screen size with the least room) and at 1280x720 (where words are longest against the
// frame's room: a German note is wider than its English one at the same text size), shaped with
// that language's fonts: nothing the frame description asks for is left out.
class TextFitLanguageTest : public ::testing::TestWithParam<std::string> {};

TEST_P(TextFitLanguageTest, EveryLineInsideTheFrameApartAndWhole) {
  const text::ScopedLanguage language(GetParam());
  render::FontSet fonts(render::textFontsFor(render::defaultFontPath(), GetParam()));
  render::GlyphAtlas atlas(fonts);
  render::TextPainter painter(atlas);
  for (const Size& size : {kSmallScreen, Size{"1280x720", 1280, 720}}) {
    for (const scene::PresetInfo& preset : scene::presetList()) {
      // The gas's words are its readouts and chart, checked in every language by the other
      // presets; it alone takes seconds to simulate.
      if (scene::loadPreset(preset.name).bodies.size() > 40) continue;
      checkPreset(preset, size, painter, false);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Languages, TextFitLanguageTest, ::testing::ValuesIn(test::languageTags()),
                         test::languageName);

std::string sizeName(const ::testing::TestParamInfo<Size>& info) {
  std::string name = info.param.name;
  std::replace(name.begin(), name.end(), '@', '_');
  return name;
}

// The print sizes span the range a teacher uses (6 to 18 cm, 150 to 600 dpi); layout scales with
// the text floor, so these cover the cramped end (6 cm at 150 dpi) and the roomy end.
INSTANTIATE_TEST_SUITE_P(Sizes, TextFitTest,
                         ::testing::Values(kSmallScreen, Size{"480x270", 480, 270},
                                           Size{"1280x720", 1280, 720}, printed(6.0, 150.0),
                                           printed(8.0, 300.0), printed(12.0, 600.0),
                                           printed(18.0, 150.0)),
                         sizeName);

}  // namespace
}  // namespace collide::text_fit
