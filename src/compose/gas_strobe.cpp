#include "compose/gas_strobe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "compose/frame_geometry.hpp"

namespace collide::compose {
namespace {

// Opacity of a marked molecule's path at its start (its end: the painter's usual trail opacity):
// the whole path stays readable, earlier parts fainter like the images on it.
constexpr float kPathStartAlpha = 0.25f;

}  // namespace

std::vector<std::size_t> markedMolecules(const physics::Timeline& timeline) {
  const physics::Snapshot start = timeline.sample(0.0);
  std::vector<std::size_t> marked;
  if (start.bodies.empty()) return marked;
  core::Vec2 low = start.bodies.front().position_m, high = low;
  for (const physics::BodyState& body : start.bodies) {
    low = low.cwiseMin(body.position_m);
    high = high.cwiseMax(body.position_m);
  }
  const std::size_t count = std::min(kMarkedMolecules, start.bodies.size());
  for (std::size_t k = 0; k < count; ++k) {
    const core::Vec2 aim{low.x() + (high.x() - low.x()) * (2.0 * k + 1.0) / (2.0 * count),
                         0.5 * (low.y() + high.y())};
    std::size_t best = start.bodies.size();
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < start.bodies.size(); ++i) {
      if (std::find(marked.begin(), marked.end(), i) != marked.end()) continue;
      const double distance = (start.bodies[i].position_m - aim).norm();
      if (distance < best_distance) {
        best = i;
        best_distance = distance;
      }
    }
    marked.push_back(best);
  }
  return marked;
}

std::vector<core::Vec2> moleculePath(const scene::SceneDesc& scene,
                                     const physics::Timeline& timeline, const FramePlan& plan,
                                     std::size_t body, double end_s, double step_s) {
  // The corners first (every collision of this body, with a disk or a wall), then steps between.
  std::vector<double> times{0.0, end_s};
  const int index = static_cast<int>(body);
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s > end_s) break;
    if (event.body_a == index || event.body_b == index) times.push_back(event.time_s);
  }
  std::sort(times.begin(), times.end());
  std::vector<double> all;
  for (std::size_t k = 0; k < times.size(); ++k) {
    all.push_back(times[k]);
    if (k + 1 == times.size()) break;
    const double gap = times[k + 1] - times[k];
    const int steps = step_s > 0.0 ? static_cast<int>(std::ceil(gap / step_s)) : 1;
    for (int s = 1; s < steps; ++s) all.push_back(times[k] + gap * s / steps);
  }
  std::vector<core::Vec2> path;
  for (double t_s : all) {
    const physics::BodyState state = timeline.sample(t_s).bodies[body];
    path.push_back(drawnCenter(scene, body, state, t_s, plan.frame_velocity_mps));
  }
  return path;
}

frame::Rgba markedColour(const Theme& theme, std::size_t k) {
  return theme.bodies[k % theme.bodies.size()];
}

void markGasStrobe(frame::PanelModel& panel, const std::vector<std::size_t>& marked,
                   const scene::SceneDesc& scene, const physics::Timeline& timeline,
                   const FramePlan& plan, const Theme& theme, double end_s) {
  for (frame::BodyModel& body : panel.bodies) {
    body.fill = theme.lost;
    body.fill.a *= kGasBackgroundAlpha;
  }
  // Between corners a straight line needs no steps; gravity bends it, so step anyway.
  const double step_s = end_s / 400.0;
  for (std::size_t k = 0; k < marked.size(); ++k) {
    if (marked[k] >= panel.bodies.size()) continue;
    frame::BodyModel& body = panel.bodies[marked[k]];
    body.fill = markedColour(theme, k);
    body.trail_m = moleculePath(scene, timeline, plan, marked[k], end_s, step_s);
    body.trail_start_alpha = kPathStartAlpha;
  }
}

}  // namespace collide::compose
