// The string engine's predictions: the next impact, slack or taut event (see string_engine.hpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>

#include "physics/bracketed_contact.hpp"
#include "physics/string_engine.hpp"
#include "physics/swing_pair_bound.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
// Relative size of speeds, angles and gaps that are rounding, not motion or clearance.
constexpr double kRounding = 1e-12;
// Free flight changes its speed bound as it goes: searches look this far ahead at a time, s.
constexpr double kFreeChunk_s = 0.25;

// The first time from `from` to `t_end` at which `gap` closes to contact, searched `chunk_s` at
// a time (infinite: all at once, where the bounds hold for all time). `search_for(start, end)`
// gives the chunk's bounds (its start_s and end_s are set here), or none where nothing can
// close over it.
template <typename SearchFor>
double firstContactByChunks(const std::function<GapSample(double)>& gap, double from, double t_end,
                            double chunk_s, const SearchFor& search_for) {
  for (double start = from; start <= t_end;) {
    const double end = std::min(t_end, start + chunk_s);
    std::optional<ContactSearch> search = search_for(start, end);
    if (!search) return kInfinity;
    search->start_s = start;
    search->end_s = end;
    const double t = firstContact_s(gap, *search);
    if (std::isfinite(t)) return t;
    if (end >= t_end) break;
    start = end;
  }
  return kInfinity;
}

}  // namespace

SwingPair StringEngine::swingPair(int ua, int ub, double t, double reach_m) const {
  const SwingState &sa = state_.swings[ua], &sb = state_.swings[ub];
  const PendulumArc &arc_a = *arcs_[ua], &arc_b = *arcs_[ub];
  SwingPair pair;
  pair.length_m = sa.length_m;
  pair.omega0_rad_s = std::sqrt(gravity_m_s2_ / sa.length_m);
  pair.reach_m = reach_m;
  pair.a = arc_a.at(t - sa.t_ref_s);
  pair.b = arc_b.at(t - sb.t_ref_s);
  // A swing's angle stays within its amplitude of the turn it started in; only swings that
  // started within half a turn of straight down keep a bound below pi.
  const bool near_bottom = std::abs(pair.a.angle_rad) <= kPi && std::abs(pair.b.angle_rad) <= kPi &&
                           arc_a.kind() != PendulumKind::kRotation &&
                           arc_b.kind() != PendulumKind::kRotation;
  pair.largest_angle_rad =
      near_bottom ? std::max(arc_a.amplitude_rad(), arc_b.amplitude_rad()) : kPi;
  // omega^2 = 4 omega0^2 (h - sin^2(theta / 2)) <= 4 omega0^2 h.
  pair.angular_speed_bound_rad_s =
      2.0 * pair.omega0_rad_s *
      std::sqrt(std::max(arc_a.energyParameter(), arc_b.energyParameter()));
  return pair;
}

double StringEngine::predictPair(int a, int b, double t_end) const {
  const int ua = state_.bodies[a].unit, ub = state_.bodies[b].unit;
  if (ua == ub) return kInfinity;
  const double t0 = state_.time_s;
  // Two bodies at rest at the bottom of their strings, or on strings of one length swinging
  // in step (a cradle's balls leaving together): their distance never changes.
  const auto resting = [&](int u) { return arcs_[u] && arcs_[u]->kind() == PendulumKind::kRest; };
  if (resting(ua) && resting(ub)) return kInfinity;
  if (arcs_[ua] && arcs_[ub]) {
    const SwingState &sa = state_.swings[ua], &sb = state_.swings[ub];
    const PendulumState pa = arcs_[ua]->at(t0 - sa.t_ref_s), pb = arcs_[ub]->at(t0 - sb.t_ref_s);
    const double omega0 = std::sqrt(gravity_m_s2_ / sa.length_m);
    if (std::abs(sa.length_m - sb.length_m) <= kRounding * sa.length_m &&
        std::abs(pa.angle_rad - pb.angle_rad) <= kRounding &&
        std::abs(pa.angular_velocity_rad_s - pb.angular_velocity_rad_s) <= kRounding * omega0) {
      return kInfinity;
    }
  }
  const double reach = model_.half_size_m[a] + model_.half_size_m[b];
  const auto gap = [&](double t) {
    const Kin ka = bodyAt(a, t), kb = bodyAt(b, t);
    const core::Vec2 d = kb.x - ka.x;
    const double distance = d.norm();
    return GapSample{distance - reach, d.dot(kb.v - ka.v) / distance};
  };
  // Two swings on strings of one length: their relative motion bounds the curvature far more
  // tightly as they come into step, over chunks of 1 / omega0 (the bound grows with the horizon
  // by at most a factor e^2 over that).
  const bool one_length = arcs_[ua] && arcs_[ub] &&
                          std::abs(state_.swings[ua].length_m - state_.swings[ub].length_m) <=
                              kRounding * state_.swings[ua].length_m;
  const double chunk_s = one_length ? 1.0 / std::sqrt(gravity_m_s2_ / state_.swings[ua].length_m)
                         : arcs_[ua] && arcs_[ub] ? kInfinity
                                                  : kFreeChunk_s;
  return firstContactByChunks(
      gap, t0, t_end, chunk_s, [&](double start, double end) -> std::optional<ContactSearch> {
        const double va = speedBound(ua, start, end), vb = speedBound(ub, start, end);
        if (va + vb <= kRounding * model_.speed_scale_mps) return std::nullopt;  // nothing closes
        ContactSearch search;
        // |distance''| <= |relative velocity|^2 / distance + |relative acceleration|.
        search.curvature_mps2 =
            (va + vb) * (va + vb) / reach + accelBound(ua, va) + accelBound(ub, vb);
        if (one_length) {
          search.curvature_mps2 =
              std::min(search.curvature_mps2,
                       swingPairCurvature_mps2(swingPair(ua, ub, start, reach), end - start));
        }
        search.closing_floor_mps = kRounding * std::max(model_.speed_scale_mps, va + vb);
        search.touch_m = kRounding * std::max(1.0, reach);
        return search;
      });
}

double StringEngine::predictWall(int body, int wall, double t_end) const {
  const int unit = state_.bodies[body].unit;
  if (arcs_[unit] && arcs_[unit]->kind() == PendulumKind::kRest) return kInfinity;
  const WallDef& w = model_.world.walls[wall];
  const double radius = model_.half_size_m[body];
  const auto gap = [&](double t) {
    const Kin k = bodyAt(body, t);
    return GapSample{w.normal.dot(k.x - w.point_m) - radius, w.normal.dot(k.v)};
  };
  return firstContactByChunks(
      gap, state_.time_s, t_end, arcs_[unit].has_value() ? kInfinity : kFreeChunk_s,
      [&](double start, double end) -> std::optional<ContactSearch> {
        const double v = speedBound(unit, start, end);
        ContactSearch search;
        search.curvature_mps2 = accelBound(unit, v);
        search.closing_floor_mps = kRounding * std::max(model_.speed_scale_mps, v);
        search.touch_m = kRounding * std::max(1.0, radius);
        return search;
      });
}

std::optional<StringEngine::Event> StringEngine::predictString(int unit) const {
  const SwingState& swing = state_.swings[unit];
  if (!swing.has_string) return std::nullopt;
  if (swing.taut) {
    const std::optional<double> slack = arcs_[unit]->slackTime_s();
    if (!slack) return std::nullopt;
    return Event{std::max(swing.t_ref_s + *slack, state_.time_s), Kind::kSlack, unit, 0};
  }
  const UnitState& u = state_.units[unit];
  const std::optional<double> taut =
      tautTime_s(swing.length_m, gravity_m_s2_, u.x_ref_m - swing.pivot_m, u.v_mps);
  if (!taut) return std::nullopt;
  return Event{std::max(u.t_ref_s + *taut, state_.time_s), Kind::kTaut, unit, 0};
}

std::optional<StringEngine::Event> StringEngine::nextEvent(double t_end) const {
  std::optional<Event> best;
  // Earliest first; ties broken by kind, then indices: a total order.
  const auto consider = [&](const Event& e) {
    if (!(e.time_s <= t_end)) return;
    if (!best || e.time_s < best->time_s ||
        (e.time_s == best->time_s &&
         std::make_tuple(e.kind, -e.closing_mps, e.a, e.b) <
             std::make_tuple(best->kind, -best->closing_mps, best->a, best->b))) {
      best = e;
    }
  };
  const int bodies = static_cast<int>(state_.bodies.size());
  const int walls = static_cast<int>(model_.world.walls.size());
  // String events first: they are cheap and bound the searches for impacts, which need look no
  // further than the best event so far (a search that finds a contact finds the same one
  // whatever its end).
  for (int u = 0; u < static_cast<int>(state_.units.size()); ++u) {
    if (!state_.units[u].alive) continue;
    if (const std::optional<Event> e = predictString(u)) consider(*e);
  }
  const auto horizon = [&] { return best ? best->time_s : t_end; };
  for (int a = 0; a < bodies; ++a) {
    for (int b = a + 1; b < bodies; ++b) {
      Event e{predictPair(a, b, horizon()), Kind::kPair, a, b};
      if (e.time_s == state_.time_s) {
        const Kin ka = bodyAt(a, e.time_s), kb = bodyAt(b, e.time_s);
        e.closing_mps = (kb.x - ka.x).normalized().dot(ka.v - kb.v);
      }
      consider(e);
    }
    for (int w = 0; w < walls; ++w) consider({predictWall(a, w, horizon()), Kind::kWall, a, w});
  }
  return best;
}

}  // namespace collide::physics::detail
