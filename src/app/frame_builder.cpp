#include "app/frame_builder.hpp"

#include <algorithm>
#include <cmath>

#include "app/palette.hpp"

namespace collide::app {
namespace {

// Samples used to find the extent of the motion; collision instants are added on top.
constexpr int kPlanSamples = 400;
// Fraction of the view width that the fastest body's arrow spans.
constexpr double kLongestArrowFraction = 0.15;

// Blocks are drawn as squares standing on the track (y = 0); disks are centred on their position.
core::Vec2 bodyCenter(const scene::BodyDesc& body, const physics::BodyState& state,
                      int dimensions) {
  if (dimensions == 1) return {state.position_m.x(), 0.5 * body.size_m};
  return state.position_m;
}

core::Vec2 halfExtent(const scene::BodyDesc& body) {
  if (body.shape == "disk") return {body.size_m, body.size_m};
  return {0.5 * body.size_m, 0.5 * body.size_m};
}

}  // namespace

FramePlan planFrames(const scene::SceneDesc& scene, const physics::Timeline& timeline) {
  std::vector<double> times;
  for (int i = 0; i <= kPlanSamples; ++i) times.push_back(timeline.duration_s() * i / kPlanSamples);
  for (const physics::CollisionEvent& event : timeline.collisions()) times.push_back(event.time_s);

  core::Vec2 low = core::Vec2::Constant(INFINITY), high = core::Vec2::Constant(-INFINITY);
  double fastest_mps = 0.0, most_energy_J = timeline.initialKineticEnergy();
  for (double t : times) {
    const physics::Snapshot snapshot = timeline.sample(t);
    for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
      const core::Vec2 c = bodyCenter(scene.bodies[i], snapshot.bodies[i], scene.dimensions);
      low = low.cwiseMin(c - halfExtent(scene.bodies[i]));
      high = high.cwiseMax(c + halfExtent(scene.bodies[i]));
      fastest_mps = std::max(fastest_mps, snapshot.bodies[i].velocity_mps.norm());
    }
    most_energy_J =
        std::max(most_energy_J, timeline.kineticEnergy(snapshot) + snapshot.energy_lost_J);
  }

  FramePlan plan;
  const double width = std::max(high.x() - low.x(), 1e-3);
  const double margin = 0.08 * width;
  plan.view.min_m = {low.x() - margin, low.y()};
  plan.view.max_m = {high.x() + margin, high.y()};
  if (scene.dimensions == 1) {
    // Room below the track and above the blocks for the velocity arrows.
    const double tallest = high.y();
    plan.view.min_m.y() = -0.6 * tallest;
    plan.view.max_m.y() = 2.4 * tallest;
  } else {
    plan.view.min_m.y() -= margin;
    plan.view.max_m.y() += margin;
  }
  const double view_width = plan.view.max_m.x() - plan.view.min_m.x();
  plan.arrow_m_per_mps = fastest_mps > 0.0 ? kLongestArrowFraction * view_width / fastest_mps : 0.0;
  plan.energy_full_scale_J = most_energy_J > 0.0 ? most_energy_J : 1.0;
  return plan;
}

render::FrameModel buildFrame(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                              const FramePlan& plan, const physics::Snapshot& snapshot) {
  render::FrameModel frame;
  frame.view = plan.view;
  frame.draw_track = scene.dimensions == 1;
  frame.track_y_m = 0.0;
  frame.arrow_m_per_mps = plan.arrow_m_per_mps;
  frame.energy_bar.full_scale_J = plan.energy_full_scale_J;
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    const scene::BodyDesc& body = scene.bodies[i];
    const physics::BodyState& state = snapshot.bodies[i];
    render::BodyModel model;
    model.shape = body.shape == "disk" ? render::BodyShape::kDisk : render::BodyShape::kRectangle;
    model.center_m = bodyCenter(body, state, scene.dimensions);
    model.half_extent_m = halfExtent(body);
    model.fill = bodyColor(i, body);
    model.velocity_mps = state.velocity_mps;
    frame.bodies.push_back(model);

    const double kinetic_J = 0.5 * defs[i].mass_kg * state.velocity_mps.squaredNorm();
    frame.energy_bar.segments.push_back({kinetic_J, model.fill, "KE" + std::to_string(i + 1)});
  }
  frame.energy_bar.segments.push_back({snapshot.energy_lost_J, lostEnergyColor(), "lost"});
  return frame;
}

}  // namespace collide::app
