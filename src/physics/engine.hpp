#pragma once
// Internal: the state an event-driven engine carries between events, the precomputed model of a
// world, and the interface shared by the 1D (line) and 2D (plane) engines. Not part of the public
// API; the Timeline keeps copies of EngineState as checkpoints and re-simulates from them.
//
// Determinism rests on one rule: every predicted event time is a pure function of the current
// states of the bodies involved (never of the time the prediction was made), and events are
// ordered by a total key. Rebuilding the predictions from a checkpoint therefore replays the
// original run bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/vec.hpp"
#include "physics/swing_state.hpp"
#include "physics/timeline.hpp"
#include "physics/world.hpp"

namespace collide::physics::detail {

// Trajectory of a unit's centre of mass during a soft contact, sampled by the integrator.
struct Track {
  std::vector<double> time_s;
  std::vector<core::Vec2> position_m, velocity_mps;
};

// A rigid group of bodies moving together: one body, a 1D composite, a 2D stuck cluster.
// Motion between events: x(t) = x_ref + v (t - t_ref) + a (t - t_ref)^2 / 2, angle likewise
// linear in time.
struct UnitState {
  double t_ref_s = 0.0;             // time at which x_ref, v, angle_ref hold
  core::Vec2 x_ref_m = {0.0, 0.0};  // centre of mass
  core::Vec2 v_mps = {0.0, 0.0};    // centre-of-mass velocity
  core::Vec2 a_mps2 = {0.0, 0.0};   // gravity, less what resting contacts take; 0 if attached
  // Of a_mps2, what sliding friction adds (against v while the unit slides; static friction
  // holding it at rest: minus gravity), so that its work and impulse can be booked.
  core::Vec2 friction_mps2 = {0.0, 0.0};
  // Air drag over the unit's mass (drag_motion.hpp): linear, k/m in 1/s, and quadratic, c/m in
  // 1/m. With either above 0 the motion between events is drag's closed form, not the parabola.
  double drag_rate_per_s = 0.0;
  double drag_per_m = 0.0;
  // Rolling balls (rolling_law.hpp): the spin about the table's x and y axes at t_ref and its
  // constant rate, whether the ball rolls (else its contact point slips on the cloth), and the
  // cloth's power per kg at t_ref and its constant rate (its work over a piece of motion is
  // m (p dt + p' dt^2 / 2)).
  core::Vec2 spin_radps = {0.0, 0.0};
  core::Vec2 spin_rate_radps2 = {0.0, 0.0};
  bool rolls = false;
  double cloth_power_Wpkg = 0.0, cloth_power_rate_Wpkgps = 0.0;
  double angle_ref_rad = 0.0;  // rotation of the unit frame since it formed
  double omega_radps = 0.0;
  double mass_kg = 0.0;
  double inertia_kgm2 = 0.0;           // about the centre of mass, including the disks' spin
  bool alive = true;                   // false once merged into another unit
  bool attached = false;               // 1D: fixed to a wall; infinite mass, never moves
  std::uint32_t resting_walls = 0;     // 2D: bit k set while sliding on wall k (k < 32)
  std::shared_ptr<const Track> track;  // for t < t_ref: soft contact in progress
};

struct BodyLink {
  int unit = 0;
  core::Vec2 offset_m = {0.0, 0.0};  // from the unit's centre of mass, in the unit frame
  double angle_offset_rad = 0.0;     // body angle = unit angle + this
};

// A running sum of energy booked as lost, with Neumaier's compensation (Neumaier, ZAMM 54, 1974):
// millions of small losses beside a large running total keep their digits.
struct EnergyLedger {
  double sum_J = 0.0;
  double compensation_J = 0.0;  // the low-order part that sum_J could not hold

  void add(double loss_J) {
    const double next = sum_J + loss_J;
    compensation_J +=
        std::abs(sum_J) >= std::abs(loss_J) ? (sum_J - next) + loss_J : (loss_J - next) + sum_J;
    sum_J = next;
  }
  double total_J() const { return sum_J + compensation_J; }
};

struct EngineState {
  double time_s = 0.0;  // time of the last processed event
  std::int64_t collision_count = 0;
  // What the impacts so far dissipated, each booked at its analytic value (1/2 m_eff (1 - e^2)
  // u_n^2; merges from conservation of momentum; soft contacts their integrated loss), never
  // as a difference of kinetic energies, which cancels catastrophically at extreme mass ratios.
  EnergyLedger energy_lost;
  // Stored energy turned into motion (releases, super-elastic impacts), booked likewise, so
  // that neither ledger ever holds a negative entry.
  EnergyLedger energy_released;
  // What sliding friction took (friction.cpp): its work, booked per piece of motion as
  // m |f| times the distance slid, and its impulse on the bodies (the surface takes the opposite).
  EnergyLedger energy_to_surface;
  EnergyLedger friction_impulse_x, friction_impulse_y;
  // What air drag took (drag_motion.cpp): its work, booked per piece of motion.
  EnergyLedger energy_to_air;
  std::size_t releases_done = 0;      // WorldDef::releases before this one have acted
  std::int64_t releases_applied = 0;  // of them, those that pushed (the rest found no contact)
  std::vector<UnitState> units;
  std::vector<BodyLink> bodies;
  std::vector<double> last_impact_s;  // per body, for the collapse rule; -inf before any
  // Per body: impacts in its current burst, a run of impacts each within Model::collapse_window_s
  // of the one before (the collapse guard looks at this).
  std::vector<std::int32_t> burst_impacts;
  bool collapse_warned = false;
  bool super_elastic_warned = false;  // the speed cap's warning was given
  // Per body, for the clustering guard (2D): impacts at a restitution below 1 since
  // cluster_start_s, a window of the scene's own time scale.
  std::vector<std::int32_t> cluster_impacts;
  std::vector<double> cluster_start_s;
  // Worlds with strings (string_engine.cpp): how each unit hangs, and the count of events that
  // are no collisions (a string going slack or snapping taut; with friction, a sliding body
  // stopping), so that sampling knows when a checkpoint's motion no longer holds. Empty and 0
  // elsewhere.
  std::vector<SwingState> swings;
  std::int64_t string_events = 0;
  // Molecules with insides (WorldDef::internal_dof > 0): each body's internal energy, J, and the
  // state of the generator the exchanges draw from (a checkpoint carries both, so a replay draws
  // the same numbers). Empty and 0 elsewhere.
  std::vector<double> internal_J;
  std::uint64_t internal_rng = 0;

  // Books an impact's change of kinetic energy, 1/2 m_eff (1 - e^2) u^2 with its sign: a loss
  // (e <= 1) in energy_lost, a gain (e > 1) as released.
  void book(double loss_J) {
    if (loss_J >= 0.0) {
      energy_lost.add(loss_J);
    } else {
      energy_released.add(-loss_J);
    }
  }

  // The body's burst count if it had an impact at t_s.
  std::int32_t burstAt(int body, double t_s, double window_s) const {
    return t_s - last_impact_s[body] <= window_s ? burst_impacts[body] + 1 : 1;
  }
  void noteImpact(int body, double t_s, double window_s) {
    burst_impacts[body] = burstAt(body, t_s, window_s);
    last_impact_s[body] = t_s;
  }
  // Counts an impact of `body` at a restitution below 1 at t_s; returns the impacts in its window.
  std::int32_t noteInelasticImpact(int body, double t_s, double window_s) {
    if (!(t_s - cluster_start_s[body] <= window_s)) {
      cluster_start_s[body] = t_s;
      cluster_impacts[body] = 0;
    }
    return ++cluster_impacts[body];
  }
};

// The world plus tables derived from it once.
struct Model {
  explicit Model(WorldDef world);

  WorldDef world;
  std::vector<double> half_size_m;        // per body: half width (1D) or radius (2D)
  std::vector<double> spin_inertia_kgm2;  // per body about its own centre (disk: m r^2 / 2)
  // Per body, rolling balls: about a horizontal axis through its centre (2/5 m r^2); 0 elsewhere.
  std::vector<double> ball_inertia_kgm2;
  // The scene's own time scale: the smallest body size over the largest speed it can reach
  // (initial speeds, and the speed gravity gives over the scene's extent), s; infinite for a
  // scene where nothing moves.
  double time_scale_s = 0.0;
  // Impacts of a body closer together than this (1e-9 of the time scale) belong to one burst;
  // 0 when WorldDef::collapse_time_s = 0 disables the collapse guard.
  double collapse_window_s = 0.0;
  // The largest speed the scene starts with or gravity gives over its extent, m/s: closing
  // speeds kTieUlps epsilons of this (or of the partners' own speeds) are round-off.
  double speed_scale_mps = 0.0;
  bool has_strings = false;   // a body hangs on a string: the string engine runs the world
  bool has_friction = false;  // hasFriction(world): the engines book sliding friction
  bool has_drag = false;      // hasDrag(world): the engines move units by drag's closed forms

  // A closing speed the partners' velocities cannot resolve: a few units of rounding of the
  // larger of their speeds and the scene's speed scale. An impact at it changes nothing that
  // doubles can hold; a touching pair closing at it is at rest relative to each other.
  bool closingIsRoundOff(double closing_mps, double va_mps, double vb_mps) const;

  // e0 of a body pair.
  double pairRestitution(int a, int b) const {
    return pair_e_.empty() ? world.restitution : pairOverride(a, b);
  }
  // e applied at an impact of normal speed u_mps, for base value e0 (the pair's or the wall's).
  double applyLaw(double e0, double u_mps) const {
    return world.restitution_model.law == RestitutionLaw::kConstant ? e0 : lawOf(e0, u_mps);
  }

 private:
  double pairOverride(int a, int b) const;
  double lawOf(double e0, double u_mps) const;

  std::unordered_map<std::uint64_t, double> pair_e_;
};

EngineState initialState(const Model& model);

// Sliding friction's part of a unit's acceleration along a line, from its velocity v, gravity g
// along the line, and its kinetic and static friction as decelerations k <= s: against v while
// it slides; at rest, -g where static friction holds it, else against g (it slides off).
inline double frictionAlongLine(double v, double g, double k, double s) {
  if (v != 0.0) return v > 0.0 ? -k : k;
  if (std::abs(g) <= s) return -g;
  return g > 0.0 ? -k : k;
}

// Sliding friction's acceleration in a level plane, from the velocity v and the kinetic
// friction as a deceleration k: k against v while the unit slides, none at rest.
inline core::Vec2 frictionInPlane(const core::Vec2& v, double k) {
  const double speed = v.norm();
  if (speed == 0.0) return core::Vec2::Zero();
  return (-k / speed) * v;
}

// Exact state of every body at t_s >= state.time_s (or inside a soft-contact track).
Snapshot evaluate(const Model& model, const EngineState& state, double t_s);
BodyState evaluateBody(const Model& model, const EngineState& state, int body, double t_s);

// An event's signed loss (1/2 m_eff (1 - e^2) u^2, negative for e > 1) split as EngineState::book
// splits it: a gain goes to energy_released_J, so energy_lost_J is never negative.
inline void splitGain(CollisionEvent& event) {
  if (event.energy_lost_J < 0.0) {
    event.energy_released_J += -event.energy_lost_J;
    event.energy_lost_J = 0.0;
  }
  event.energy_lost_analytic_J = std::max(event.energy_lost_analytic_J, 0.0);
}

// Where an engine sends what it finds.
struct Recorder {
  std::vector<CollisionEvent>* events = nullptr;  // filled up to event_limit
  std::int64_t event_limit = 0;
  std::vector<SoftContact>* soft_contacts = nullptr;  // filled up to event_limit
  std::vector<Warning>* warnings = nullptr;           // null while re-simulating
  const std::function<void(const CollisionEvent&)>* stream = nullptr;
  const std::function<void(const StringEvent&)>* string_stream = nullptr;  // replays only

  bool wants(std::int64_t index) const {
    return stream != nullptr || (events != nullptr && index < event_limit);
  }
  void emit(const CollisionEvent& event) const {
    if (events != nullptr && event.index < event_limit) events->push_back(event);
    if (stream != nullptr) (*stream)(event);
  }
  void emitString(const StringEvent& event) const {
    if (string_stream != nullptr) (*string_stream)(event);
  }
  void fileSoft(const SoftContact& contact) const {
    if (soft_contacts != nullptr && contact.collision_index < event_limit) {
      soft_contacts->push_back(contact);
    }
  }
  void warn(Warning warning) const {
    if (warnings != nullptr) warnings->push_back(std::move(warning));
  }
};

enum class RunStop {
  kCountLimit,    // collision_count reached the requested limit
  kDone,          // no event left at or before t_end
  kCollisionCap,  // WorldDef::max_collisions reached
  kStalled,       // too many events at one instant
  kRateCap,       // WorldDef::max_collisions_per_second exceeded; the engine filed the warning
};

class Engine {
 public:
  virtual ~Engine() = default;
  // Processes events in time order while their time <= t_end_s and collision_count < count_limit.
  virtual RunStop run(double t_end_s, std::int64_t count_limit) = 0;
  virtual const EngineState& state() const = 0;
};

std::unique_ptr<Engine> makeLineEngine(const Model& model, EngineState start, const Recorder& out);
std::unique_ptr<Engine> makePlaneEngine(const Model& model, EngineState start, const Recorder& out);
// Worlds with strings: how each body hangs at t = 0 (string_engine.cpp).
std::vector<SwingState> initialSwings(const Model& model);
std::unique_ptr<Engine> makeStringEngine(const Model& model, EngineState start,
                                         const Recorder& out);
std::unique_ptr<Engine> makeEngine(const Model& model, EngineState start, const Recorder& out);

// Impacts predicted within this many units of rounding of each other (relative to their time) are
// one instant: resolved together as one round, never in an order set by body numbering.
inline constexpr double kTieUlps = 4.0;

// Events at one identical time beyond this count mean the run cannot progress.
inline constexpr std::int64_t kStallEventCount = 100000;
// The 1D engine allows far more: pi-blocks with 9 digits packs tens of millions of impacts into
// times closer than the rounding of t (about 5e-16 s apart near t = 4 s), so that t stops
// advancing while the velocities go on changing exactly as they should. An endless run at one
// instant ends here at the latest (seconds), or earlier at max_collisions or a stop request.
inline constexpr std::int64_t kLineStallEventCount = 400'000'000;

}  // namespace collide::physics::detail
