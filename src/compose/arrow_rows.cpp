#include "compose/arrow_rows.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace collide::compose {

namespace {
constexpr double kRestSpeed_mps = 1e-6;  // slower: at rest, no arrow (render's rule)
// Render draws no arrow shorter than one head length (frame::arrowShape's visible minimum):
// about 2.5 % of the view's width in a 16:9 picture, 4.5 % in a square one. The rows count the
// larger, so two short arrows drawn at that minimum never meet.
constexpr double kLeastArrowOfView = 0.045;

struct Span {
  double from_m, to_m;
};
}  // namespace

void assignArrowRows(frame::PanelModel& panel, double margin_m) {
  for (frame::BodyModel& body : panel.bodies) body.arrow_row = 0;
  if (panel.two_d || panel.arrow_m_per_mps <= 0.0) return;
  std::vector<std::vector<Span>> rows;
  for (frame::BodyModel& body : panel.bodies) {
    const double speed = std::abs(body.velocity_mps.x());
    if (speed <= kRestSpeed_mps || body.moves_with >= 0) continue;
    double length = speed * panel.arrow_m_per_mps;
    if (panel.arrow_max_length_m > 0.0) length = std::min(length, panel.arrow_max_length_m);
    length = std::max(length, kLeastArrowOfView * (panel.view.max_m.x() - panel.view.min_m.x()));
    const double direction = body.velocity_mps.x() > 0.0 ? 1.0 : -1.0;
    double tip = body.center_m.x() + direction * length;
    // Drawn back from a wall it would reach (frame::bodyArrowShape): its tip short of the face.
    for (const frame::WallModel& wall : panel.walls) {
      const double face = wall.point_m.x();
      if (wall.normal.x() * direction < 0.0 && (face - body.center_m.x()) * direction >= 0.0 &&
          (tip - face) * direction > -margin_m) {
        tip = face - direction * margin_m;
      }
    }
    const double tail = tip - direction * length;
    const Span span{std::min(tail, tip) - margin_m, std::max(tail, tip) + margin_m};
    // Row 0 runs just over its own body's top: across a taller body it would strike through it,
    // so it goes up a row (the rows above clear every body).
    const double top = body.center_m.y() + body.half_extent_m.y();
    const bool over_taller =
        std::any_of(panel.bodies.begin(), panel.bodies.end(), [&](const frame::BodyModel& other) {
          const bool rider = other.moves_with >= 0 &&
                             &panel.bodies[static_cast<std::size_t>(other.moves_with)] == &body;
          return &other != &body && !rider && other.center_m.y() + other.half_extent_m.y() > top &&
                 other.center_m.x() - other.half_extent_m.x() < span.to_m &&
                 span.from_m < other.center_m.x() + other.half_extent_m.x();
        });
    std::size_t row = over_taller ? 1 : 0;
    while (rows.size() < row) rows.emplace_back();
    for (; row < rows.size(); ++row) {
      const bool free = std::none_of(rows[row].begin(), rows[row].end(), [&](const Span& other) {
        return span.from_m < other.to_m && other.from_m < span.to_m;
      });
      if (free) break;
    }
    if (row == rows.size()) rows.emplace_back();
    rows[row].push_back(span);
    body.arrow_row = static_cast<int>(row);
  }
}

}  // namespace collide::compose
