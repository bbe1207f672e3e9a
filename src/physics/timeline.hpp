#pragma once
// The result of a simulation: piecewise-analytic trajectories that can be sampled exactly at any
// time, and the ordered log of collisions.
//
// Memory stays bounded however many collisions happen (pi-blocks with 8 digits has 31 million):
// the first WorldDef::max_recorded_collisions events are stored, the rest are counted exactly and
// can be streamed again with replayCollisions(); exact sampling uses checkpoints of the engine
// state and re-simulates deterministically from the nearest one when events lie in between.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "physics/world.hpp"

namespace collide::physics {

namespace detail {
struct TimelineData;
}

struct BodyState {
  core::Vec2 position_m = {0.0, 0.0};
  core::Vec2 velocity_mps = {0.0, 0.0};
  double angle_rad = 0.0;               // rotation since t = 0 (only stuck 2D clusters rotate)
  double angular_velocity_radps = 0.0;  // counter-clockwise positive
  // Rolling balls: the spin about the table's x and y axes, rad/s (its energy is
  // 1/2 (2/5 m r^2) |spin|^2); zero elsewhere.
  core::Vec2 spin_radps = {0.0, 0.0};
};

// Partner index used in CollisionEvent::body_b for wall k: kWallPartnerBase - k (always negative).
inline constexpr int kWallPartnerBase = -1;

struct CollisionEvent {
  std::int64_t index = 0;              // 0-based position in the event log
  double time_s = 0.0;                 // impact time (soft contact: when it began)
  int body_a = 0;                      // index into WorldDef::bodies
  int body_b = 0;                      // body index, or kWallPartnerBase - wall index
  double restitution = 1.0;            // e applied at this impact
  double restitution_requested = 1.0;  // e from the pair/wall and the restitution law,
                                       // before the collapse rule (TC model) overrode it
  core::Vec2 normal = {1.0, 0.0};      // unit contact normal, from a towards b
  core::Vec2 velocity_a_before_mps = {0.0, 0.0}, velocity_a_after_mps = {0.0, 0.0};
  core::Vec2 velocity_b_before_mps = {0.0, 0.0}, velocity_b_after_mps = {0.0, 0.0};  // walls: 0
  double closing_speed_mps = 0.0;       // normal approach speed before impact, >= 0
  double impulse_Ns = 0.0;              // normal impulse magnitude on each partner
  double energy_lost_J = 0.0;           // booked in the ledger: the analytic value below, for a
                                        // soft contact its integrated loss, for a disk settling
                                        // on a wall (spin stopped) its kinetic energy change
  double energy_lost_analytic_J = 0.0;  // 1/2 m_eff (1 - e^2) u_n^2 (point masses:
                                        // m_eff = mu; walls: m_eff = m); merges: from
                                        // conservation of momentum (and angular momentum);
                                        // 0 where energy was released (e > 1, a release)
  // Stored energy turned into kinetic energy, booked in its own ledger (never as a negative
  // loss): a super-elastic impact's 1/2 m_eff (e^2 - 1) u_n^2, a release's Q. >= 0.
  double energy_released_J = 0.0;
  bool release = false;             // a ReleaseDef pushed the partners apart (no impact:
                                    // closing speed 0, e as the scene's, normal a to b)
  bool merged = false;              // the partners joined (1D composite, 2D cluster) or
                                    // the body came to rest on the wall
  bool collapse_rule = false;       // the TC collapse rule made this impact inelastic
  double contact_duration_s = 0.0;  // soft contact: how long it lasted; impulse: 0

  bool hitsWall() const { return body_b < 0; }
  int wallIndex() const { return kWallPartnerBase - body_b; }  // only when hitsWall()
};

// A string going slack or snapping taut (worlds with strings): no collision, so it is not in the
// collision log or count; Timeline::replayEvents streams it in its place among the collisions.
struct StringEvent {
  double time_s = 0.0;
  int body = 0;       // index into WorldDef::bodies: the body on the string (bodies it carries
                      // after a merge move with it)
  bool taut = false;  // true: snapped taut (a jerk along the string); false: went slack
  core::Vec2 position_m = {0.0, 0.0};  // the body's, at time_s
  core::Vec2 velocity_before_mps = {0.0, 0.0}, velocity_after_mps = {0.0, 0.0};
  double energy_lost_J = 0.0;  // the jerk's loss, booked in the ledger; 0 going slack
};

// State of every body at one instant.
struct Snapshot {
  double time_s = 0.0;
  std::vector<BodyState> bodies;
  double energy_lost_J = 0.0;      // kinetic energy lost in collisions up to time_s
  double energy_released_J = 0.0;  // stored energy released up to time_s (releases, e > 1)
  // Sliding friction up to time_s: its work, turned into heat in the surface and the bodies,
  // and the momentum the surface took (the bodies' momentum plus it is the start's, but for
  // what walls and gravity give).
  double energy_to_surface_J = 0.0;
  core::Vec2 surface_momentum_kgmps = {0.0, 0.0};
  // Air drag's work up to time_s: what went to the air (0 without drag).
  double energy_to_air_J = 0.0;
  // Molecules with insides (WorldDef::internal_dof > 0): the disks' internal energy at time_s,
  // J; kinetic + internal is the energy at the start. 0 elsewhere.
  double internal_energy_J = 0.0;
  int collision_count = 0;  // collisions at or before time_s (releases included: events)
  int release_count = 0;    // of those, releases (ReleaseDef): no impacts
  int impactCount() const { return collision_count - release_count; }
};

enum class SimulationStatus {
  kComplete,                 // simulated over the whole duration
  kCollisionCapReached,      // stopped at WorldDef::max_collisions; valid up to simulatedUntil_s()
  kStalled,                  // events stopped advancing time (e.g. an unsupported resting stack)
  kCollisionRateCapReached,  // stopped at WorldDef::max_collisions_per_second; valid up to
                             // simulatedUntil_s()
};

enum class WarningKind {
  kCollisionCap,         // the run stopped at the collision cap
  kStalled,              // the run stopped: events piled up at one instant
  kCollisionRateCap,     // the run stopped: more than max_collisions_per_second in one second
  kSoftContactMismatch,  // a soft contact's measured e or energy loss is off by more than 1%
  kCollapseRule,         // the first impact made inelastic by the collapse rule (reported once)
  kEnergyLedger,         // booked losses and the energy measured at both ends disagree
  kPrecision,            // mass or size ratios beyond what double precision resolves
  kSuperElasticCap,      // the first super-elastic impact made elastic by the speed cap (once)
  kReleaseSkipped,       // a release found its bodies apart (or joined) and released nothing
};

struct Warning {
  WarningKind kind = WarningKind::kCollisionCap;
  std::int64_t collision_index = -1;  // the collision it is about, or -1
  double time_s = 0.0;                // s
  std::string message;                // one complete sentence for the user
};

// One sample of the force between two bodies in soft contact.
struct ContactForceSample {
  double time_s = 0.0;
  double force_N = 0.0;           // normal force on body b (on a: the opposite), repulsive positive
  double overlap_m = 0.0;         // spring compression
  double overlap_rate_mps = 0.0;  // its rate (positions between samples follow the cubic
                                  // Hermite curve through overlap and rate)
};

// The record of one soft contact (ContactModel::kSpringDamper): a Hunt-Crossley law
// F = k s^n (1 + lambda ds/dt) that never pulls; see physics/soft_contact.hpp.
struct SoftContact {
  std::int64_t collision_index = 0;   // CollisionEvent::index of the contact
  int body_a = 0, body_b = 0;         // as in CollisionEvent
  double start_s = 0.0, end_s = 0.0;  // contact interval
  double stiffness = 0.0;             // k, N/m^n; the spring stores k s^(n+1) / (n+1)
  double exponent = 1.0;              // n
  double damping_per_mps = 0.0;       // lambda, s/m
  double restitution_requested = 1.0;
  double restitution_measured = 1.0;     // -u_n after / u_n before
  double energy_lost_requested_J = 0.0;  // 1/2 m_eff (1 - e^2) u^2
  double energy_lost_measured_J = 0.0;
  std::vector<ContactForceSample> samples;
};

class Timeline {
 public:
  explicit Timeline(std::shared_ptr<const detail::TimelineData> data);

  const WorldDef& world() const;
  double duration_s() const { return world().duration_s; }

  // The first WorldDef::max_recorded_collisions collisions, in time order.
  const std::vector<CollisionEvent>& collisions() const;
  std::int64_t collisionCount() const;  // exact total
  bool collisionsTruncated() const { return collisionCount() > std::int64_t(collisions().size()); }
  // Calls `visit` for every collision in order, re-simulating past the stored ones (pi-blocks
  // with 8 digits: about a second).
  void replayCollisions(const std::function<void(const CollisionEvent&)>& visit) const;
  // The same, with every string event too, in the order the run met them (time order).
  void replayEvents(const std::function<void(const CollisionEvent&)>& visit,
                    const std::function<void(const StringEvent&)>& visit_string) const;

  // Exact state at time t (clamped to [0, duration]). A time equal to a collision time gives the
  // state after it. After a run that stopped early (a cap or a stall), a time past
  // simulatedUntil_s() gives the last simulated state, held (its time_s is simulatedUntil_s()):
  // later states were never simulated, and carrying the free motion on would move bodies through
  // walls and each other.
  Snapshot sample(double t_s) const;

  double kineticEnergy(const Snapshot& snapshot) const;    // J, translation and disk spin
  double potentialEnergy(const Snapshot& snapshot) const;  // J, -sum m g.x (zero at the origin)
  double mechanicalEnergy(const Snapshot& snapshot) const {
    return kineticEnergy(snapshot) + potentialEnergy(snapshot);
  }
  core::Vec2 momentum(const Snapshot& snapshot) const;  // kg m/s
  // kg m^2/s about `about_m`, orbital plus disk spin; counter-clockwise positive.
  double angularMomentum(const Snapshot& snapshot, core::Vec2 about_m = {0.0, 0.0}) const;
  // The state at t = 0 before any impact, also one due at t = 0 (bodies touching and
  // approaching): the initial conditions as given. sample(0) gives the state after such impacts.
  Snapshot initialState() const;
  double initialKineticEnergy() const;  // J, of initialState()
  // J, all collisions: each impact's loss booked analytically (1/2 m_eff (1 - e^2) u_n^2, merges
  // from conservation of momentum, soft contacts their integrated loss) and summed with
  // compensation. Never negative.
  double totalEnergyLost() const;
  // J, stored energy released into motion (releases, super-elastic impacts), each booked at its
  // analytic value and summed with compensation. Never negative. The books: mechanical energy
  // at the end + lost = at the start + released.
  double totalEnergyReleased() const;
  // J, the work of sliding friction over the run (0 without friction), booked per piece of
  // motion and summed with compensation. The books: mechanical energy at the end + lost +
  // to the surface = at the start + released.
  double totalEnergyToSurface() const;
  // J, the work of air drag over the run (0 without drag), booked likewise. The books: mechanical
  // energy at the end + lost + to the surface + to the air = at the start + released.
  double totalEnergyToAir() const;
  // J, the check on the ledger: mechanical energy at t = 0 less that at the end of the run. It
  // agrees with totalEnergyLost() - totalEnergyReleased() to within energyLedgerTolerance()
  // (round-off scaled to the energies involved and the number of impacts); beyond that the run
  // carries a warning.
  double energyLostMeasured() const;
  double energyLedgerTolerance() const;  // J

  SimulationStatus status() const;
  double simulatedUntil_s() const;  // duration, or where a cap stopped the run
  const std::vector<Warning>& warnings() const;
  const std::vector<SoftContact>& softContacts() const;  // at most max_recorded_collisions

 private:
  std::shared_ptr<const detail::TimelineData> data_;
};

}  // namespace collide::physics
