// SPDX-License-Identifier: MIT
// Every number on every preset's pictures and alt text is legible (at most four significant
// figures, no exponent, no "-0", nothing cut off with an ellipsis), and a label that gives way
// leaves nothing behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "frame_numbers.hpp"
#include "report/alt_text.hpp"
#include "report/narration.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

using frame_numbers::everyPreset;
using frame_numbers::instant;
using frame_numbers::kInstants;
using frame_numbers::Picture;

// Every number in `text`: fails on more than four significant figures, an exponent, a negative
// zero, or an ellipsis. The one ellipsis allowed is a whole last list item (", …"): a caption of a
// scene with many bodies lists its first velocities and says that more follow.
void expectLegible(const std::string& full_text, const std::string& where) {
  SCOPED_TRACE(where + ": " + full_text);
  const std::string ellipsis = "\u2026";  // U+2026, one character
  const std::string more = ", " + ellipsis;
  const std::string text =
      full_text.ends_with(more) ? full_text.substr(0, full_text.size() - more.size()) : full_text;
  EXPECT_EQ(text.find(ellipsis), std::string::npos) << "ellipsis";
  EXPECT_EQ(text.find("..."), std::string::npos) << "ellipsis";
  static const std::regex exponent(R"([0-9]\.?[eE][+\-\xE2]?[0-9])");
  EXPECT_FALSE(std::regex_search(text, exponent)) << "exponent";
  // A count ("collisions: 12797", "12797 collisions": the ideal gas after 3 s) is exact and read
  // whole: not a measurement, so not held to four figures.
  static const std::regex count(R"(collisions: [0-9,]+|[0-9,]+ collisions)");
  const std::string measured = std::regex_replace(text, count, "collisions");
  // Numbers: digits with thousands groups and decimals, optionally signed.
  static const std::regex number(
      R"(((?:\xE2\x88\x92|-)?)([0-9]{1,3}(?:,[0-9]{3})+|[0-9]+)(?:\.([0-9]+))?)");
  for (auto it = std::sregex_iterator(measured.begin(), measured.end(), number);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    std::string digits = std::string(m[2]) + std::string(m[3]);
    digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) {
      EXPECT_TRUE(std::string(m[1]).empty()) << "negative zero: " << m.str();
      continue;
    }
    // Trailing zeros of an integer are not significant (12,500); decimals' are.
    std::string significant = digits.substr(first);
    if (!m[3].matched) {
      while (significant.size() > 1 && significant.back() == '0') significant.pop_back();
    }
    EXPECT_LE(significant.size(), 4u) << "too many figures: " << m.str();
  }
}

void expectFrameLegible(const frame::FrameModel& frame, const std::string& where) {
  expectLegible(frame.title, where + " title");
  expectLegible(frame.time_readout, where + " time");
  expectLegible(frame.subtitle, where + " subtitle");
  for (const frame::PanelModel& panel : frame.panels) {
    expectLegible(panel.heading, where + " heading");
    expectLegible(panel.info, where + " info");
    expectLegible(panel.caption, where + " caption");
    for (const frame::BodyModel& body : panel.bodies) {
      expectLegible(body.label, where + " label");
      expectLegible(body.velocity_label, where + " velocity");
    }
    for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
      expectLegible(segment.label, where + " bar");
    }
  }
  for (const frame::ChartModel& chart : frame.charts) {
    expectLegible(chart.title, where + " chart title");
    expectLegible(chart.y_label, where + " chart axis");
  }
}

TEST(FrameNumbersTest, EveryTextOfEveryPresetIsLegible) {
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    std::vector<report::PanelDescription> panels;
    for (std::size_t p = 0; p < frames.panelCount(); ++p) {
      panels.push_back({frames.panelHeading(p), &frames.panelTimeline(p)});
    }
    for (int k = 0; k < kInstants; k += 3) {
      const double t = instant(picture.scene, k);
      const std::string where = picture.preset + " at " + std::to_string(t);
      expectFrameLegible(frames.frameAtSimulated(t), where);
      expectLegible(report::describePanels(panels, picture.scene.title, t), where + " alt text");
    }
    expectFrameLegible(frames.strobeFrame(5.0), picture.preset + " strobe");
    expectFrameLegible(frames.chartFrame(), picture.preset + " chart");
    report::NarrationOptions options;
    options.title = picture.scene.title;
    for (const report::Cue& cue : report::narrate(frames.timeline(), options)) {
      expectLegible(cue.text, picture.preset + " caption cue");
    }
  }
}

// A label that gives way (to the body's number, in a crowd) leaves nothing behind: no place and so
// no leader line pointing from empty space at its body; every label still shown has its place.
TEST(FrameNumbersTest, ALabelThatGivesWayLeavesNoLeader) {
  int dropped = 0, placed = 0;
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    for (int k = 0; k < kInstants; ++k) {
      const double t = instant(picture.scene, k);
      for (const frame::PanelModel& panel : frames.frameAtSimulated(t).panels) {
        for (const frame::BodyModel& body : panel.bodies) {
          SCOPED_TRACE(picture.preset + " at " + std::to_string(t));
          for (const auto& [text, at] :
               {std::pair{&body.label, &body.label_at},
                std::pair{&body.velocity_label, &body.velocity_label_at}}) {
            EXPECT_EQ(text->empty(), !at->has_value()) << *text;
            dropped += text->empty() && !body.tag.empty() ? 1 : 0;
            placed += at->has_value() ? 1 : 0;
          }
        }
      }
    }
  }
  EXPECT_GT(dropped, 0);  // pi-blocks' small block gives way beside the big one
  EXPECT_GT(placed, 100);
}
}  // namespace
}  // namespace collide
