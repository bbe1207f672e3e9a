#include "compose/arrow_rows.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace collide::compose {

namespace {
constexpr double kRestSpeed_mps = 1e-6;  // slower: at rest, no arrow (render's rule)
// Render draws no arrow shorter than one head length (render::arrowShape's visible minimum):
// about 2.5 % of the view's width in a 16:9 picture, 4.5 % in a square one. The rows count the
// larger, so two short arrows drawn at that minimum never meet.
constexpr double kLeastArrowOfView = 0.045;

struct Span {
  double from_m, to_m;
};
}  // namespace

void assignArrowRows(render::PanelModel& panel, double margin_m) {
  for (render::BodyModel& body : panel.bodies) body.arrow_row = 0;
  if (panel.two_d || panel.arrow_m_per_mps <= 0.0) return;
  std::vector<std::vector<Span>> rows;
  for (render::BodyModel& body : panel.bodies) {
    const double speed = std::abs(body.velocity_mps.x());
    if (speed <= kRestSpeed_mps || body.moves_with >= 0) continue;
    double length = speed * panel.arrow_m_per_mps;
    if (panel.arrow_max_length_m > 0.0) length = std::min(length, panel.arrow_max_length_m);
    length = std::max(length, kLeastArrowOfView * (panel.view.max_m.x() - panel.view.min_m.x()));
    const double tip = body.center_m.x() + (body.velocity_mps.x() > 0.0 ? length : -length);
    const Span span{std::min(body.center_m.x(), tip) - margin_m,
                    std::max(body.center_m.x(), tip) + margin_m};
    std::size_t row = 0;
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
