// Label placement and framing, checked on the frame description (no pixels read): every preset at
// five instants (start, just before and just after the first collision, middle, end) and its
// strobe, at 1280x720 and 640x360, also with every label 40 % longer (translations often are),
// and as a figure printed 8 cm wide at 300 dpi.
// Every text box lies inside the frame, covers no body, arrow, wall, string or contact flash, keeps
// about a word space from every other text, and is nearer its own body than any other; every leader
// line strikes through no other text, leader, arrow, wall, flash or body.
// The geometry of bodies and arrows is recomputed here from the FrameModel and render's layout,
// independently of compose's own obstacle list.
#include "compose/label_placement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "label_reading_checks.hpp"
#include "pixel_distances.hpp"
#include "render/layout.hpp"
#include "render/mark_sizes.hpp"
#include "render/text_metrics.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

using compose_test::Box;
using compose_test::PixelBody;
using compose_test::pointToBox;
using compose_test::segmentToBox;

struct Size {
  int width_px, height_px;
  double text_floor_px = 0.0;  // a printed figure's (render::printTextFloorPx)
};

bool intersects(const Box& a, const Box& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// Two lines of text read as two when there is about a word space between them across, or any
// room at all above or below (the line box holds the font's own leading): these many em.
constexpr double kLeastGapAcrossEm = 0.25;
constexpr double kLeastGapAlongEm = 0.05;
bool apart(const Box& a, const Box& b, double em) {
  const double across = std::max(a.x0 - b.x1, b.x0 - a.x1);
  const double along = std::max(a.y0 - b.y1, b.y0 - a.y1);
  return across >= kLeastGapAcrossEm * em || along >= kLeastGapAlongEm * em;
}

double pointToSegment(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b) {
  const core::Vec2 ab = b - a;
  const double t =
      ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Distance between two segments, by dense sampling of the first.
double segmentToSegment(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                        const core::Vec2& d) {
  const int steps = std::max(1, static_cast<int>((b - a).norm() / 0.25));
  double best = INFINITY;
  for (int i = 0; i <= steps; ++i)
    best = std::min(best, pointToSegment(a + (b - a) * (double(i) / steps), c, d));
  return best;
}

struct Arrow {
  core::Vec2 tail, tip;
  double half_width;
  std::size_t body;
};

// A mark drawn as a thick segment (a disk when a == b): walls with their hatching, contact flashes.
struct Mark {
  core::Vec2 a, b;
  double half_width;
  std::string what;
};

// A line of text placed in the scene, and the leader line the painter draws from it (from the
// box's point nearest the leader's end, render/draw_world.cpp).
struct Text {
  Box box;
  std::string text;
  std::optional<std::size_t> body;  // the body it names (none: a dimension's text)
  bool velocity = false;
  std::optional<core::Vec2> leader_from, leader_to;
};

// Text that names no body and has no leader (a dimension's, the legend's lines).
Text plainText(const Box& box, const std::string& text) {
  Text t;
  t.box = box;
  t.text = text;
  return t;
}

std::string lengthened(const std::string& text) {
  if (text.empty()) return text;
  const std::size_t extra = (text.size() * 4 + 9) / 10;  // bytes: at least 40 % more characters
  return text + std::string(extra, 'x');
}

// Checks one frame; `where` names it in failures.
// `values_shown`: whether every arrow's value and every numbered body's mass must be shown.
void checkFrame(const render::FrameModel& frame, Size size, render::TextMetrics& metrics,
                const std::string& where, bool values_shown = true) {
  SCOPED_TRACE(where);
  const render::FrameLayout layout = render::layoutFrame(
      frame, size.width_px, size.height_px, size.text_floor_px,
      [&metrics](std::string_view text, double px) { return metrics.width(text, px); });
  const double line_box = metrics.ascender(layout.text_px) + metrics.descender(layout.text_px);
  std::vector<Box> all_texts;
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const render::PanelModel& panel = frame.panels[p];
    ASSERT_EQ(panel.placed_for_width_px, size.width_px);
    ASSERT_EQ(panel.placed_for_height_px, size.height_px);
    ASSERT_EQ(panel.placed_for_scale_px, layout.scale_px);
    const render::WorldToPixel to_px = render::panelMapping(panel, layout.panels[p], layout);
    const render::PixelRect area = render::worldArea(panel, layout.panels[p], layout);
    std::vector<PixelBody> bodies;
    std::vector<Arrow> arrows;
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const render::BodyModel& body = panel.bodies[i];
      const core::Vec2 c = to_px.toPixel(body.center_m);
      const double hx = to_px.px_per_m * body.half_extent_m.x();
      const bool disk = body.shape == render::BodyShape::kDisk;
      const double hy = disk ? hx : to_px.px_per_m * body.half_extent_m.y();
      bodies.push_back({disk, c, {hx, hy}});
      const double speed = body.velocity_mps.norm();
      if (speed > 1e-6 && panel.arrow_m_per_mps > 0.0 && body.moves_with < 0) {
        const core::Vec2 d{body.velocity_mps.x() / speed, -body.velocity_mps.y() / speed};
        // 1D: above the body; a lifted arrow (arrow_row r) r rows of a head's width and a gap
        // above the tallest body's arrow line.
        double line_y = c.y() - hy - layout.arrow_gap_px;
        if (body.arrow_row > 0) {
          for (const render::BodyModel& other : panel.bodies) {
            line_y = std::min(line_y, to_px.toPixel(other.center_m).y() -
                                          to_px.px_per_m * other.half_extent_m.y() -
                                          layout.arrow_gap_px);
          }
          line_y -= body.arrow_row * (layout.arrow_head_width_px + layout.gap_px);
        }
        const core::Vec2 tail = panel.two_d ? c : core::Vec2{c.x(), line_y};
        // To scale, but never longer than the panel's off-scale limit nor shorter than the
        // painter's visible minimum: one head length, in 2D beyond the disk's edge.
        const double least =
            1.0 * layout.arrow_head_length_px + (panel.two_d ? std::max(hx, hy) : 0.0);
        double length = speed * panel.arrow_m_per_mps * to_px.px_per_m;
        if (panel.arrow_max_length_m > 0.0) {
          length = std::min(length, panel.arrow_max_length_m * to_px.px_per_m);
        }
        length = std::max(length, least);
        // 1D: one that would reach the face of a wall it moves towards is drawn back, its tip a
        // gap short of it.
        double room = INFINITY;
        for (const render::WallModel& wall : panel.walls) {
          const double ahead = (to_px.toPixel(wall.point_m).x() - c.x()) * d.x();
          if (!panel.two_d && wall.normal.x() * d.x() < 0.0 && ahead >= 0.0) {
            room = std::min(room, ahead - layout.gap_px);
          }
        }
        const core::Vec2 start = tail - std::max(0.0, length - room) * d;
        arrows.push_back({start, start + length * d, 0.5 * layout.arrow_head_width_px, i});
      }
    }
    // Walls (their line and hatching: a track-width line twice as thick and strokes of the hatch
    // length on the solid side) and contact flashes, as the painter draws them.
    std::vector<Mark> marks;
    const double wall_half = 2.0 * layout.track_px + render::kWallHatchLength * layout.scale_px;
    for (const render::WallModel& wall : panel.walls) {
      const core::Vec2 w = to_px.toPixel(wall.point_m);
      if (!panel.two_d) {
        marks.push_back({{w.x(), to_px.toPixel({0.0, panel.track_y_m}).y()},
                         {w.x(), area.y0},
                         wall_half,
                         "a wall"});
      } else {
        const core::Vec2 along{wall.normal.y(), wall.normal.x()};
        const double reach = 2.0 * (size.width_px + size.height_px);
        marks.push_back({w - reach * along, w + reach * along, wall_half, "a wall"});
      }
    }
    for (const render::FlashModel& flash : panel.flashes) {
      const core::Vec2 f = to_px.toPixel(flash.center_m);
      marks.push_back({f, f, render::flashRadiusPx(flash, layout, to_px), "a flash"});
    }
    // Strings (lines 0.6 of the line width thick, at least a pixel), their pivots, and the
    // beams they hang from (a beam under its line's height, hatched above with strokes at 45°).
    for (const render::StringModel& string : panel.suspension.strings) {
      const core::Vec2 pivot = to_px.toPixel(string.pivot_m);
      marks.push_back({pivot, to_px.toPixel(string.body_m),
                       0.5 * std::max(1.0, 0.6 * layout.line_px), "a string"});
      marks.push_back({pivot, pivot, std::max(1.5, render::kPivotRadius * layout.scale_px),
                       "a string's pivot"});
    }
    for (const render::SupportModel& support : panel.suspension.supports) {
      const core::Vec2 a = to_px.toPixel(support.from_m), b = to_px.toPixel(support.to_m);
      const double beam = render::kSupportThickness * layout.scale_px;
      const double hatch = render::kSupportHatchLength * layout.scale_px / std::sqrt(2.0);
      // As a thick segment through the middle of the beam and its hatching.
      const double half = 0.5 * (beam + hatch), y = a.y() - half;
      marks.push_back({{std::min(a.x(), b.x()) + half, y},
                       {std::max(a.x(), b.x()) + hatch - half, y},
                       half,
                       "the beam strings hang from"});
    }

    std::vector<Text> texts;
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const render::BodyModel& body = panel.bodies[i];
      for (const auto& [text, at] : {std::pair{&body.label, &body.label_at},
                                     std::pair{&body.velocity_label, &body.velocity_label_at}}) {
        if (text->empty()) continue;
        SCOPED_TRACE(*text);
        ASSERT_TRUE(at->has_value()) << "a label without a place";
        const render::PlacedText& placed = **at;
        const Box box{placed.top_left_px.x(), placed.top_left_px.y(),
                      placed.top_left_px.x() + placed.size_px.x(),
                      placed.top_left_px.y() + placed.size_px.y()};
        // The box is the text's real extent.
        EXPECT_NEAR(placed.size_px.x(), metrics.width(*text, layout.text_px), 0.5);
        EXPECT_NEAR(placed.size_px.y(), line_box, 0.5);
        Text entry{box, *text, i, text == &body.velocity_label, std::nullopt, std::nullopt};
        if (placed.leader_to_px) {
          const core::Vec2& to = *placed.leader_to_px;
          entry.leader_to = to;
          entry.leader_from =
              core::Vec2{std::clamp(to.x(), box.x0, box.x1), std::clamp(to.y(), box.y0, box.y1)};
        }
        texts.push_back(entry);
      }
    }
    for (const render::DimensionModel& dim : panel.suspension.dimensions) {
      if (dim.label_at && !dim.label.empty()) {
        const render::PlacedText& placed = *dim.label_at;
        texts.push_back(plainText({placed.top_left_px.x(), placed.top_left_px.y(),
                                   placed.top_left_px.x() + placed.size_px.x(),
                                   placed.top_left_px.y() + placed.size_px.y()},
                                  dim.label));
      }
      // The notes state the speed the rise gives back, the point of the picture: on a screen
      // they always find a place (at print sizes they may give way to the bodies' labels).
      if (size.text_floor_px == 0.0) {
        EXPECT_TRUE(dim.notes.empty() || dim.notes_at_px) << "the notes found no place";
      }
      if (dim.notes_at_px && !dim.notes.empty()) {
        // The notes' lines (as compose broke them, where it did), 1.3 em apart, as the painter
        // draws them.
        core::Vec2 at = *dim.notes_at_px;
        const std::vector<std::string>& lines =
            dim.notes_lines.empty() ? dim.notes : dim.notes_lines;
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

    for (const render::ReadoutLegend::Entry& entry : panel.legend.entries) {
      const core::Vec2& at = entry.top_left_px;
      texts.push_back(plainText(
          {at.x(), at.y(), at.x() + metrics.width(entry.text, layout.text_px), at.y() + line_box},
          entry.text));
      // The legend names its body by the number the body shows: inside it (where the painter
      // writes it: render::tagFitsInside) or, for a body too small for it, beside it. (At print
      // sizes a speck of a ball under a contact flash has no room for it yet.)
      ASSERT_GE(entry.body, 0);
      ASSERT_LT(entry.body, static_cast<int>(panel.bodies.size()));
      const render::BodyModel& named = panel.bodies[static_cast<std::size_t>(entry.body)];
      EXPECT_FALSE(named.tag.empty()) << entry.text << ": its body carries no number";
      if (size.text_floor_px > 0.0) continue;
      EXPECT_TRUE(render::tagFitsInside(named, layout, to_px) || named.tag_at)
          << entry.text << ": the legend names body " << entry.body + 1
          << " by a number the picture does not show";
    }
    // A number beside its body is text like any other: clear of everything, nearest its body.
    const double small_box = metrics.ascender(layout.small_px) + metrics.descender(layout.small_px);
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const render::BodyModel& body = panel.bodies[i];
      if (!body.tag_at || body.tag.empty()) continue;
      const core::Vec2& at = body.tag_at->top_left_px;
      Text tag{
          {at.x(), at.y(), at.x() + metrics.width(body.tag, layout.small_px), at.y() + small_box},
          body.tag,
          i,
          false,
          std::nullopt,
          std::nullopt};
      texts.push_back(tag);
    }
    for (const Text& t : texts) {
      SCOPED_TRACE(t.text);
      const Box& box = t.box;
      EXPECT_TRUE(box.x0 >= 0 && box.y0 >= 0 && box.x1 <= size.width_px && box.y1 <= size.height_px)
          << "outside the frame";
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        EXPECT_GT(bodies[k].distanceTo(box), 0.0) << "covers body " << k + 1;
      }
      for (const Arrow& arrow : arrows) {
        EXPECT_GT(segmentToBox(arrow.tail, arrow.tip, box), arrow.half_width) << "covers an arrow";
      }
      for (const Mark& mark : marks) {
        EXPECT_GT(segmentToBox(mark.a, mark.b, box), mark.half_width) << mark.what << " crosses it";
      }
      if (t.body) {
        // Nearer what it names than anything it could be read as naming: a mass label its body,
        // a readout its body or its arrow; never another body or another body's arrow.
        const std::size_t i = *t.body;
        const auto arrowDistance = [&](std::size_t k) {
          double d = INFINITY;
          for (const Arrow& arrow : arrows) {
            if (arrow.body == k) d = std::min(d, segmentToBox(arrow.tail, arrow.tip, box));
          }
          return d;
        };
        const double own = t.velocity ? std::min(bodies[i].distanceTo(box), arrowDistance(i))
                                      : bodies[i].distanceTo(box);
        for (std::size_t k = 0; k < bodies.size(); ++k) {
          // A body riding on this one (a bullet in its block) is drawn and labelled as part of it.
          const bool rider = panel.bodies[k].moves_with == static_cast<int>(i);
          if (k != i && !rider) {
            EXPECT_LT(own, bodies[k].distanceTo(box)) << "nearer body " << k + 1 << " than its own";
            EXPECT_LT(own, arrowDistance(k)) << "nearer body " << k + 1 << "'s arrow than its own";
          }
        }
        // And near it: within two lines of text, or joined to it by a leader that ends on it.
        if (!t.leader_to) {
          EXPECT_LE(own, 2.0 * line_box) << "far from what it names, with no leader";
        } else {
          const core::Vec2& to = *t.leader_to;
          bool ends_on_it = bodies[i].distanceTo({to.x(), to.y(), to.x(), to.y()}) <= 1.0;
          for (const Arrow& arrow : arrows) {
            ends_on_it = ends_on_it || (t.velocity && arrow.body == i &&
                                        pointToSegment(to, arrow.tail, arrow.tip) <= 1.0);
          }
          EXPECT_TRUE(ends_on_it) << "its leader ends away from what it names";
        }
      }
      if (!t.leader_to) continue;
      // The leader strikes through no other text, no arrow (but the readout's own, where it
      // ends), no wall or flash, and no body but its own.
      const core::Vec2 a = *t.leader_from, b = *t.leader_to;
      for (const Text& other : texts) {
        if (&other == &t) continue;
        EXPECT_GT(segmentToBox(a, b, other.box), 0.0) << "its leader crosses " << other.text;
        if (other.leader_to) {
          EXPECT_GT(segmentToSegment(a, b, *other.leader_from, *other.leader_to), 0.0)
              << "its leader crosses " << other.text << "'s";
        }
      }
      for (const Arrow& arrow : arrows) {
        if (t.velocity && arrow.body == *t.body) continue;
        EXPECT_GT(segmentToSegment(a, b, arrow.tail, arrow.tip), arrow.half_width)
            << "its leader crosses the arrow of body " << arrow.body + 1;
      }
      for (const Mark& mark : marks) {
        EXPECT_GT(segmentToSegment(a, b, mark.a, mark.b), mark.half_width)
            << "its leader crosses " << mark.what;
      }
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        if (k == *t.body) continue;
        const Box outline{
            bodies[k].center.x() - bodies[k].half.x(), bodies[k].center.y() - bodies[k].half.y(),
            bodies[k].center.x() + bodies[k].half.x(), bodies[k].center.y() + bodies[k].half.y()};
        const double d = bodies[k].disk
                             ? pointToSegment(bodies[k].center, a, b) - bodies[k].half.x()
                             : segmentToBox(a, b, outline);
        EXPECT_GT(d, 0.0) << "its leader crosses body " << k + 1;
      }
    }
    // In a scene that labels its bodies (1D, and 2D up to three bodies; more are a crowd of
    // numbered bodies), nothing that gives way is lost: every arrow's value is shown, by the
    // arrow or in the legend; and a scene that states masses (a crowd of like blocks may state
    // none) states every numbered body's, by the body or in the legend ("m₁ = 1.00 kg" for the
    // block numbered 1). A rider is labelled with its carrier. At print sizes too: a printed
    // figure keeps lines for them above its 1D scenes' arrows.
    if (values_shown && (!panel.two_d || panel.bodies.size() <= 3)) {
      for (const Arrow& arrow : arrows) {
        const render::BodyModel& body = panel.bodies[arrow.body];
        const bool by_arrow = !body.velocity_label.empty() && body.velocity_label_at;
        const bool in_legend = std::any_of(panel.legend.entries.begin(), panel.legend.entries.end(),
                                           [&](const render::ReadoutLegend::Entry& entry) {
                                             return entry.body == static_cast<int>(arrow.body) &&
                                                    !entry.mass && !entry.text.empty();
                                           });
        EXPECT_TRUE(by_arrow || in_legend)
            << "panel " << p + 1 << ": body " << arrow.body + 1 << "'s arrow has no value";
      }
      const auto massInLegend = [&](std::size_t body) {
        return std::any_of(panel.legend.entries.begin(), panel.legend.entries.end(),
                           [&](const render::ReadoutLegend::Entry& entry) {
                             return entry.body == static_cast<int>(body) && entry.mass &&
                                    !entry.text.empty();
                           });
      };
      bool states_masses = false;
      for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
        states_masses = states_masses || !panel.bodies[i].label.empty() || massInLegend(i);
      }
      for (std::size_t i = 0; i < panel.bodies.size() && states_masses; ++i) {
        const render::BodyModel& body = panel.bodies[i];
        if (body.tag.empty() || body.moves_with >= 0) continue;
        const bool by_body = !body.label.empty() && body.label_at;
        EXPECT_TRUE(by_body || massInLegend(i))
            << "panel " << p + 1 << ": body " << i + 1 << " is numbered, its mass unstated";
      }
    }
    for (const Text& t : texts) all_texts.push_back(t.box);
  }
  for (std::size_t a = 0; a < all_texts.size(); ++a) {
    for (std::size_t b = a + 1; b < all_texts.size(); ++b) {
      EXPECT_FALSE(intersects(all_texts[a], all_texts[b])) << "two labels overlap";
      EXPECT_TRUE(apart(all_texts[a], all_texts[b], layout.text_px))
          << "two labels nearer than a word space: they read as one";
    }
  }
}

void checkPreset(const scene::PresetInfo& preset, Size size, bool longer) {
  const scene::SceneDesc scene = scene::loadPreset(preset.name);
  const app::Animation animation =
      app::animate(scene, {size.width_px, size.height_px, size.text_floor_px});
  const compose::FrameSource& source = animation.frames;
  render::TextMetrics metrics;
  const double end = source.simulatedDuration_s();
  const double first = source.timeline().collisions().empty()
                           ? 0.5 * end
                           : source.timeline().collisions().front().time_s;
  std::vector<std::pair<std::string, render::FrameModel>> frames;
  for (const auto& [name, t] :
       {std::pair{"start", 0.0}, std::pair{"before", first - 1e-3},
        std::pair{"after", first + 1e-3}, std::pair{"middle", 0.5 * end}, std::pair{"end", end}}) {
    frames.emplace_back(name, source.frameAtSimulated(std::clamp(t, 0.0, end)));
  }
  frames.emplace_back("strobe", source.strobeFrame(scene.view.strobe_rate_hz));
  for (auto& [name, frame] : frames) {
    if (longer) {
      for (render::PanelModel& panel : frame.panels) {
        for (render::BodyModel& body : panel.bodies) {
          body.label = lengthened(body.label);
          body.velocity_label = lengthened(body.velocity_label);
        }
        for (render::ReadoutLegend::Entry& entry : panel.legend.entries) {
          entry.text = lengthened(entry.text);
        }
      }
      compose::placeLabels(frame, size.width_px, size.height_px, metrics, size.text_floor_px);
    }
    // Still too crowded at 8 cm and 8.5 pt (issue 17 part C, left): a chain of six blocks, three
    // panels side by side, a scene beside its chart; two 2D frames. Every other frame at print
    // size states every value.
    static const std::vector<std::string> kCrowdedInPrint{
        "granular-chain middle",     "granular-chain end",
        "compare-restitution after", "compare-restitution middle",
        "compare-restitution end",   "soft-contact before",
        "soft-contact after",        "soft-contact middle",
        "soft-contact end",          "stick-2d strobe",
        "ballistic-pendulum start"};
    const bool crowded =
        size.text_floor_px > 0.0 && std::find(kCrowdedInPrint.begin(), kCrowdedInPrint.end(),
                                              preset.name + " " + name) != kCrowdedInPrint.end();
    const std::string where = preset.name + " " + name + " at " + std::to_string(size.width_px) +
                              "x" + std::to_string(size.height_px) +
                              (longer ? ", 40 % longer" : "");
    checkFrame(frame, size, metrics, where, !crowded);
    if (size.text_floor_px == 0.0) {
      compose_test::expectLabelsReadAsTheirOwn(frame, size.width_px, size.height_px, 0.0, metrics,
                                               where);
    }
  }
}

std::string sizeName(const ::testing::TestParamInfo<std::tuple<Size, bool>>& info) {
  const Size size = std::get<0>(info.param);
  return std::to_string(size.width_px) + "x" + std::to_string(size.height_px) +
         (size.text_floor_px > 0.0 ? "Print" : "") + (std::get<1>(info.param) ? "Longer" : "");
}

const double kPrintFloor_px = render::printTextFloorPx(300.0);

class LabelPlacementTest : public ::testing::TestWithParam<std::tuple<Size, bool>> {};

TEST_P(LabelPlacementTest, NoLabelOverlapsOrWandersInAnyPreset) {
  const auto [size, longer] = GetParam();
  for (const scene::PresetInfo& preset : scene::presetList()) checkPreset(preset, size, longer);
}

INSTANTIATE_TEST_SUITE_P(Sizes, LabelPlacementTest,
                         ::testing::Values(std::tuple{Size{1280, 720}, false},
                                           std::tuple{Size{640, 360}, false},
                                           std::tuple{Size{1280, 720}, true},
                                           std::tuple{Size{640, 360}, true},
                                           // 8 cm at 300 dpi (--print 8cm@300): 8.5 pt text.
                                           std::tuple{Size{945, 630, kPrintFloor_px}, false}),
                         sizeName);

// A printed figure's text is large beside its blocks: where no row over the arrows has room for
// two readouts side by side, each stands on its arrow's line beyond the tip (the worked example
// at 8 cm, 300 dpi, in the second after its collision: both values were lost, only the caption
// had them).
TEST(LabelPlacementPrintTest, ReadoutsStandBeyondTheirArrowsWhereARowHasNoRoom) {
  const app::Animation animation =
      app::animate(scene::loadPreset("worked-example"), {945, 630, kPrintFloor_px});
  const compose::FrameSource& source = animation.frames;
  const double collision_s = source.timeline().collisions().front().time_s;
  for (double t : {collision_s + 0.5, collision_s + 0.8}) {
    SCOPED_TRACE(t);
    const render::FrameModel frame = source.frameAtSimulated(t);
    for (const render::BodyModel& body : frame.panels.front().bodies) {
      ASSERT_GT(body.velocity_mps.norm(), 0.0);
      EXPECT_FALSE(body.velocity_label.empty());
      EXPECT_TRUE(body.velocity_label_at.has_value());
    }
  }
}

// Labels that fit keep their text: in a scene of two bodies with room to spare none gives way.
TEST(LabelPlacementRoomTest, RoomyScenesKeepEveryLabel) {
  for (const char* name : {"worked-example", "elastic", "billiards-glancing", "stick-2d"}) {
    SCOPED_TRACE(name);
    const app::Animation animation = app::animate(scene::loadPreset(name), {1280, 720});
    for (double t : {0.0, 0.5 * animation.frames.simulatedDuration_s()}) {
      const render::FrameModel frame = animation.frames.frameAtSimulated(t);
      for (const render::BodyModel& body : frame.panels.front().bodies) {
        EXPECT_FALSE(body.label.empty()) << "t = " << t;
        EXPECT_FALSE(body.velocity_label.empty()) << "t = " << t;
      }
    }
  }
}

}  // namespace
}  // namespace collide
