#pragma once
// Internal: the 2D engine, disks in a plane. Units are single disks or stuck clusters (rigid,
// rotating about their centre of mass). Events live in a binary heap; each carries the version
// stamps of the units it was predicted from, and a stale one (a unit changed since) is dropped
// when popped. Predictions are pure functions of the current unit states, so rebuilding the heap
// from a checkpoint replays a run exactly. The broad phase's cell crossings, one per disk, wait
// apart in an indexed heap (crossing_queue.hpp) and are taken in the same order of events.
//
// plane_engine.cpp: queue and loop; plane_toi.cpp: times of impact; plane_contacts.cpp: impulses,
// resting on walls, stuck clusters, soft contacts and records.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "physics/crossing_queue.hpp"
#include "physics/drag_motion.hpp"
#include "physics/engine.hpp"
#include "physics/impact_rules.hpp"
#include "physics/rate_guard.hpp"
#include "physics/soft_contact.hpp"

namespace collide::physics::detail {

class PlaneEngine final : public Engine {
 public:
  PlaneEngine(const Model& model, EngineState start, const Recorder& out);
  RunStop run(double t_end_s, std::int64_t count_limit) override;
  const EngineState& state() const override { return state_; }

 private:
  static constexpr int kCrossing = 2;
  static constexpr int kStop = 3;
  struct Event {
    double time_s;
    int kind;  // 0: disk-disk, 1: disk-wall, kCrossing: a disk into a neighbouring grid cell,
               // kStop: a unit sliding with friction comes to rest (b unused)
    int a, b;  // bodies (a < b), body and wall, or body and direction (+x, -x, +y, -y)
    std::uint32_t stamp_a, stamp_b;
  };
  // Heap order: earliest first; ties broken by kind, then bodies: a total order.
  struct Later {
    bool operator()(const Event& x, const Event& y) const {
      if (x.time_s != y.time_s) return x.time_s > y.time_s;
      if (x.kind != y.kind) return x.kind > y.kind;
      if (x.a != y.a) return x.a > y.a;
      return x.b > y.b;
    }
  };

  // Kinematics of a body at time t (its unit advanced analytically).
  struct Kin {
    core::Vec2 x, v;  // disk centre, m and m/s
    core::Vec2 arm;   // from the unit's centre of mass to the disk centre, m
  };
  // Inline for the common case, a disk at its unit's centre (a single disk); the hot path of
  // every prediction.
  Kin kinematics(int body, double t) const {
    const BodyLink& link = state_.bodies[body];
    if (model_.has_drag && hasDrag(state_.units[link.unit])) return draggedKinematics(body, t);
    if (link.offset_m.x() != 0.0 || link.offset_m.y() != 0.0) return clusterKinematics(body, t);
    const UnitState& u = state_.units[link.unit];
    const double dt = t - u.t_ref_s;
    Kin k;
    k.x = u.x_ref_m + u.v_mps * dt + 0.5 * u.a_mps2 * dt * dt;
    k.v = u.v_mps + u.a_mps2 * dt;
    k.arm = core::Vec2::Zero();
    return k;
  }
  Kin clusterKinematics(int body, double t) const;  // a disk off its unit's centre

  // Air drag (plane_drag.cpp): a unit with drag moves by drag's closed forms, its drag's work is
  // booked per piece of motion, and times of impact with it are bracketed to round-off.
  Kin draggedKinematics(int body, double t) const;
  void advanceDragged(UnitState& u, double t);
  double predictDraggedPair(int a, int b, double t0) const;
  double predictDraggedWall(int body, int wall, double t0) const;
  // How hard two touching units are pressed together along n (from a to b), m/s^2: gravity's
  // push, or under drag the difference of their accelerations less what their sliding past each
  // other (the centripetal |dv_t|^2 / d) undoes; 0 where nothing presses them.
  double pairPush(const UnitState& ua, const UnitState& ub, const Kin& ka, const Kin& kb,
                  const core::Vec2& n) const {
    if (!model_.has_drag) return std::max((ua.a_mps2 - ub.a_mps2).dot(n), 0.0);
    return draggedPairPush(ua, ub, ka, kb, n);
  }
  double draggedPairPush(const UnitState& ua, const UnitState& ub, const Kin& ka, const Kin& kb,
                         const core::Vec2& n) const;
  void advanceUnit(int unit, double t);

  // Predictions (plane_toi.cpp).
  double predictPair(int a, int b) const;
  double predictWall(int body, int wall) const;
  double conservativeAdvance(int a, int b_or_wall, bool wall, double t0, double tau_max) const;

  void rebuildQueue();
  // A unit changed at an event: a new stamp (its old predictions go stale) and, with sliding
  // friction, its new law of motion.
  void renew(int unit);
  void predictUnit(int unit, int skip_unit);  // all events of its bodies except with skip_unit
  void push(int kind, int a, int b, double time);
  bool valid(const Event& event) const;
  // The first event in the order of Later, of the heap's valid events (stale ones are dropped on
  // the way) and the crossings; false when there is none. A crossing leaves crossing_queue_
  // through crossCell, anything else the heap through popHeap.
  bool nextEvent(Event& next);
  void popHeap();

  // Responses (plane_contacts.cpp).
  void pairImpact(int a, int b, double t);
  void wallImpact(int body, int wall, double t);
  // The steps of pairImpact. How the two units answer a unit impulse along the normal n (from a
  // to b): the directions their velocities change in (pa, pb: less what walls they rest on
  // block), the levers about their centres of mass (ca, cb) and the effective mass.
  struct PairResponse {
    core::Vec2 pa, pb;
    double ca = 0.0, cb = 0.0;
    std::uint32_t blocked_a = 0, blocked_b = 0;
    double m_eff = 0.0;
  };
  PairResponse pairResponse(const UnitState& ua, const UnitState& ub, const Kin& ka, const Kin& kb,
                            const core::Vec2& n) const;
  // A soft contact of two disks that do not spin: false where resolveSoftContact declines it.
  bool softPairImpact(int a, int b, double t, const core::Vec2& n, double e, CollisionEvent& event);
  void applyPairImpulse(UnitState& ua, UnitState& ub, const PairResponse& r, double impulse) const;
  // Molecules with insides (internal_energy.cpp): the Borgnakke-Larsen exchange of two free
  // disks that neither spin nor rest on walls, in place of the impulse law; false elsewhere.
  bool exchangeWithInsides(int a, int b, const PairResponse& r, const core::Vec2& n,
                           CollisionEvent& event);
  // Stops the run's loop where a disk came to rest on another under gravity.
  void noteRestingOnDisk(int a, int b, const Kin& ka, const Kin& kb, const core::Vec2& n, double e,
                         double a_push);
  // The steps of wallImpact: a unit settling on the wall, a soft contact with it (false where
  // resolveSoftContact declines it), and a rebound's impulse about `lever`.
  void settleOnWall(UnitState& unit, int wall) const;
  bool softWallImpact(int body, int wall, double t, double e, CollisionEvent& event);
  static void applyWallImpulse(UnitState& unit, const core::Vec2& normal, double lever, double e,
                               double u, double m_eff);
  void stick(int a, int b, double t, double u, const ImpactDecision& d, const core::Vec2& n);
  void updateAcceleration(UnitState& unit) const;
  // Per unit impulse along `direction`, the direction the unit's velocity changes in: the
  // direction itself, less the components blocked by walls it rests on (set in `blocked`).
  core::Vec2 responseDirection(const UnitState& unit, double lever, const core::Vec2& direction,
                               std::uint32_t& blocked) const;
  void finish(const CollisionEvent& event, const ImpactDecision& d);
  // The clustering guard: counts an impact of `body` at a restitution below 1 (`d`), and marks
  // the body once it has had kClusterImpacts of them within the scene's time scale.
  void noteClustering(int body, double t, const ImpactDecision& d);

  // Simultaneous impacts (plane_groups.cpp): every event due within rounding of `first` (kTieUlps)
  // is taken from the queue into ties_; true when there is more than one. resolveInstant resolves
  // them in groups that share a unit, simultaneousImpact one such group as one system (false:
  // the group is beyond it and goes pair by pair).
  bool collectTies(const Event& first);
  void resolveInstant(double t);
  bool simultaneousImpact(const std::vector<Event>& members, double t);
  // The steps of simultaneousImpact. One contact of the group, its units advanced to t: bodies
  // (b < 0: kWallPartnerBase - wall), the normal from a towards b (into the wall), its closing
  // speed, restitution and impulse.
  struct GroupContact {
    int a = 0, b = 0;
    core::Vec2 n;
    double closing = 0.0, e = 1.0, impulse = 0.0;
    ImpactDecision decision;
  };
  // Whether a group can be one system: few contacts, rigid ones, between single disks that
  // neither spin nor rest on walls.
  bool oneSystemApplies(const std::vector<Event>& members) const;
  GroupContact groupContact(const Event& e, double t);
  // The Delassus matrix of the contacts (row-major) and the right-hand side (1 + e) c.
  void delassusSystem(const std::vector<GroupContact>& contacts, std::vector<double>& delassus,
                      std::vector<double>& rhs) const;
  // The records of the contacts' impacts as they start (velocities before any impulse).
  std::vector<CollisionEvent> groupRecordsBefore(const std::vector<GroupContact>& contacts,
                                                 double t) const;
  // Applies every contact's impulse and predicts the units it touched again.
  void applyGroupImpulses(const std::vector<GroupContact>& contacts);
  double inverseMassOf(int body) const {
    return 1.0 / state_.units[state_.bodies[body].unit].mass_kg;
  }
  // Sorts a group that goes pair by pair into the order of its contact points (x, then y).
  void orderByPlace(std::vector<Event>& members, double t) const;

  // Sliding friction (plane_friction.cpp). A sliding unit decelerates at k = mu g_n against its
  // velocity, so it moves on a straight line, quadratically in time, until it stops: an event
  // of kind kStop. Friction's work and impulse are booked per piece of motion.
  void setFrictionLaw(int unit);
  double stopTime(int unit) const;
  void pushStop(int unit);
  void stopUnit(int unit, double t);
  void bookSurface(UnitState& unit, double t);  // books a piece of motion up to t
  // Whether the next event due by t_end_s is a stop (stops count no collision, so a run at its
  // collision limit still takes them, as the line engine does).
  bool stopDue(double t_end_s);
  // The time of impact (from t0) of a slowing unit with a wall: the gap s0 + s1 tau + s2 tau^2
  // falls only while the unit moves towards it, up to its stop.
  double slowingWallTime(int unit, double s0, double s1, double s2, double t0) const;
  // Stops the run (a warning) where a stuck cluster would turn under friction.
  bool frictionStalls(double t);

  // Broad phase (plane_grid.cpp): a uniform grid of cells; see there.
  void setUpGrid();
  void dropGrid();
  void fileWallsInCells(double largest_m);
  int cellIndex(double x, double origin, int cells) const;
  // Calls visit(other) for every disk filed in the 3 x 3 cells around the body's (itself too).
  template <typename Visit>
  void forNeighbours(int body, Visit&& visit) const {
    const int cx = body_cell_x_[body], cy = body_cell_y_[body];
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, cells_y_ - 1); ++y) {
      for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, cells_x_ - 1); ++x) {
        for (int other : cell_bodies_[y * cells_x_ + x]) visit(other);
      }
    }
  }
  void predictCrossing(int body);
  void pushPair(int i, int j);        // predicts and queues an impact of two disks
  void pushWall(int body, int wall);  // ... of a disk on a wall
  void pushWalls(int body);           // ... on every wall it can reach from its cell
  void crossCell(const Event& event);
  void fileSoftContact(SoftOutcome& soft, int body_a, int body_b, double t);

  const Model& model_;
  EngineState state_;
  Recorder out_;
  // Per unit: the stamp of its last change. Stamps come from one counter, so a body that moved
  // to another unit can never match an old stamp by coincidence.
  std::vector<std::uint32_t> version_;
  std::uint32_t last_stamp_ = 0;
  std::vector<std::vector<int>> members_;  // per unit: its bodies, ascending
  std::vector<Event> heap_;
  std::vector<Event> ties_;       // scratch: the events of one instant
  std::vector<Event> set_aside_;  // scratch: stops set aside while collecting ties
  CrossingQueue crossing_queue_;  // with the grid: each disk's next cell crossing
  bool grid_ = false;             // the broad phase is on (many single disks)
  bool drop_grid_ = false;        // a stuck cluster formed: back to all pairs after this event
  double cell_m_ = 0.0, origin_x_ = 0.0, origin_y_ = 0.0;
  int cells_x_ = 0, cells_y_ = 0;
  std::vector<std::vector<int>> cell_bodies_;   // per cell (row-major): its disks
  std::vector<int> body_cell_x_, body_cell_y_;  // per body: its cell
  // Per cell: bit k set when a disk centred in the cell can touch wall k; empty when there are
  // more than 32 walls (then every wall is predicted).
  std::vector<std::uint32_t> cell_walls_;
  std::vector<double> crossing_s_;  // per body: its next cell crossing, or kNever
  std::size_t heap_limit_ = 0;      // rebuild the heap when stale entries pile up
  std::int64_t same_time_events_ = 0;
  // A disk came to rest on another disk under gravity (beyond the event model): the upper and
  // the lower body, or -1.
  int resting_upper_ = -1, resting_lower_ = -1;
  bool friction_ = false;              // a body slides with friction (Model::has_friction)
  std::vector<double> kinetic_decel_;  // per unit: mu_k g_n mass-weighted over its bodies, m/s^2
  // A stuck cluster that friction would turn (spinning, or its bodies' friction off its line of
  // motion), which the model does not follow, or -1.
  int turning_cluster_ = -1;
  // A rolling ball that its spin presses onto a cushion it came to rest against (the resting
  // rule), a lasting contact the model does not follow, or -1.
  int pressed_ball_ = -1;
  // The first disk the clustering guard found in an inelastic cluster, or -1.
  int clustered_body_ = -1;
  CollisionRateGuard rate_guard_;
};

}  // namespace collide::physics::detail
