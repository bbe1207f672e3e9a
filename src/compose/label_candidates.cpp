#include "compose/label_candidates.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "frame/mark_sizes.hpp"

namespace collide::compose {
namespace {

constexpr int kRings = 5;        // candidate distances from the body
constexpr int kDirections = 16;  // candidate directions around a 2D body

void addCandidate(Label& label, const Box& box, double cost, bool leader) {
  label.candidates.push_back(box);
  label.base_cost.push_back(cost);
  label.needs_leader.push_back(leader);
}

// Whether a label is a readout drawn over (or beyond) its body's arrow.
bool byArrow(const Label& label, const frame::PanelModel& panel) {
  return label.velocity && panel.bodies[label.body].velocity_mps.norm() > kRestSpeed_mps &&
         panel.arrow_m_per_mps > 0.0;
}

// 1D: rows under the track (a mass label) or over the arrow (a readout), slid sideways.
void addRowCandidates(Label& label, const frame::PanelModel& panel, const LabelScene& scene,
                      const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  const Box& body = scene.obstacles.bodies()[label.body].bounds;
  const double w = label.size.x(), hgt = label.size.y(), gap = layout.gap_px;
  const frame::BodyModel& model = panel.bodies[label.body];
  const double track_bottom = to_px.toPixel({0.0, panel.track_y_m}).y() + layout.track_px + gap;
  double arrow_top =
      frame::arrowLineYPx(panel, model, layout, to_px) - 0.5 * layout.arrow_head_width_px - gap;
  double anchor_x = body.center().x();
  if (byArrow(label, panel)) {
    // Over the middle of the arrow (drawn back from a wall ahead: its tail behind the body).
    const frame::ArrowShape arrow = frame::bodyArrowShape(model, panel, layout, to_px);
    anchor_x +=
        (model.velocity_mps.x() > 0 ? 1.0 : -1.0) * (0.5 * arrow.length_px - arrow.tail_back_px);
  } else if (label.velocity) {
    arrow_top = body.y0 - gap;
  }
  const double row = hgt + kTextGapAlongEm * layout.text_px;
  for (int r = 0; r < kRings; ++r) {
    for (int s = -6; s <= 6; ++s) {
      const double x0 = anchor_x - 0.5 * w + s * 0.25 * w;
      const double y0 = label.velocity ? arrow_top - hgt - r * row : track_bottom + r * row;
      addCandidate(label, {x0, y0, x0 + w, y0 + hgt}, r * 3.0 * hgt + std::abs(s) * 0.25 * w,
                   r > 0 || std::abs(s) > 2);
    }
    // Flush with either edge of the scene: the slides' steps can miss a narrow free stretch
    // there (a long readout left of two blocks at the frame's edge).
    for (const double x0 : {scene.obstacles.clip().x0, scene.obstacles.clip().x1 - w}) {
      const double y0 = label.velocity ? arrow_top - hgt - r * row : track_bottom + r * row;
      const double slide = std::abs(x0 - (anchor_x - 0.5 * w));
      addCandidate(label, {x0, y0, x0 + w, y0 + hgt}, r * 3.0 * hgt + slide,
                   r > 0 || slide > 0.5 * w);
    }
  }
}

// 1D, where no row has room: on the arrow's own line beyond its tip (a printed figure's large
// text over blocks standing close), then beside the block.
void addLastResorts(Label& label, const frame::PanelModel& panel, const LabelScene& scene,
                    const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  const Box& body = scene.obstacles.bodies()[label.body].bounds;
  const double w = label.size.x(), hgt = label.size.y(), gap = layout.gap_px;
  const frame::BodyModel& model = panel.bodies[label.body];
  // Beyond the tip the painter draws, which an arrow drawn back from a wall ahead has a gap
  // short of the wall, not at its length from the body's centre.
  if (byArrow(label, panel)) {
    const double direction = model.velocity_mps.x() > 0 ? 1.0 : -1.0;
    const frame::ArrowShape arrow = frame::bodyArrowShape(model, panel, layout, to_px);
    const core::Vec2 tail = frame::bodyArrowTailPx(model, panel, layout, to_px, arrow);
    const double tip_x = tail.x() + direction * arrow.length_px;
    const double clear = 0.5 * layout.arrow_head_width_px + gap;
    const double x0 = direction > 0 ? tip_x + clear : tip_x - clear - w;
    addCandidate(label, {x0, tail.y() - 0.5 * hgt, x0 + w, tail.y() + 0.5 * hgt}, 8.0 * hgt, false);
  }
  // Beside the block, as a last resort before giving way; slid into the scene where it would
  // stick out of it (a block near the frame's margin leaves a gap less room beside it).
  const Box& clip = scene.obstacles.clip();
  for (int side : {-1, 1}) {
    double x0 = side > 0 ? body.x1 + gap : body.x0 - gap - w;
    if (clip.x1 - clip.x0 >= w) x0 = std::clamp(x0, clip.x0, clip.x1 - w);
    const double y0 = label.velocity ? body.y0 - hgt : body.y1 - hgt;
    addCandidate(label, {x0, y0, x0 + w, y0 + hgt}, 8.0 * hgt, false);
  }
}

// 2D: all around the body, ring by ring.
void addRingCandidates(Label& label, const frame::PanelModel& panel, const LabelScene& scene,
                       const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  const Box& body = scene.obstacles.bodies()[label.body].bounds;
  const core::Vec2 c = body.center();
  const double w = label.size.x(), hgt = label.size.y(), gap = layout.gap_px;
  const frame::BodyModel& model = panel.bodies[label.body];
  const double speed = model.velocity_mps.norm();
  const double radius = 0.5 * std::max(body.x1 - body.x0, body.y1 - body.y0);
  // Preferred sides: a mass label below its body, a readout beyond the arrow's tip.
  core::Vec2 preferred{0.0, 1.0};
  double reach = radius;
  if (byArrow(label, panel)) {
    preferred = {model.velocity_mps.x() / speed, -model.velocity_mps.y() / speed};
    reach = std::max(radius, frame::bodyArrowShape(model, panel, layout, to_px).length_px);
  } else if (label.velocity) {
    preferred = {0.0, -1.0};
  }
  for (int r = 0; r < kRings; ++r) {
    const double d = gap + r * 1.2 * hgt;
    for (int k = 0; k < kDirections; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / kDirections;
      const core::Vec2 u{std::cos(angle), std::sin(angle)};
      // The box touches the circle of radius `radius + d` from outside, on the side u points to.
      const core::Vec2 near = c + (radius + d) * u;
      const double x0 =
          near.x() - 0.5 * w + 0.5 * w * u.x() / std::max(std::abs(u.x()), std::abs(u.y()));
      const double y0 =
          near.y() - 0.5 * hgt + 0.5 * hgt * u.y() / std::max(std::abs(u.x()), std::abs(u.y()));
      const double turn = 1.0 - u.dot(preferred);  // 0 on the preferred side, 2 opposite
      addCandidate(label, {x0, y0, x0 + w, y0 + hgt}, r * 2.0 * hgt + turn * 0.6 * hgt, r > 1);
    }
    // Beyond the arrow's tip, for the readout.
    if (label.velocity && reach > radius) {
      const core::Vec2 tip = c + (reach + d) * preferred;
      const double x0 = preferred.x() >= 0.0 ? tip.x() : tip.x() - w;
      // Farther from the body than a line or so of text: a leader shows whose it is.
      addCandidate(label, {x0, tip.y() - 0.5 * hgt, x0 + w, tip.y() + 0.5 * hgt}, r * 2.0 * hgt,
                   reach + d - radius > 1.5 * hgt);
    }
  }
}

}  // namespace

void addCandidates(Label& label, const frame::PanelModel& panel, const LabelScene& scene,
                   const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  if (panel.two_d) {
    addRingCandidates(label, panel, scene, layout, to_px);
    return;
  }
  addRowCandidates(label, panel, scene, layout, to_px);
  addLastResorts(label, panel, scene, layout, to_px);
}

}  // namespace collide::compose
