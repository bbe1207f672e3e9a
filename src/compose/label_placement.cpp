#include "compose/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "compose/dimension_placement.hpp"
#include "render/layout.hpp"

namespace collide::compose {
namespace {

// Sizes the GL painter draws with, as fractions of the frame height (render/draw_world.cpp and
// draw_readouts.cpp): what a label must keep clear of.
constexpr double kFlashRadius = 0.06;
constexpr double kComRadius = 0.02;
constexpr double kHatchLength = 0.022;
constexpr double kRulerTick = 0.02;
constexpr double kInsetSize = 0.3, kInsetMaxShare = 0.4;
constexpr double kRestSpeed_mps = 1e-6;

constexpr double kHard = 1e6;    // one overlap outweighs any distance
constexpr int kRings = 5;        // candidate distances from the body
constexpr int kDirections = 16;  // candidate directions around a 2D body
constexpr int kImprovementRounds = 4;

struct Box {
  double x0, y0, x1, y1;
  bool intersects(const Box& o, double pad = 0.0) const {
    return x0 < o.x1 + pad && o.x0 < x1 + pad && y0 < o.y1 + pad && o.y0 < y1 + pad;
  }
  core::Vec2 center() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
};

// A thick segment (a disk when a == b): bodies, arrows, walls, flashes, markers.
struct Capsule {
  core::Vec2 a, b;
  double radius;
};

// Distance from the box to point p (0 inside).
double distance(const Box& box, const core::Vec2& p) {
  const double dx = std::max({box.x0 - p.x(), 0.0, p.x() - box.x1});
  const double dy = std::max({box.y0 - p.y(), 0.0, p.y() - box.y1});
  return std::hypot(dx, dy);
}

double distance(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b) {
  const core::Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Whether the segment ab crosses the box (Liang–Barsky clipping).
bool crosses(const Box& box, const core::Vec2& a, const core::Vec2& b) {
  double t0 = 0.0, t1 = 1.0;
  const core::Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.x0, box.x1 - a.x(), a.y() - box.y0, box.y1 - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
    } else {
      const double t = q[i] / p[i];
      if (p[i] < 0.0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  return t0 <= t1;
}

// Distance from the box to the segment ab (0 where they meet).
double distance(const Box& box, const core::Vec2& a, const core::Vec2& b) {
  if (crosses(box, a, b)) return 0.0;
  double best = std::min(distance(box, a), distance(box, b));
  for (const core::Vec2& corner : {core::Vec2{box.x0, box.y0}, core::Vec2{box.x1, box.y0},
                                   core::Vec2{box.x0, box.y1}, core::Vec2{box.x1, box.y1}}) {
    best = std::min(best, distance(corner, a, b));
  }
  return best;
}

bool overlaps(const Box& box, const Capsule& c) {
  return distance(box, c.a, c.b) < c.radius;
}

struct Label {
  std::size_t body;
  bool velocity;  // the velocity readout, else the mass label
  std::string* text;
  core::Vec2 size;
  std::vector<Box> candidates;
  std::vector<double> base_cost;  // distance and preference
  std::vector<bool> needs_leader;
  int chosen = -1;
};

struct PanelScene {
  std::vector<Box> body_boxes;       // bounding boxes of the bodies, pixels
  std::vector<Capsule> body_shapes;  // the bodies themselves
  std::vector<bool> body_is_disk;
  std::vector<int> moves_with;     // per body: the body it rides on (one body with it), or -1
  std::vector<Capsule> obstacles;  // arrows, walls, flashes, markers, strobe images
  std::vector<Box> blocked;        // track, ruler, momentum inset
  Box clip;                        // labels stay inside
};

PanelScene describePanel(const render::PanelModel& panel, const render::PanelLayout& where,
                         const render::FrameLayout& layout, const render::WorldToPixel& to_px,
                         const render::PixelRect& area) {
  PanelScene scene;
  const double h = layout.scale_px;  // what the painter scales its marks by
  const render::PixelRect& clip = where.world_clip;
  scene.clip = {clip.x0, clip.y0, clip.x1, clip.y1};
  const auto shapeOf = [&](const render::BodyModel& body) {
    const core::Vec2 c = to_px.toPixel(body.center_m);
    const double hx = to_px.px_per_m * body.half_extent_m.x();
    const double hy =
        body.shape == render::BodyShape::kDisk ? hx : to_px.px_per_m * body.half_extent_m.y();
    return std::pair<core::Vec2, core::Vec2>{c, {hx, hy}};
  };
  for (const render::BodyModel& body : panel.bodies) {
    const auto [c, half] = shapeOf(body);
    scene.body_boxes.push_back(
        {c.x() - half.x(), c.y() - half.y(), c.x() + half.x(), c.y() + half.y()});
    scene.body_is_disk.push_back(body.shape == render::BodyShape::kDisk);
    scene.moves_with.push_back(body.moves_with);
    if (body.shape == render::BodyShape::kDisk) {
      scene.body_shapes.push_back({c, c, half.x()});
    } else {
      // A rectangle as a capsule along its longer side, covering it whole.
      const core::Vec2 along = half.x() >= half.y() ? core::Vec2{half.x() - half.y(), 0.0}
                                                    : core::Vec2{0.0, half.y() - half.x()};
      scene.body_shapes.push_back({c - along, c + along, std::hypot(half.x(), half.y())});
    }
    // The velocity arrow, as the painter draws it.
    const double speed = body.velocity_mps.norm();
    if (speed > kRestSpeed_mps && panel.arrow_m_per_mps > 0.0 && body.moves_with < 0) {
      const core::Vec2 d{body.velocity_mps.x() / speed, -body.velocity_mps.y() / speed};
      const core::Vec2 tail =
          panel.two_d ? c : core::Vec2{c.x(), render::arrowLineYPx(panel, body, layout, to_px)};
      const render::ArrowShape arrow = render::arrowShape(speed, panel, layout, to_px);
      scene.obstacles.push_back(
          {tail, tail + arrow.length_px * d, 0.5 * layout.arrow_head_width_px + 1.0});
    }
  }
  for (const render::BodyModel& ghost : panel.ghosts) {
    const auto [c, half] = shapeOf(ghost);
    if (ghost.shape == render::BodyShape::kDisk) {
      scene.obstacles.push_back({c, c, half.x()});
    } else {
      scene.blocked.push_back(
          {c.x() - half.x(), c.y() - half.y(), c.x() + half.x(), c.y() + half.y()});
    }
  }
  for (const render::FlashModel& flash : panel.flashes) {
    const core::Vec2 c = to_px.toPixel(flash.center_m);
    scene.obstacles.push_back({c, c, kFlashRadius * h});
  }
  if (panel.center_of_mass_m) {
    const core::Vec2 c = to_px.toPixel(*panel.center_of_mass_m);
    scene.obstacles.push_back({c, c, kComRadius * h + 1.0});
  }
  const double wall_half = 2.0 * layout.track_px + kHatchLength * h;
  for (const render::WallModel& wall : panel.walls) {
    const core::Vec2 p = to_px.toPixel(wall.point_m);
    if (!panel.two_d) {
      const double track_y = to_px.toPixel({0.0, panel.track_y_m}).y();
      scene.obstacles.push_back({{p.x(), track_y}, {p.x(), area.y0}, wall_half});
    } else {
      const core::Vec2 along{wall.normal.y(), wall.normal.x()};  // pixel y flips
      const double reach = 2.0 * (clip.width() + clip.height());
      scene.obstacles.push_back({p - reach * along, p + reach * along, wall_half});
    }
  }
  // The lines of a dimension (its text is placed first and blocked in placePanel; strings are
  // added there after it: a note may cross a thin string, a body's label should not).
  const double thin = std::max(1.0, 0.5 * layout.line_px);
  for (const render::DimensionModel& dim : panel.suspension.dimensions) {
    for (const PixelSegment& line : dimensionLines(dim, layout, to_px)) {
      scene.obstacles.push_back({line.a, line.b, 0.5 * thin + 1.0});
    }
  }
  if (panel.draw_track) {
    const double y = to_px.toPixel({0.0, panel.track_y_m}).y();
    scene.blocked.push_back({clip.x0, y - 1.0, clip.x1, y + layout.track_px + 1.0});
  }
  if (panel.ruler) {
    const double tick = kRulerTick * h;
    double y = where.scene.y1 - layout.small_px * 1.3 - tick;
    if (!panel.two_d) {
      y = std::min(y, to_px.toPixel({0.0, panel.track_y_m}).y() + layout.track_px +
                          2.0 * layout.gap_px + 1.3 * layout.text_px);
    }
    scene.blocked.push_back({clip.x0, y - 1.0, clip.x1, clip.y1 + 1e6});
    if (panel.two_d) {
      // The vertical scale and its numbers, left of its line.
      const double x = render::verticalRulerX(panel, to_px, area, layout);
      const double numbers = 2.5 * layout.small_px + tick + layout.gap_px;  // worldArea's room
      scene.blocked.push_back({x - numbers, clip.y0, x + 1.0, clip.y1});
    }
  }
  if (panel.momentum) {
    const double side = std::round(std::min(
        kInsetSize * h, std::min(kInsetMaxShare * where.scene.width(), where.scene.height())));
    scene.blocked.push_back(
        {where.scene.x1 - side, where.scene.y0, where.scene.x1, where.scene.y0 + side});
  }
  return scene;
}

// Candidate boxes for a label of `size` beside a body: 2D all around it, ring by ring; 1D the mass
// label under the track and the velocity readout over the arrow, in rows, slid sideways.
void addCandidates(Label& label, const render::PanelModel& panel, const PanelScene& scene,
                   const render::FrameLayout& layout, const render::WorldToPixel& to_px) {
  const Box& body = scene.body_boxes[label.body];
  const core::Vec2 c = body.center();
  const double w = label.size.x(), hgt = label.size.y(), gap = layout.gap_px;
  const auto add = [&](const Box& box, double cost, bool leader) {
    label.candidates.push_back(box);
    label.base_cost.push_back(cost);
    label.needs_leader.push_back(leader);
  };
  const render::BodyModel& model = panel.bodies[label.body];
  const double speed = model.velocity_mps.norm();
  if (!panel.two_d) {
    const double track_bottom = to_px.toPixel({0.0, panel.track_y_m}).y() + layout.track_px + gap;
    double arrow_top =
        render::arrowLineYPx(panel, model, layout, to_px) - 0.5 * layout.arrow_head_width_px - gap;
    double anchor_x = c.x();
    if (label.velocity && speed > kRestSpeed_mps && panel.arrow_m_per_mps > 0.0) {
      // Over the middle of the arrow.
      anchor_x += 0.5 * (model.velocity_mps.x() > 0 ? 1.0 : -1.0) *
                  render::arrowShape(speed, panel, layout, to_px).length_px;
    } else if (label.velocity) {
      arrow_top = body.y0 - gap;
    }
    const double row = hgt + 0.25 * gap;
    for (int r = 0; r < kRings; ++r) {
      for (int s = -6; s <= 6; ++s) {
        const double x0 = anchor_x - 0.5 * w + s * 0.25 * w;
        const double y0 = label.velocity ? arrow_top - hgt - r * row : track_bottom + r * row;
        add({x0, y0, x0 + w, y0 + hgt}, r * 3.0 * hgt + std::abs(s) * 0.25 * w,
            r > 0 || std::abs(s) > 2);
      }
    }
    // Beside the block, as a last resort before giving way.
    for (int side : {-1, 1}) {
      const double x0 = side > 0 ? body.x1 + gap : body.x0 - gap - w;
      const double y0 = label.velocity ? body.y0 - hgt : body.y1 - hgt;
      add({x0, y0, x0 + w, y0 + hgt}, 8.0 * hgt, false);
    }
    return;
  }
  const double radius = 0.5 * std::max(body.x1 - body.x0, body.y1 - body.y0);
  // Preferred sides: a mass label below its body, a readout beyond the arrow's tip.
  core::Vec2 preferred{0.0, 1.0};
  double reach = radius;
  if (label.velocity && speed > kRestSpeed_mps && panel.arrow_m_per_mps > 0.0) {
    preferred = {model.velocity_mps.x() / speed, -model.velocity_mps.y() / speed};
    reach = std::max(radius, render::arrowShape(speed, panel, layout, to_px).length_px);
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
      add({x0, y0, x0 + w, y0 + hgt}, r * 2.0 * hgt + turn * 0.6 * hgt, r > 1);
    }
    // Beyond the arrow's tip, for the readout.
    if (label.velocity && reach > radius) {
      const core::Vec2 tip = c + (reach + d) * preferred;
      const double x0 = preferred.x() >= 0.0 ? tip.x() : tip.x() - w;
      add({x0, tip.y() - 0.5 * hgt, x0 + w, tip.y() + 0.5 * hgt}, r * 2.0 * hgt, false);
    }
  }
}

// Gap between a label box and body i's outline, pixels.
double bodyDistance(const Box& box, const PanelScene& scene, std::size_t i) {
  if (scene.body_is_disk[i]) {
    const Capsule& disk = scene.body_shapes[i];
    return distance(box, disk.a) - disk.radius;
  }
  const Box& body = scene.body_boxes[i];
  const double dx = std::max({body.x0 - box.x1, 0.0, box.x0 - body.x1});
  const double dy = std::max({body.y0 - box.y1, 0.0, box.y0 - body.y1});
  return std::hypot(dx, dy);
}

// What a candidate costs given the labels placed so far (chosen >= 0).
double cost(const Label& label, int k, const std::vector<Label>& labels, const PanelScene& scene,
            double gap) {
  const Box& box = label.candidates[static_cast<std::size_t>(k)];
  double total = label.base_cost[static_cast<std::size_t>(k)];
  if (box.x0 < scene.clip.x0 || box.x1 > scene.clip.x1 || box.y0 < scene.clip.y0 ||
      box.y1 > scene.clip.y1) {
    total += kHard;
  }
  for (const Box& blocked : scene.blocked) {
    if (box.intersects(blocked)) total += kHard;
  }
  for (const Capsule& obstacle : scene.obstacles) {
    if (overlaps(box, obstacle)) total += kHard;
  }
  const double own = bodyDistance(box, scene, label.body);
  for (std::size_t i = 0; i < scene.body_boxes.size(); ++i) {
    const double d = bodyDistance(box, scene, i);
    if (d < 0.5 * gap) total += kHard;  // on or against a body
    // Not clearly nearer its own body; a body riding on it (a bullet in its block) is part of it.
    const bool rider = scene.moves_with[i] == static_cast<int>(label.body);
    if (i != label.body && !rider && d <= own + 1.0) total += kHard;
  }
  for (const Label& other : labels) {
    if (&other == &label || other.chosen < 0) continue;
    if (box.intersects(other.candidates[static_cast<std::size_t>(other.chosen)], 0.3 * gap)) {
      total += kHard;
    }
  }
  return total;
}

void placePanel(render::PanelModel& panel, const render::PanelLayout& where,
                const render::FrameLayout& layout, render::TextMetrics& metrics) {
  const render::PixelRect area = render::worldArea(panel, where, layout);
  const render::WorldToPixel to_px = render::fitView(panel.view, area);
  PanelScene scene = describePanel(panel, where, layout, to_px, area);
  const double size = layout.text_px;
  const double line = metrics.ascender(size) + metrics.descender(size);

  // A dimension's text first (it belongs to its line); the bodies' labels keep clear of it.
  const auto is_free = [&](const render::PixelRect& r) {
    const Box box{r.x0, r.y0, r.x1, r.y1};
    for (const Box& blocked : scene.blocked) {
      if (box.intersects(blocked)) return false;
    }
    for (const Capsule& obstacle : scene.obstacles) {
      if (overlaps(box, obstacle)) return false;
    }
    for (std::size_t i = 0; i < scene.body_boxes.size(); ++i) {
      if (bodyDistance(box, scene, i) < 0.5 * layout.gap_px) return false;
    }
    return true;
  };
  for (const render::PixelRect& r :
       placeDimensionTexts(panel.suspension, layout, to_px, where.world_clip, metrics, is_free)) {
    const double pad = 0.3 * layout.gap_px;
    scene.blocked.push_back({r.x0 - pad, r.y0 - pad, r.x1 + pad, r.y1 + pad});
  }
  const double thin = std::max(1.0, 0.5 * layout.line_px);
  for (const render::StringModel& string : panel.suspension.strings) {
    scene.obstacles.push_back(
        {to_px.toPixel(string.pivot_m), to_px.toPixel(string.body_m), 0.5 * thin + 1.0});
  }

  std::vector<Label> labels;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    render::BodyModel& body = panel.bodies[i];
    body.label_at.reset();
    body.velocity_label_at.reset();
    for (bool velocity : {true, false}) {
      std::string& text = velocity ? body.velocity_label : body.label;
      if (text.empty()) continue;
      Label label{i, velocity, &text, {metrics.width(text, size), line}, {}, {}, {}, -1};
      addCandidates(label, panel, scene, layout, to_px);
      labels.push_back(std::move(label));
    }
  }
  // Greedy: fastest bodies' readouts first (their arrows leave the least room), then masses.
  std::stable_sort(labels.begin(), labels.end(), [&](const Label& a, const Label& b) {
    if (a.velocity != b.velocity) return a.velocity;
    return panel.bodies[a.body].velocity_mps.norm() > panel.bodies[b.body].velocity_mps.norm();
  });
  const auto best = [&](Label& label) {
    double lowest = std::numeric_limits<double>::infinity();
    int pick = -1;
    label.chosen = -1;
    for (int k = 0; k < static_cast<int>(label.candidates.size()); ++k) {
      const double c = cost(label, k, labels, scene, layout.gap_px);
      if (c < lowest) lowest = c, pick = k;
    }
    label.chosen = pick;
    return lowest;
  };
  for (Label& label : labels) best(label);
  for (int round = 0; round < kImprovementRounds; ++round) {
    bool changed = false;
    for (Label& label : labels) {
      const int before = label.chosen;
      best(label);
      changed = changed || label.chosen != before;
    }
    if (!changed) break;
  }
  // Labels that found no free place give way, worst first, until the rest are clear.
  for (Label& label : labels) {
    if (label.chosen < 0 || cost(label, label.chosen, labels, scene, layout.gap_px) < kHard)
      continue;
    label.chosen = -1;
    label.text->clear();
    panel.bodies[label.body].tag = std::to_string(label.body + 1);
  }
  for (const Label& label : labels) {
    if (label.chosen < 0) continue;
    const std::size_t k = static_cast<std::size_t>(label.chosen);
    const Box& box = label.candidates[k];
    render::PlacedText placed{{box.x0, box.y0}, {box.x1 - box.x0, box.y1 - box.y0}, std::nullopt};
    if (label.needs_leader[k]) {
      // To the body's edge, on the line from its centre to the box.
      const Capsule& shape = scene.body_shapes[label.body];
      const core::Vec2 c = 0.5 * (shape.a + shape.b);
      const core::Vec2 toward = box.center() - c;
      const Box& body = scene.body_boxes[label.body];
      const double r = 0.5 * std::min(body.x1 - body.x0, body.y1 - body.y0);
      placed.leader_to_px = c + r * toward / std::max(toward.norm(), 1e-9);
    }
    render::BodyModel& body = panel.bodies[label.body];
    (label.velocity ? body.velocity_label_at : body.label_at) = placed;
  }
  panel.placed_for_width_px = layout.width_px;
  panel.placed_for_height_px = layout.height_px;
  panel.placed_for_scale_px = layout.scale_px;
}

}  // namespace

void placeLabels(render::FrameModel& frame, int width_px, int height_px,
                 render::TextMetrics& metrics, double text_floor_px) {
  const render::FrameLayout layout = render::layoutFrame(
      frame, width_px, height_px, text_floor_px,
      [&metrics](std::string_view text, double size) { return metrics.width(text, size); });
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    placePanel(frame.panels[p], layout.panels[p], layout, metrics);
  }
}

}  // namespace collide::compose
