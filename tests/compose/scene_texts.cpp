#include "scene_texts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

#include "frame/mark_sizes.hpp"

namespace collide::compose_test {
namespace {

// Text that names no body and has no leader (a dimension's, the legend's lines).
SceneText plainText(const Box& box, const std::string& text) {
  SceneText t;
  t.box = box;
  t.text = text;
  return t;
}

}  // namespace

void gatherSceneTexts(const frame::PanelModel& panel, const frame::FrameLayout& layout,
                      const frame::WorldToPixel& to_px, render::TextMetrics& metrics,
                      double text_floor_px, std::vector<SceneText>& texts) {
  const double line_box = metrics.ascender(layout.text_px) + metrics.descender(layout.text_px);
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    for (const auto& [text, at] : {std::pair{&body.label, &body.label_at},
                                   std::pair{&body.velocity_label, &body.velocity_label_at}}) {
      if (text->empty()) continue;
      SCOPED_TRACE(*text);
      ASSERT_TRUE(at->has_value()) << "a label without a place";
      const frame::PlacedText& placed = **at;
      const Box box{placed.top_left_px.x(), placed.top_left_px.y(),
                    placed.top_left_px.x() + placed.size_px.x(),
                    placed.top_left_px.y() + placed.size_px.y()};
      // The box is the text's real extent.
      EXPECT_NEAR(placed.size_px.x(), metrics.width(*text, layout.text_px), 0.5);
      EXPECT_NEAR(placed.size_px.y(), line_box, 0.5);
      SceneText entry{box, *text, i, text == &body.velocity_label, std::nullopt, std::nullopt};
      if (placed.leader_to_px) {
        const core::Vec2& to = *placed.leader_to_px;
        entry.leader_to = to;
        entry.leader_from =
            core::Vec2{std::clamp(to.x(), box.x0, box.x1), std::clamp(to.y(), box.y0, box.y1)};
      }
      texts.push_back(entry);
    }
  }
  for (const frame::DimensionModel& dim : panel.dimensions) {
    if (dim.label_at && !dim.label.empty()) {
      const frame::PlacedText& placed = *dim.label_at;
      texts.push_back(plainText({placed.top_left_px.x(), placed.top_left_px.y(),
                                 placed.top_left_px.x() + placed.size_px.x(),
                                 placed.top_left_px.y() + placed.size_px.y()},
                                dim.label));
    }
    // The notes state the speed the rise gives back, the point of the picture: on a screen
    // they always find a place (at print sizes they may give way to the bodies' labels).
    if (text_floor_px == 0.0) {
      EXPECT_TRUE(dim.notes.empty() || dim.notes_at_px) << "the notes found no place";
    }
    if (dim.notes_at_px && !dim.notes.empty()) {
      // The notes' lines (as compose broke them, where it did), 1.3 em apart, as the painter
      // draws them.
      core::Vec2 at = *dim.notes_at_px;
      const std::vector<std::string>& lines = dim.notes_lines.empty() ? dim.notes : dim.notes_lines;
      for (const std::string& line : lines) {
        texts.push_back(plainText(
            {at.x(), at.y(), at.x() + metrics.width(line, layout.text_px), at.y() + line_box},
            line));
        at.y() += 1.3 * layout.text_px;
      }
      // Broken into lines, they still say every word of the notes.
      const auto joined = [](const std::vector<std::string>& parts) {
        std::string all;
        for (const std::string& part : parts) all += (all.empty() ? "" : " ") + part;
        return all;
      };
      EXPECT_EQ(joined(lines), joined(dim.notes));
    }
  }

  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    const core::Vec2& at = entry.top_left_px;
    texts.push_back(plainText(
        {at.x(), at.y(), at.x() + metrics.width(entry.text, layout.text_px), at.y() + line_box},
        entry.text));
    // The legend names its body by the number the body shows: inside it (where the painter
    // writes it: frame::tagFitsInside) or, for a body too small for it, beside it. (At print
    // sizes a speck of a ball under a contact flash has no room for it yet.)
    ASSERT_GE(entry.body, 0);
    ASSERT_LT(entry.body, static_cast<int>(panel.bodies.size()));
    const frame::BodyModel& named = panel.bodies[static_cast<std::size_t>(entry.body)];
    EXPECT_FALSE(named.tag.empty()) << entry.text << ": its body carries no number";
    if (text_floor_px > 0.0) continue;
    EXPECT_TRUE(frame::tagFitsInside(named, layout, to_px) || named.tag_at)
        << entry.text << ": the legend names body " << entry.body + 1
        << " by a number the picture does not show";
  }
  // A number beside its body is text like any other: clear of everything, nearest its body.
  const double small_box = metrics.ascender(layout.small_px) + metrics.descender(layout.small_px);
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    if (!body.tag_at || body.tag.empty()) continue;
    const core::Vec2& at = body.tag_at->top_left_px;
    SceneText tag{
        {at.x(), at.y(), at.x() + metrics.width(body.tag, layout.small_px), at.y() + small_box},
        body.tag,
        i,
        false,
        std::nullopt,
        std::nullopt};
    texts.push_back(tag);
  }
}

}  // namespace collide::compose_test
