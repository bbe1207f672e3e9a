// SPDX-License-Identifier: MIT
// The 1D engine's releases: stored energy pushing two touching units apart at a stated time
// (world.hpp, ReleaseDef). See line_engine.hpp.
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/line_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {

double LineEngine::nextReleaseTime() const {
  const std::vector<ReleaseDef>& releases = model_.world.releases;
  return state_.releases_done < releases.size() ? releases[state_.releases_done].time_s : kNever;
}

int LineEngine::releaseSlot(const ReleaseDef& release) const {
  const int l = state_.bodies[release.body_a].unit, r = state_.bodies[release.body_b].unit;
  if (l == r) return -1;
  for (int slot = 1; slot < static_cast<int>(order_.size()); ++slot) {
    if (order_[slot - 1] != l || order_[slot] != r) continue;
    const bool faces = last_body_[l] == release.body_a && first_body_[r] == release.body_b;
    return faces && slot_mass_[slot] > 0.0 ? slot : -1;
  }
  return -1;
}

void LineEngine::applyRelease(double t) {
  const ReleaseDef& release = model_.world.releases[state_.releases_done++];
  const int slot = releaseSlot(release);
  const int l = slot > 0 ? order_[slot - 1] : -1, r = slot > 0 ? order_[slot] : -1;
  double gap = 0.0;
  if (slot > 0) {
    advance(state_.units[l], t);
    advance(state_.units[r], t);
    gap = (state_.units[r].x_ref_m.x() + left_m_[r]) - (state_.units[l].x_ref_m.x() + right_m_[l]);
  }
  // Touching as a scene file may place them: within a part in 1e9 of their sizes.
  const double reach =
      1e-9 * (model_.half_size_m[release.body_a] + model_.half_size_m[release.body_b]);
  if (slot < 0 || std::abs(gap) > reach) {
    skipRelease(release, t, slot > 0);
    return;
  }
  UnitState &ul = state_.units[l], &ur = state_.units[r];
  const double vl = ul.v_mps.x(), vr = ur.v_mps.x();
  const double separating = vr - vl, mu = slot_mass_[slot];
  // The separation speed afterwards: a stated speed adds to it; a stated energy Q sets it by
  // 1/2 mu (s'^2 - s^2) = Q. The released energy is booked from the stated values, never from a
  // difference of kinetic energies.
  double added = release.separation_speed_mps, released = 0.0;
  if (added > 0.0) {
    released = 0.5 * mu * added * (2.0 * separating + added);
  } else {
    added = std::sqrt(separating * separating + 2.0 * release.energy_J / mu) - separating;
    released = release.energy_J;
  }
  const double impulse = mu * added;
  ul.v_mps.x() = vl - impulse * inverse_mass_[l];
  ur.v_mps.x() = vr + impulse * inverse_mass_[r];
  state_.energy_released.add(released);
  if (out_.wants(state_.collision_count)) {
    CollisionEvent event;
    event.index = state_.collision_count;
    event.time_s = t;
    event.body_a = release.body_a;
    event.body_b = release.body_b;
    event.restitution = event.restitution_requested =
        model_.pairRestitution(release.body_a, release.body_b);
    event.normal = {1.0, 0.0};
    event.velocity_a_before_mps = {vl, 0.0};
    event.velocity_a_after_mps = {ul.v_mps.x(), 0.0};
    event.velocity_b_before_mps = {vr, 0.0};
    event.velocity_b_after_mps = {ur.v_mps.x(), 0.0};
    event.closing_speed_mps = std::max(-separating, 0.0);
    event.impulse_Ns = impulse;
    event.energy_released_J = released;
    event.release = true;
    out_.emit(event);
  }
  ++state_.collision_count;
  ++state_.releases_applied;
  const int units = static_cast<int>(order_.size());
  setSlot(slot - 1, slot == 1 ? predictWall(true) : predictPair(slot - 1));
  setSlot(slot, predictPair(slot));
  setSlot(slot + 1, slot + 1 == units ? predictWall(false) : predictPair(slot + 1));
  two_bodies_ = twoBodyFastPathApplies();
}

void LineEngine::skipRelease(const ReleaseDef& release, double t, bool apart) {
  const WorldDef& world = model_.world;
  char text[500];
  std::snprintf(
      text, sizeof text, "the release at t = %.9g s between \"%s\" and \"%s\" released nothing: %s",
      t, world.bodies[release.body_a].name.c_str(), world.bodies[release.body_b].name.c_str(),
      apart ? "they no longer touch" : "they move as one, held together by an impact");
  out_.warn({WarningKind::kReleaseSkipped, -1, t, text});
}

}  // namespace collide::physics::detail
