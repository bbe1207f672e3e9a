#include "compose/tag_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "frame/mark_sizes.hpp"

namespace collide::compose {
namespace {

constexpr int kTagDirections = 16;  // around the body, from its upper right
constexpr int kTagRings = 3;        // distances from its edge

// A number over or under an arrow's tail is nearer that arrow than any other arrow or body by at
// least this many of its lines: clearly its arrow's, not the next one's.
constexpr double kArrowTagNearerByLines = 0.5;

// Where an arrow's number (`size`) may stand over and under its shaft, in the order tried: over
// and under `from` (its tail's end; drawn back, its body's centre), then slid along the shaft,
// `leftwards` or not (from a tail towards the tip; drawn back, away from it), as far as the
// shaft's middle (pi-blocks at 2.5 s: the tail of block 1's lifted arrow stands by the wall, no
// place over or under its end free): a pixel at a time for its first two widths, so that a number
// kept off the wall stands still there while its block comes and goes, then a number's width and
// a gap at a time. `gap`: from the shaft's edge (half a head's width, `half_head`, from its line,
// as all text).
std::vector<Box> alongTheShaft(const core::Vec2& tail, const core::Vec2& tip, double from,
                               bool leftwards, bool drawn_back, const core::Vec2& size, double gap,
                               double half_head) {
  const double width = size.x(), height = size.y();
  const double shaft = std::abs(tip.x() - tail.x());
  const double fine = 2.0 * (width + gap);
  std::vector<double> alongs;
  for (double along = 0.0; along < fine; along += 1.0) alongs.push_back(along);
  for (int k = 2; k * (width + gap) + width <= 0.5 * shaft; ++k)
    alongs.push_back(k * (width + gap));
  std::vector<Box> places;
  const auto overAndUnder = [&](double x0) {
    places.push_back(
        {x0, tail.y() - half_head - gap - height, x0 + width, tail.y() - half_head - gap});
    places.push_back(
        {x0, tail.y() + half_head + gap, x0 + width, tail.y() + half_head + gap + height});
  };
  for (const double along : alongs) {
    overAndUnder(leftwards ? from - along - width : from + along);
    // Drawn back, also slid the other way, towards the tip: where something stands over the
    // shaft on the far side of its body (pi-blocks' legend over block 1 as it leaves block 2 for
    // the wall), the number stands still by it, and rides with its body once that is clear,
    // rather than stand behind the tail, far off, and jump to its body when the place frees
    // (219 px).
    if (drawn_back) overAndUnder(leftwards ? from - width + along : from - along);
  }
  return places;
}

}  // namespace

void placeTagsBeside(frame::PanelModel& panel, const std::vector<bool>& named,
                     const BodyArrows& arrows, const std::vector<int>& moves_with,
                     const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                     text::TextMeasure& metrics, Obstacles& obstacles) {
  const double size = layout.small_px;
  const double height = metrics.ascender(size) + metrics.descender(size);
  const std::vector<BodyOutline>& outlines = obstacles.bodies();
  for (std::size_t i = 0; i < panel.bodies.size() && i < named.size() && i < outlines.size(); ++i) {
    frame::BodyModel& body = panel.bodies[i];
    body.tag_at.reset();
    if (!named[i] || body.tag.empty() || frame::tagFitsInside(body, layout, to_px)) continue;
    const double width = metrics.width(body.tag, size);
    // Nearer its body than anything else by as much as every label (kNearerOwnByLines).
    const double nearer_by = std::max(1.0, kNearerOwnByLines * height);
    const Box& bounds = outlines[i].bounds;
    const core::Vec2 c = bounds.center();
    const double radius = 0.5 * std::max(bounds.x1 - bounds.x0, bounds.y1 - bounds.y0);
    for (int r = 0; r < kTagRings && !body.tag_at; ++r) {
      const double d = obstacles.bodyGap() + 1.0 + r * 0.5 * height;
      for (int k = 0; k < kTagDirections; ++k) {
        // From the upper right (where a subscript's number reads), round both ways.
        const int step = (k + 1) / 2 * (k % 2 == 0 ? 1 : -1);
        const double angle =
            std::numbers::pi / 4.0 + 2.0 * std::numbers::pi * step / kTagDirections;
        const core::Vec2 u{std::cos(angle), -std::sin(angle)};
        const double m = std::max(std::abs(u.x()), std::abs(u.y()));
        // The box touches the circle of radius `radius + d` from outside, on the side u points to.
        const core::Vec2 near = c + (radius + d) * u;
        const double x0 = near.x() - 0.5 * width + 0.5 * width * u.x() / m;
        const double y0 = near.y() - 0.5 * height + 0.5 * height * u.y() / m;
        const Box box{x0, y0, x0 + width, y0 + height};
        if (!obstacles.isFree(box)) continue;
        const double own = outlines[i].distanceTo(box);
        if (readAsOthers(box, own, i, outlines, moves_with, arrows, nearer_by) != 0) continue;
        body.tag_at = frame::PlacedText{{box.x0, box.y0}, {width, height}, std::nullopt};
        obstacles.addText(box);
        break;
      }
    }
  }
}

void placeArrowTags(frame::PanelModel& panel, const BodyArrows& arrows,
                    const std::vector<int>& moves_with, const frame::FrameLayout& layout,
                    const frame::WorldToPixel& to_px, text::TextMeasure& metrics,
                    Obstacles& obstacles) {
  const double size = layout.small_px;
  const double height = metrics.ascender(size) + metrics.descender(size);
  const std::vector<BodyOutline>& outlines = obstacles.bodies();
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    frame::BodyModel& body = panel.bodies[i];
    body.arrow_tag_at.reset();
    const bool readout_beside = !body.velocity_label.empty() && body.velocity_label_at;
    if (panel.two_d || body.tag.empty() || readout_beside || i >= arrows.size() || !arrows[i]) {
      continue;
    }
    // Over its body an arrow is its body's; lifted into a row above the bodies, or drawn back
    // from a wall ahead (its tail behind the body), it needs the number.
    const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
    if (body.arrow_row == 0 && shape.tail_back_px <= 0.0) continue;
    const auto& [tail, tip] = *arrows[i];
    const double back = tail.x() < tip.x() ? -1.0 : 1.0;  // from the tail, away from the tip
    const double width = metrics.width(body.tag, size);
    const double gap = obstacles.bodyGap() + 1.0;
    const double half_head = 0.5 * layout.arrow_head_width_px;
    // Behind the tail on the arrow's line (a gap from the shaft's end: the head is at the other
    // end), then over and under the tail's end (half a head's width from the line, as all text).
    const double behind_x0 = back > 0 ? tail.x() + 0.5 * shape.shaft_px + gap
                                      : tail.x() - 0.5 * shape.shaft_px - gap - width;
    const Box behind{behind_x0, tail.y() - 0.5 * height, behind_x0 + width,
                     tail.y() + 0.5 * height};
    std::vector<Box> places{behind};
    // Drawn back, its tail stands behind the body, far from it: the number over the shaft from
    // the body's centre away from the tip, where it stands as the body turns at the wall and its
    // arrow, no longer drawn back, starts at that centre (the number over its tail).
    const double centre_x = std::clamp(outlines[i].bounds.center().x(), std::min(tail.x(), tip.x()),
                                       std::max(tail.x(), tip.x()));
    const bool drawn_back = shape.tail_back_px > 0.0;
    if (drawn_back) places.clear();
    const double from = drawn_back ? centre_x : tail.x();
    const bool leftwards = (back > 0) != drawn_back;
    const std::vector<Box> along =
        alongTheShaft(tail, tip, from, leftwards, drawn_back, {width, height}, gap, half_head);
    places.insert(places.end(), along.begin(), along.end());
    // Drawn back with no room over or under its shaft (a legend over the arrows' rows, pi-blocks
    // after its first impact), behind its tail all the same: an arrow lifted or drawn back
    // without its value or its body's number is nobody's.
    if (drawn_back) places.push_back(behind);
    const double own_reach = 0.5 * layout.arrow_head_width_px + 1.0;  // what Obstacles keeps
    for (const Box& box : places) {
      // Free but for its own arrow, which it may come nearer behind the tail.
      const double own = distance(box, tail, tip);
      if (obstacles.hits(box) - (own < own_reach ? 1 : 0) != 0) continue;
      // On the arrow's own line its place ties it (read as the arrow's continuation); over or
      // under the tail it must be clearly nearer.
      const bool on_its_line = box.x0 == behind.x0 && box.y0 == behind.y0;
      const double margin = on_its_line ? 1.0 : kArrowTagNearerByLines * height;
      if (readAsOthers(box, own, i, outlines, moves_with, arrows, margin) != 0) continue;
      body.arrow_tag_at = frame::PlacedText{{box.x0, box.y0}, {width, height}, std::nullopt};
      obstacles.addText(box);
      break;
    }
  }
}

}  // namespace collide::compose
