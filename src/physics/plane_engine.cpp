// The 2D engine's queue and event loop. See plane_engine.hpp.
#include "physics/plane_engine.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

core::Vec2 rotate(const core::Vec2& v, double angle_rad) {
  if (angle_rad == 0.0) return v;
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// The sentence for a run stopped by a resting stack. It names the two disks so that the user
// can find them in the scene.
std::string restingStackMessage(const WorldDef& world, int upper, int lower, std::int64_t processed,
                                double t_s) {
  char text[400];
  // Without gravity in the plane, what presses one disk onto the other is sliding friction
  // slowing the one ahead more.
  const bool by_friction = world.gravity_mps2.x() == 0.0 && world.gravity_mps2.y() == 0.0;
  std::snprintf(text, sizeof text,
                "stopped at t = %.9g s after %lld collisions because disk \"%s\" came to rest on "
                "disk \"%s\" %s, which the event-driven model does not follow; later states are "
                "not simulated",
                t_s, static_cast<long long>(processed), world.bodies[upper].name.c_str(),
                world.bodies[lower].name.c_str(),
                by_friction ? "pressed onto it by sliding friction (a lasting contact)"
                            : "under gravity (a resting stack)");
  return text;
}

// The sentence for a run stopped by two disks pressed together in a scene with drag: the air
// slows the one ahead more (or gravity presses), so they would move on in lasting contact.
std::string pressedPairMessage(const WorldDef& world, int a, int b, std::int64_t processed,
                               double t_s) {
  char text[500];
  std::snprintf(text, sizeof text,
                "stopped at t = %.9g s after %lld collisions because disks \"%s\" and \"%s\" "
                "were pressed together after an impact at e = 0 (the air slows one more than the "
                "other, or gravity presses them), a lasting contact which the event-driven model "
                "does not follow; later states are not simulated (equal drag rates k/m avoid it)",
                t_s, static_cast<long long>(processed), world.bodies[a].name.c_str(),
                world.bodies[b].name.c_str());
  return text;
}

// The sentence for a run stopped by the clustering guard, naming the disk that found it.
std::string clusterMessage(const Model& model, int body, std::int64_t processed, double t_s) {
  char text[700];
  std::snprintf(text, sizeof text,
                "stopped at t = %.9g s after %lld collisions because disk \"%s\" had %d impacts "
                "at a restitution below 1 within %.3g s (the time the fastest body takes to "
                "cross the smallest): disks that lose energy at each impact gathered into a "
                "cluster whose collisions come ever faster while time hardly advances (an "
                "inelastic collapse), which the event-driven model cannot pass; later states "
                "are not simulated (a restitution nearer 1, fewer bodies or a shorter duration "
                "avoid it)",
                t_s, static_cast<long long>(processed), model.world.bodies[body].name.c_str(),
                static_cast<int>(kClusterImpacts), model.time_scale_s);
  return text;
}

}  // namespace

void PlaneEngine::noteClustering(int body, double t, const ImpactDecision& d) {
  if (!(d.e_requested < 1.0) || !std::isfinite(model_.time_scale_s)) return;
  if (state_.noteInelasticImpact(body, t, model_.time_scale_s) >= kClusterImpacts &&
      clustered_body_ < 0) {
    clustered_body_ = body;
  }
}

PlaneEngine::PlaneEngine(const Model& model, EngineState start, const Recorder& out)
    : model_(model),
      state_(std::move(start)),
      out_(out),
      rate_guard_(model.world.max_collisions_per_second) {
  version_.assign(state_.units.size(), 0);
  members_.assign(state_.units.size(), {});
  for (int i = 0; i < static_cast<int>(state_.bodies.size()); ++i) {
    members_[state_.bodies[i].unit].push_back(i);
  }
  friction_ = model.has_friction;
  if (friction_) {
    kinetic_decel_.assign(state_.units.size(), 0.0);
    for (int id = 0; id < static_cast<int>(state_.units.size()); ++id) {
      if (state_.units[id].alive) setFrictionLaw(id);
    }
  }
  setUpGrid();
  rebuildQueue();
}

PlaneEngine::Kin PlaneEngine::clusterKinematics(int body, double t) const {
  const BodyLink& link = state_.bodies[body];
  const UnitState& u = state_.units[link.unit];
  const double dt = t - u.t_ref_s;
  Kin k;
  const core::Vec2 centre = u.x_ref_m + u.v_mps * dt + 0.5 * u.a_mps2 * dt * dt;
  const core::Vec2 velocity = u.v_mps + u.a_mps2 * dt;
  k.arm = rotate(link.offset_m, u.angle_ref_rad + u.omega_radps * dt);
  k.x = centre + k.arm;
  k.v = velocity + u.omega_radps * core::Vec2(-k.arm.y(), k.arm.x());
  return k;
}

void PlaneEngine::advanceUnit(int id, double t) {
  UnitState& u = state_.units[id];
  const double dt = t - u.t_ref_s;
  if (friction_) bookSurface(u, t);
  if (dt != 0.0 && model_.has_drag && hasDrag(u)) {
    advanceDragged(u, t);
  } else if (dt != 0.0) {
    u.x_ref_m += u.v_mps * dt + 0.5 * u.a_mps2 * dt * dt;
    u.v_mps += u.a_mps2 * dt;
    u.angle_ref_rad += u.omega_radps * dt;
  }
  u.t_ref_s = t;
}

void PlaneEngine::push(int kind, int a, int b, double time) {
  if (!(time <= model_.world.duration_s)) return;
  const std::uint32_t stamp_a = version_[state_.bodies[a].unit];
  const std::uint32_t stamp_b = kind == 0 ? version_[state_.bodies[b].unit] : 0;
  heap_.push_back(Event{time, kind, a, b, stamp_a, stamp_b});
  std::push_heap(heap_.begin(), heap_.end(), Later{});
}

bool PlaneEngine::valid(const Event& event) const {
  const int unit_a = state_.bodies[event.a].unit;
  if (version_[unit_a] != event.stamp_a) return false;
  if (event.kind != 0) return true;
  const int unit_b = state_.bodies[event.b].unit;
  return unit_a != unit_b && version_[unit_b] == event.stamp_b;
}

void PlaneEngine::pushPair(int i, int j) {
  const double time = predictPair(i, j);
  // With the grid, an impact after either disk's next cell crossing is predicted again at that
  // crossing if the two are still neighbours, and cannot happen before another crossing if not:
  // keeping it out of the queue keeps the queue near the number of disks.
  if (grid_ && time > std::min(crossing_s_[i], crossing_s_[j])) return;
  push(0, std::min(i, j), std::max(i, j), time);
}

void PlaneEngine::pushWall(int body, int wall) {
  const double time = predictWall(body, wall);
  // Likewise an impact on a wall after the disk's next cell crossing is predicted again there.
  if (grid_ && time > crossing_s_[body]) return;
  push(1, body, wall, time);
}

void PlaneEngine::pushWalls(int body) {
  if (grid_ && !cell_walls_.empty()) {
    // A wall out of reach of the cell can only be met after the next crossing: not predicted.
    std::uint32_t reachable = cell_walls_[body_cell_y_[body] * cells_x_ + body_cell_x_[body]];
    while (reachable != 0) {
      pushWall(body, std::countr_zero(reachable));
      reachable &= reachable - 1;
    }
    return;
  }
  for (int w = 0; w < static_cast<int>(model_.world.walls.size()); ++w) pushWall(body, w);
}

void PlaneEngine::rebuildQueue() {
  heap_.clear();
  const int n = static_cast<int>(state_.bodies.size());
  if (grid_) {
    crossing_queue_.reset(n);
    for (int i = 0; i < n; ++i) predictCrossing(i);
  }
  for (int i = 0; i < n; ++i) {
    if (grid_) {
      forNeighbours(i, [&](int j) {
        if (j > i && state_.bodies[i].unit != state_.bodies[j].unit) pushPair(i, j);
      });
    } else {
      for (int j = i + 1; j < n; ++j) {
        if (state_.bodies[i].unit != state_.bodies[j].unit) push(0, i, j, predictPair(i, j));
      }
    }
    pushWalls(i);
  }
  if (friction_) {
    for (int id = 0; id < static_cast<int>(state_.units.size()); ++id) pushStop(id);
  }
  heap_limit_ = std::max<std::size_t>(4096, 8 * heap_.size());
}

void PlaneEngine::predictUnit(int id, int skip_unit) {
  const int n = static_cast<int>(state_.bodies.size());
  for (int i : members_[id]) {
    auto pair = [&](int j) {
      const int other = state_.bodies[j].unit;
      if (other != id && other != skip_unit) pushPair(i, j);
    };
    if (grid_) {
      predictCrossing(i);
      forNeighbours(i, pair);
    } else {
      for (int j = 0; j < n; ++j) pair(j);
    }
    pushWalls(i);
  }
  if (friction_) pushStop(id);
}

void PlaneEngine::renew(int id) {
  version_[id] = ++last_stamp_;
  if (friction_ && state_.units[id].alive) {
    state_.units[id].rolls = false;  // an impact changed it: a ball's contact point slips
    setFrictionLaw(id);
  }
}

bool PlaneEngine::nextEvent(Event& next) {
  while (!heap_.empty() && !valid(heap_.front())) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    heap_.pop_back();
  }
  if (crossing_queue_.empty()) {
    if (heap_.empty()) return false;
    next = heap_.front();
    return true;
  }
  const CrossingQueue::Entry& crossing = crossing_queue_.top();
  next = Event{crossing.time_s, kCrossing, crossing.body, crossing.direction, 0, 0};
  if (!heap_.empty() && !Later{}(heap_.front(), next)) next = heap_.front();
  return true;
}

void PlaneEngine::popHeap() {
  std::pop_heap(heap_.begin(), heap_.end(), Later{});
  heap_.pop_back();
}

RunStop PlaneEngine::run(double t_end_s, std::int64_t count_limit) {
  const std::int64_t cap = model_.world.max_collisions;
  Event event;
  for (;;) {
    if (state_.collision_count >= count_limit && !(friction_ && stopDue(t_end_s))) {
      return RunStop::kCountLimit;
    }
    if (!nextEvent(event)) return RunStop::kDone;
    if (!(event.time_s <= t_end_s)) return RunStop::kDone;
    if (event.kind == kStop) {  // no collision: before the caps, which count collisions
      popHeap();
      state_.time_s = std::max(state_.time_s, event.time_s);
      stopUnit(state_.bodies[event.a].unit, event.time_s);
      continue;
    }
    if (state_.collision_count >= cap) return RunStop::kCollisionCap;
    if (rate_guard_.exceeded(state_.collision_count, event.time_s)) {
      out_.warn({WarningKind::kCollisionRateCap, state_.collision_count - 1, state_.time_s,
                 rate_guard_.message(state_.collision_count, state_.time_s)});
      return RunStop::kRateCap;
    }
    if (event.time_s == state_.time_s) {
      if (++same_time_events_ > kStallEventCount) return RunStop::kStalled;
    } else {
      same_time_events_ = 0;
    }
    if (event.kind == kCrossing) {  // bookkeeping of the broad phase, not an impact
      crossCell(event);             // replaces the body's entry in crossing_queue_
      continue;
    }
    popHeap();
    state_.time_s = event.time_s;
    if (collectTies(event)) {
      resolveInstant(event.time_s);
    } else if (event.kind == 0) {
      pairImpact(event.a, event.b, event.time_s);
    } else {
      wallImpact(event.a, event.b, event.time_s);
    }
    if (resting_upper_ >= 0) {
      out_.warn({WarningKind::kStalled, state_.collision_count - 1, event.time_s,
                 model_.has_drag
                     ? pressedPairMessage(model_.world, std::min(resting_upper_, resting_lower_),
                                          std::max(resting_upper_, resting_lower_),
                                          state_.collision_count, event.time_s)
                     : restingStackMessage(model_.world, resting_upper_, resting_lower_,
                                           state_.collision_count, event.time_s)});
      return RunStop::kStalled;
    }
    if (clustered_body_ >= 0) {
      out_.warn({WarningKind::kStalled, state_.collision_count - 1, event.time_s,
                 clusterMessage(model_, clustered_body_, state_.collision_count, event.time_s)});
      return RunStop::kStalled;
    }
    if (friction_ && frictionStalls(event.time_s)) return RunStop::kStalled;
    if (drop_grid_) {
      drop_grid_ = false;
      dropGrid();
      rebuildQueue();
    }
    if (heap_.size() > heap_limit_) rebuildQueue();
  }
}

std::unique_ptr<Engine> makePlaneEngine(const Model& model, EngineState start,
                                        const Recorder& out) {
  return std::make_unique<PlaneEngine>(model, std::move(start), out);
}

}  // namespace collide::physics::detail
