// planFrames: one pass over the whole timeline to fix the camera, arrow scale, bar scale and the
// momentum diagram's scale before any frame is drawn.
#include <algorithm>
#include <cmath>

#include "compose/frame_builder.hpp"
#include "compose/frame_geometry.hpp"
#include "compose/scale_arrow.hpp"
#include "compose/suspension_view.hpp"
#include "physics/energy_books.hpp"

namespace collide::compose {
namespace {

constexpr int kPlanSamples = 400;               // uniform samples; collision instants are added
constexpr std::size_t kMaxPlanEvents = 2000;    // collision instants sampled, at most
constexpr double kLongestArrowFraction = 0.15;  // of the view width, for the fastest body
// Bodies whose top speed is more than this many times the typical (median) body's are drawn off
// scale, so a 200 m/s bullet does not shrink its 2 m/s block's arrow to a sliver.
constexpr double kOffScaleRatio = 10.0;
constexpr double kOffScaleArrowFraction = 0.22;  // of the view width: an off-scale arrow's length
constexpr double kNeverMovedShare = 1e-9;        // of the fastest top speed: rounding, not motion
constexpr double kScaleArrowShare = 0.6;  // the scale arrow is at most this share of the longest
constexpr double kMarginFraction = 0.08;  // 1D view margin, of the motion's extent
constexpr double kArrowTipPadFraction = 0.02;  // 1D: room beyond an arrow's tip, of the view width
// 2D: the margin round what moves and the walls, of its larger extent; labels find room beside
// the bodies, so the scene fills the frame.
constexpr double kPlaneMarginFraction = 0.03;
constexpr double kFlashS = 0.15;  // contact flash, seconds of playback

core::Vec2 frameVelocity(const scene::SceneDesc& scene, const physics::Timeline& timeline) {
  if (!scene.view.center_of_momentum_frame) return {0.0, 0.0};
  double mass = 0.0;
  core::Vec2 momentum{0.0, 0.0};
  for (const physics::BodyDef& body : timeline.world().bodies) {
    mass += body.mass_kg;
    momentum += body.mass_kg * body.velocity_mps;
  }
  core::Vec2 v = momentum / mass;
  if (scene.dimensions == 1) v.y() = 0.0;
  return v;
}

// The speed the longest arrow drawn to scale stands for: the fastest body's top speed, unless it
// is more than kOffScaleRatio times the median body's (then the fastest within that ratio).
// Bodies that never really moved do not count: a cradle's middle balls pass the impulse on and
// keep a rounding residue of ~1e-16 m/s, which as a median would put every arrow off scale.
double referenceSpeed(std::vector<double> top_speeds_mps) {
  const double fastest_mps = top_speeds_mps.empty()
                                 ? 0.0
                                 : *std::max_element(top_speeds_mps.begin(), top_speeds_mps.end());
  std::erase_if(top_speeds_mps, [&](double v) { return !(v > kNeverMovedShare * fastest_mps); });
  if (top_speeds_mps.empty()) return 0.0;
  std::sort(top_speeds_mps.begin(), top_speeds_mps.end());
  const double typical = top_speeds_mps[(top_speeds_mps.size() - 1) / 2];
  double reference = typical;
  for (double v : top_speeds_mps) {
    if (v <= kOffScaleRatio * typical) reference = v;
  }
  return reference;
}

// The instants the plan samples: kPlanSamples uniform ones, then the collisions' (at most
// kMaxPlanEvents). Also notes each body's first collision and the bonds of stuck bodies.
std::vector<double> planTimes(const physics::Timeline& timeline, FramePlan& plan) {
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  plan.first_collision_s.assign(defs.size(), INFINITY);
  std::vector<double> times;
  const double duration = timeline.duration_s();
  for (int i = 0; i <= kPlanSamples; ++i) times.push_back(duration * i / kPlanSamples);
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  for (std::size_t k = 0; k < events.size(); ++k) {
    const physics::CollisionEvent& event = events[k];
    for (int body : {event.body_a, event.body_b}) {
      if (body >= 0 && body < static_cast<int>(defs.size())) {
        plan.first_collision_s[body] = std::min(plan.first_collision_s[body], event.time_s);
      }
    }
    if (k < kMaxPlanEvents) times.push_back(event.time_s);
    if (event.merged && !event.hitsWall()) {
      plan.bonds.push_back({event.time_s, event.body_a, event.body_b});
    }
  }
  return times;
}

// What the samples show: the extent of the motion, the speeds, the momentum chain's reach and
// the energies.
struct Sweep {
  core::Vec2 low = core::Vec2::Constant(INFINITY), high = core::Vec2::Constant(-INFINITY);
  double fastest_mps = 0.0, farthest_Ns = 0.0;
  std::vector<double> top_speed_mps;                // per body
  std::vector<double> potential, rest;              // per sample: potential energy; kinetic + lost
  std::vector<std::pair<double, double>> moving_x;  // (centre x, velocity x) where it moves
  bool along_x = true;  // every body only ever moves along x (a 2D head-on shot: a track)
};

// Samples the run at `times`; sets the plan's momentum reach and initial momentum.
Sweep sweepSamples(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                   FramePlan& plan, const std::vector<double>& times) {
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  Sweep sweep;
  sweep.top_speed_mps.assign(defs.size(), 0.0);
  sweep.potential.resize(times.size());
  sweep.rest.resize(times.size());
  for (std::size_t s = 0; s < times.size(); ++s) {
    const physics::Snapshot snapshot = timeline.sample(times[s]);
    core::Vec2 chain{0.0, 0.0};
    for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
      const core::Vec2 c =
          drawnCenter(scene, i, snapshot.bodies[i], times[s], plan.frame_velocity_mps);
      sweep.low = sweep.low.cwiseMin(c - halfExtent(scene.bodies[i]));
      sweep.high = sweep.high.cwiseMax(c + halfExtent(scene.bodies[i]));
      const core::Vec2 v = snapshot.bodies[i].velocity_mps - plan.frame_velocity_mps;
      // hypot, not norm(): the square of 1e-300 m/s is below what a double holds, and the
      // picture's scale of speeds would be 0, its labels "0 m/s".
      const double speed_mps = std::hypot(v.x(), v.y());
      sweep.fastest_mps = std::max(sweep.fastest_mps, speed_mps);
      sweep.top_speed_mps[i] = std::max(sweep.top_speed_mps[i], speed_mps);
      if (std::abs(v.x()) > 0.0) sweep.moving_x.emplace_back(c.x(), v.x());
      sweep.along_x = sweep.along_x && v.y() == 0.0;
      chain += defs[i].mass_kg * v;
      sweep.farthest_Ns = std::max(sweep.farthest_Ns, std::hypot(chain.x(), chain.y()));
      plan.momentum_low_Ns = plan.momentum_low_Ns.cwiseMin(chain);
      plan.momentum_high_Ns = plan.momentum_high_Ns.cwiseMax(chain);
    }
    if (s == 0) plan.initial_momentum_Ns = chain;
    double kinetic = 0.0;
    for (double e : bodyKineticEnergies(timeline, plan, snapshot)) kinetic += e;
    sweep.potential[s] = plan.potential ? timeline.potentialEnergy(snapshot) : 0.0;
    sweep.rest[s] =
        kinetic + snapshot.energy_lost_J + snapshot.energy_to_surface_J + snapshot.energy_to_air_J;
  }
  return sweep;
}

// The full scales of the energy bar and the momentum diagram.
void setEnergyScales(FramePlan& plan, const Sweep& sweep, double released_J) {
  const std::vector<double>&potential = sweep.potential, &rest = sweep.rest;
  plan.potential_floor_J = *std::min_element(potential.begin(), potential.end());
  // The bar stands for the energy at the start (conserved as KE + PE + lost); the largest sum
  // only if nothing moves at first. Mid-contact soft-collision samples can book a loss early, so
  // the maximum would leave the bar short of full.
  // Energy released in the run (a spring, a shot, e > 1) adds to that: the largest total reached.
  plan.energy_start_J = rest[0] + potential[0] - plan.potential_floor_J;
  double most_energy_J = plan.energy_start_J + released_J;
  if (!(most_energy_J > 0.0)) {
    for (std::size_t s = 0; s < rest.size(); ++s) {
      most_energy_J = std::max(most_energy_J, rest[s] + potential[s] - plan.potential_floor_J);
    }
  }
  plan.energy_full_scale_J = most_energy_J > 0.0 ? most_energy_J : 1.0;
  // PE is counted from the lowest the bodies go. Where that is below the start by no more than a
  // millionth of the picture's energy (a bullet riding in a swinging block dips 10 µm below
  // where it came in), the start is the floor: at t = 0 PE reads 0, not "1.01 µJ" beside 200 J
  // (a dip below it is shown as 0: parts are never negative).
  constexpr double kStartFloorShare = 1e-6;
  if (potential[0] - plan.potential_floor_J <= kStartFloorShare * plan.energy_full_scale_J) {
    plan.potential_floor_J = potential[0];
  }
  plan.momentum_full_scale_Ns = sweep.farthest_Ns > 0.0 ? sweep.farthest_Ns : 1.0;
}

// Widens [low, high] to the walls that bound the motion.
void keepWallsInView(const scene::SceneDesc& scene, core::Vec2& low, core::Vec2& high) {
  for (const scene::WallDesc& wall : scene::allWalls(scene)) {
    if (scene.dimensions == 1 || std::abs(wall.normal.x()) > 0.99) {
      low.x() = std::min(low.x(), wall.position_m.x());
      high.x() = std::max(high.x(), wall.position_m.x());
    }
    if (scene.dimensions == 2 && std::abs(wall.normal.y()) > 0.99) {
      low.y() = std::min(low.y(), wall.position_m.y());
      high.y() = std::max(high.y(), wall.position_m.y());
    }
  }
}

// The view of [low, high] with its margin.
frame::ViewWindow viewAround(const scene::SceneDesc& scene, const core::Vec2& low,
                             const core::Vec2& high) {
  frame::ViewWindow view;
  const double width = std::max(high.x() - low.x(), 1e-3);
  if (scene.dimensions == 1) {
    const double margin = kMarginFraction * width;
    view.min_m = {low.x() - margin, 0.0};
    view.max_m = {high.x() + margin, std::max(high.y(), 1e-3)};
  } else {
    const double margin = kPlaneMarginFraction * std::max(width, high.y() - low.y());
    view.min_m = low - core::Vec2{margin, margin};
    view.max_m = high + core::Vec2{margin, margin};
  }
  return view;
}

// The arrows' scale for the plan's view: the reference speed's arrow kLongestArrowFraction of
// its width, an off-scale arrow's length capped.
void scaleArrows(FramePlan& plan, double reference_mps, bool off_scale) {
  const double view_width = plan.view.max_m.x() - plan.view.min_m.x();
  plan.arrow_m_per_mps =
      reference_mps > 0.0 ? kLongestArrowFraction * view_width / reference_mps : 0.0;
  plan.arrow_max_length_m = off_scale ? kOffScaleArrowFraction * view_width : 0.0;
}

// The arrows are part of the picture: widens the view until every arrow's tip (and a head's
// width beyond it) is in it at every sampled instant. Arrow lengths are a share of the view width
// (at most kOffScaleArrowFraction), so a few rounds settle it.
void widenForArrowTips(FramePlan& plan, const std::vector<std::pair<double, double>>& moving_x,
                       double reference_mps, bool off_scale) {
  const core::Vec2 motion_min = plan.view.min_m, motion_max = plan.view.max_m;
  for (int round = 0; round < 4; ++round) {
    const double pad = kArrowTipPadFraction * (plan.view.max_m.x() - plan.view.min_m.x());
    double from = motion_min.x(), to = motion_max.x();
    for (const auto& [x, v] : moving_x) {
      double length = std::abs(v) * plan.arrow_m_per_mps;
      if (plan.arrow_max_length_m > 0.0) length = std::min(length, plan.arrow_max_length_m);
      const double tip = x + (v > 0.0 ? length : -length);
      from = std::min(from, tip - pad);
      to = std::max(to, tip + pad);
    }
    plan.view.min_m.x() = from;
    plan.view.max_m.x() = to;
    scaleArrows(plan, reference_mps, off_scale);
  }
}

}  // namespace

std::vector<double> bodyKineticEnergies(const physics::Timeline& timeline, const FramePlan& plan,
                                        const physics::Snapshot& snapshot) {
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  std::vector<double> energies;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    energies.push_back(
        physics::bodyKineticEnergy_J(defs[i], snapshot.bodies[i], plan.frame_velocity_mps));
  }
  return energies;
}

FramePlan planFrames(const scene::SceneDesc& scene, const physics::Timeline& timeline) {
  FramePlan plan;
  plan.frame_velocity_mps = frameVelocity(scene, timeline);
  plan.potential = scene.gravity_mps2.squaredNorm() > 0.0;
  const double slowdown = std::max(1.0, scene.view.slow_motion_factor);
  plan.flash_s = kFlashS / slowdown;

  const std::vector<double> times = planTimes(timeline, plan);
  Sweep sweep = sweepSamples(scene, timeline, plan, times);
  plan.releases = physics::canReleaseEnergy(timeline.world());
  plan.friction = physics::hasFriction(timeline.world());
  plan.cloth = timeline.world().rolling;
  plan.drag = physics::hasDrag(timeline.world());
  plan.springs = !timeline.softContacts().empty();
  setEnergyScales(plan, sweep, timeline.totalEnergyReleased());
  // The loss only grows: a run that has lost nothing at its end never labels it.
  plan.loses_energy = timeline.sample(timeline.duration_s()).energy_lost_J >=
                      kLabelledShare * plan.energy_full_scale_J;
  // Walls bound the motion: keep them in view (not in the moving frame, where they drift).
  if (!scene.view.center_of_momentum_frame) keepWallsInView(scene, sweep.low, sweep.high);
  // Strings hang from their pivots: keep them and their bars in view.
  includePivots(scene, sweep.low, sweep.high);
  plan.view = viewAround(scene, sweep.low, sweep.high);
  const double reference_mps = referenceSpeed(sweep.top_speed_mps);
  const bool off_scale = sweep.fastest_mps > reference_mps * (1.0 + 1e-9);
  scaleArrows(plan, reference_mps, off_scale);
  // A plane scene whose bodies only move along x (billiards-follow) frames like a track: its
  // arrows lead the bodies out of the motion's extent (the object ball's ran off the frame).
  const bool track_like = scene.dimensions == 1 || sweep.along_x;
  if (track_like && plan.arrow_m_per_mps > 0.0) {
    widenForArrowTips(plan, sweep.moving_x, reference_mps, off_scale);
  }
  plan.scale_arrow_mps = roundValueBelow(kScaleArrowShare * reference_mps);
  plan.fastest_mps = sweep.fastest_mps;
  plan.skids = findSkids(timeline);
  plan.longest_skid_m = longestSkid_m(plan.skids, timeline);
  plan.formats = formatsFor({&plan}, timeline.duration_s());
  return plan;
}

PictureFormats formatsFor(const std::vector<const FramePlan*>& plans, double duration_s) {
  double energy = 0.0, speed = 0.0, momentum = 0.0, length = 0.0;
  for (const FramePlan* plan : plans) {
    energy = std::max(energy, plan->energy_full_scale_J);
    speed = std::max(speed, plan->fastest_mps);
    momentum = std::max(momentum, plan->momentum_full_scale_Ns);
    length = std::max(length, plan->longest_skid_m);
  }
  return pictureFormats(energy, speed, momentum, duration_s, length);
}

}  // namespace collide::compose
