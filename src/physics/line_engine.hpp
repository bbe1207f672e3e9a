#pragma once
// Internal: the 1D engine, blocks on a line. Bodies never pass each other, so the order along the
// line is fixed and only neighbours can meet. Units (single blocks or merged composites) are
// contiguous runs in that order. Each gap between neighbouring units, and the gap between an end
// unit and the innermost wall on its side, is one event slot holding its predicted time;
// recomputing a slot overwrites (invalidates) its previous prediction. The earliest slot comes
// from a scan (a few slots) or a tournament tree (many).
//
// line_engine.cpp holds the hot path (elastic and partly elastic impulses, which is all that
// pi-blocks needs); line_contacts.cpp the rarer outcomes (merges, attachment to a wall, soft
// contacts) and the event records; line_two_bodies.cpp the same loop specialised to two elastic
// bodies; line_wall_pair.cpp two elastic bodies and one wall, which is where pi-blocks spends its
// hundreds of millions of impacts.
#include <algorithm>
#include <optional>
#include <vector>

#include "physics/drag_motion.hpp"
#include "physics/engine.hpp"
#include "physics/impact_rules.hpp"
#include "physics/rate_guard.hpp"
#include "physics/soft_contact.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {

class LineEngine final : public Engine {
 public:
  LineEngine(const Model& model, EngineState start, const Recorder& out);
  RunStop run(double t_end_s, std::int64_t count_limit) override;
  const EngineState& state() const override { return state_; }

 private:
  // What one impact between two units (or a unit and a wall) looked like, for the records.
  struct Impact {
    double t_s = 0.0;
    int body_a = 0, body_b = 0;  // body_b: kWallPartnerBase - wall for walls
    double normal_x = 1.0;       // from a towards b
    double va_before = 0.0, va_after = 0.0, vb_before = 0.0, vb_after = 0.0;  // m/s
    double closing_mps = 0.0;
    double impulse_Ns = 0.0;
    double lost_J = 0.0;           // booked in the ledger
    double lost_analytic_J = 0.0;  // 1/2 m_eff (1 - e^2) u^2 (soft contacts: what e asks for)
    double duration_s = 0.0;
    bool merged = false;
    ImpactDecision decision;
  };

  void rebuild();  // order, extents, caches and slots from state_ alone
  int earliest() const;
  void refresh(int slot);
  void setSlot(int slot, double time);
  double predict(int slot) const;
  double predictPair(int slot) const;
  double predictWall(bool left) const;

  double positionAt(const UnitState& u, double t) const {
    const double dt = t - u.t_ref_s;
    if (drag_ && hasDrag(u)) return dragMotion(u, dt).position_m.x();
    if (!accelerated_) return u.x_ref_m.x() + u.v_mps.x() * dt;
    return u.x_ref_m.x() + u.v_mps.x() * dt + 0.5 * u.a_mps2.x() * dt * dt;
  }
  double velocityAt(const UnitState& u, double t) const {
    if (drag_ && hasDrag(u)) return dragMotion(u, t - u.t_ref_s).velocity_mps.x();
    if (!accelerated_) return u.v_mps.x();
    return u.v_mps.x() + u.a_mps2.x() * (t - u.t_ref_s);
  }
  void advance(UnitState& u, double t) {
    if (t != u.t_ref_s && !u.attached) {
      if (friction_) bookFriction(u, t);
      if (drag_ && hasDrag(u)) {
        advanceDragged(u, t);
        return;
      }
      const double x = positionAt(u, t);
      u.v_mps.x() = velocityAt(u, t);
      u.x_ref_m.x() = x;
    }
    u.t_ref_s = t;
  }

  // Sliding friction (line_friction.cpp). Each unit's acceleration is a pure function of its
  // velocity at t_ref (kinetic friction against it, or static friction holding it at rest), a
  // unit coming to rest is an event (a stop), and a prediction past a partner's stop is none:
  // the stop predicts again. Scenes with friction run their own loop.
  RunStop runWithFriction(double t_end_s, std::int64_t count_limit);
  void settleFriction();            // every unit's law from its velocity; every slot again
  void setFrictionLaw(int id);      // a_mps2 and friction_mps2 from v (and gravity)
  double stopTime(int id) const;    // when the unit comes to rest sliding, or kNever
  void stopUnit(int id, double t);  // at rest exactly, then static friction's law
  bool joinPressingPair();          // joins one touching pair pressed together, if any
  void frictionTables();            // kinetic_decel_, static_decel_ (by rebuild)
  // The acceleration pressing a unit at rest onto a wall of normal n: 0 where static friction
  // holds it (at rest against a wall it then stays for good: in 1D impacts only press it on).
  double pushAtRest(int id, double n) const;
  void bookFriction(const UnitState& u, double t);  // friction's work and impulse up to t
  double beforeStops(double time, int l, int r) const {
    if (!friction_) return time;
    const double stop = std::min(l >= 0 ? stopTime(l) : kNever, r >= 0 ? stopTime(r) : kNever);
    return time <= stop ? time : kNever;
  }
  void impactAt(int slot, double t);  // the run loop's impacts at t: a round, a wall or a pair

  // Air drag (line_drag.cpp). A unit with drag moves by drag's closed forms (drag_motion.hpp);
  // its drag's work is booked per piece of motion, and times of impact with it are found by
  // bracketed root finding (drag_contact.hpp).
  void dragTables();                            // each unit's drag from its bodies (by rebuild)
  void advanceDragged(UnitState& u, double t);  // to t, booking the work to the air
  double predictDragged(int l, int r) const;    // the gap between units l and r (-1: a wall)
  double accelerationNow(int id) const;         // at the unit's reference velocity

  // The acceleration pressing unit id onto the wall of normal n (into free space), or a free unit
  // onto an attached neighbour: gravity, and with friction what decelerates a rebound (kinetic
  // friction points back at the partner while the unit moves away from it).
  double wallPush(int id, double n) const {
    if (friction_) return -model_.world.gravity_mps2.x() * n + kinetic_decel_[id];
    return accelerated_ ? -state_.units[id].a_mps2.x() * n : 0.0;
  }
  // Between two free units with friction: how fast the one behind gains on the one ahead (less
  // friction behind), which ends their bounces as a floor ends a ball's.
  double pairPush(int l, int r) const {
    if (!accelerated_) return 0.0;
    if (inverse_mass_[l] == 0.0) return wallPush(r, 1.0);
    if (inverse_mass_[r] == 0.0) return wallPush(l, -1.0);
    if (drag_) return std::max(accelerationNow(l) - accelerationNow(r), 0.0);
    if (!friction_) return 0.0;
    return std::max(state_.units[l].a_mps2.x() - state_.units[r].a_mps2.x(), 0.0);
  }

  // Simultaneous impacts (line_groups.cpp). Every slot due within rounding of t (kTieUlps) is
  // one round; rounds repeat while slots stay due at t. See docs/physics.md.
  void collectDue(int node, double window_s);
  void resolveRound(double t);
  void groupImpact(int first, int last, double t);  // slots first..last, adjacent, all due
  struct Contact;
  // The steps of groupImpact, over contacts_: a contact's partners, closing speed and
  // restitution (its units advanced to t); the impulses of the tridiagonal system; a contact's
  // record; the perfectly inelastic contacts' merges and attachments.
  void decideGroupContact(Contact& c, double t);
  void solveGroupImpulses();
  void recordGroupContact(const Contact& c, double t, double lost);
  void mergeGroup(int first, double t);
  void joinUnits(int slot, double t);  // merge the pair of a slot (no record)
  void attachUnit(int id, bool left);  // fix a unit against a wall (no record)

  // The fast path for two elastic bodies without gravity (line_two_bodies.cpp): runs events
  // like run() while it can; false when the next event needs the general loop.
  bool twoBodyFastPathApplies() const;
  [[gnu::noinline]] bool runTwoBodies(double t_end_s, std::int64_t count_limit, RunStop& stop);
  struct TwoBodyRun;  // its state and steps (line_two_bodies.cpp)
  // Two elastic bodies and one wall without gravity (line_wall_pair.cpp): every event of such a
  // run, recorded or not; false when a round needs the general loop.
  bool wallPairApplies() const;
  [[gnu::noinline]] bool runWallPair(double t_end_s, std::int64_t count_limit, RunStop& stop);
  struct WallPairRun;

  // Releases (line_release.cpp): the next one's time (kNever when all have acted), the slot
  // between its bodies (-1 unless they are neighbouring units face to face), and its action.
  double nextReleaseTime() const;
  int releaseSlot(const ReleaseDef& release) const;
  [[gnu::noinline]] void applyRelease(double t);
  [[gnu::noinline]] void skipRelease(const ReleaseDef& release, double t, bool apart);

  void wallImpact(bool left, double t);
  // The record of a wall impact as it starts: who, where, how fast and the analytic loss
  // 1/2 m (1 - e^2) u^2 (n: the wall normal into free space, v the unit's velocity before).
  static Impact wallImpactRecord(double t, int body, int wall, double n, double v, double u,
                                 double m, const ImpactDecision& d);
  void pairImpact(int slot, double t);
  // Cold paths (line_contacts.cpp).
  [[gnu::noinline]] void specialWallImpact(bool left, double t, double u, double a_push,
                                           const ImpactDecision& d);
  [[gnu::noinline]] void specialPairImpact(int slot, double t, double u, const ImpactDecision& d);
  void merge(int slot, double t, double u, const ImpactDecision& d);
  [[gnu::noinline]] void record(const Impact& impact);
  [[gnu::noinline]] void warnCollapse(double t, const ImpactDecision& d);
  [[gnu::noinline]] void warnSuperElasticCap(double t, const ImpactDecision& d);
  [[gnu::noinline]] void stopForRate() {
    out_.warn({WarningKind::kCollisionRateCap, state_.collision_count - 1, state_.time_s,
               rate_guard_.message(state_.collision_count, state_.time_s)});
  }
  // The checks a fast run (two bodies, wall pair) makes before an impact at t, in the general
  // loop's order: the rate guard (the run is stored first, as the general loop would have it)
  // and a stall of impacts at one instant. Empty when the impact goes ahead, with the run's clock
  // moved to t.
  template <class FastRun>
  std::optional<RunStop> fastRunStopsAt(FastRun& run, double t) {
    if (rate_guard_.exceeded(run.count, t)) {
      run.store();
      stopForRate();
      return RunStop::kRateCap;
    }
    if (t == run.now) {
      if (++run.same_time > kLineStallEventCount) return RunStop::kStalled;
    } else {
      run.same_time = 0;
    }
    run.now = t;
    return std::nullopt;
  }
  void fileSoftContact(SoftOutcome& soft, int body_a, int body_b, double t);
  void finish(double lost, const ImpactDecision& d, double t) {
    state_.book(lost);
    if (d.collapse && !d.resting && !state_.collapse_warned) warnCollapse(t, d);
    if (d.capped && !state_.super_elastic_warned) warnSuperElasticCap(t, d);
    ++state_.collision_count;
  }

  const Model& model_;
  EngineState state_;
  Recorder out_;
  bool accelerated_ = false;              // gravity along the line: motion is parabolic
  bool soft_ = false;                     // ContactModel::kSpringDamper
  bool two_bodies_ = false;               // twoBodyFastPathApplies() (set by rebuild)
  bool wall_pair_ = false;                // wallPairApplies() (set by rebuild)
  bool friction_ = false;                 // Model::has_friction
  bool drag_ = false;                     // Model::has_drag
  std::vector<int> body_order_;           // bodies left to right; fixed for the whole run
  std::vector<int> rank_;                 // body -> position in body_order_
  int left_wall_ = -1, right_wall_ = -1;  // innermost walls; -1: none
  double left_x_ = 0.0, right_x_ = 0.0;   // their positions, m
  // Per unit id (rebuilt on merges and attachment):
  std::vector<int> order_;                   // alive units left to right
  std::vector<double> left_m_, right_m_;     // faces relative to the centre of mass
  std::vector<int> first_body_, last_body_;  // bodies carrying those faces
  std::vector<double> inverse_mass_;         // 0 when attached
  // With friction: the unit's kinetic and static friction as decelerations, m/s^2 (mass-weighted
  // over its bodies: sum mu_i m_i g_n / sum m_i).
  std::vector<double> kinetic_decel_, static_decel_;
  // Per slot: 0 = left wall, j in [1, units) = gap between order_[j-1] and order_[j],
  // units = right wall.
  std::vector<double> slot_mass_;  // reduced mass of the pair
  std::vector<double> slot_time_;
  std::vector<int> tree_;
  int leaves_ = 1;
  std::int64_t same_time_events_ = 0;
  CollisionRateGuard rate_guard_;
  std::vector<int> due_;        // scratch: slots of the current round, ascending
  struct Contact {              // scratch for groupImpact, one per slot of the group
    int left = -1, right = -1;  // units; -1: a wall
    int body_a = 0, body_b = 0;
    double v_left = 0.0, v_right = 0.0, closing = 0.0, impulse = 0.0;
    ImpactDecision decision;
  };
  std::vector<Contact> contacts_;
  std::vector<double> diagonal_, upper_, rhs_;
};

}  // namespace collide::physics::detail
