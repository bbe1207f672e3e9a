#pragma once
// Plain definition structs: what the simulation is asked to run. Every field has a default and a
// unit. Validation of user input happens in scene/; physics asserts only on programmer mistakes.
#include <cstdint>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace collide::physics {

enum class Shape {
  kBlock,  // 1D: a block sliding on the x axis; size_m is its full width
  kDisk,   // 2D: a smooth disk in the plane; size_m is its radius
};

struct BodyDef {
  std::string name;  // shown in labels and data files
  Shape shape = Shape::kBlock;
  double mass_kg = 1.0;                  // > 0
  double size_m = 0.5;                   // block width or disk radius, > 0
  core::Vec2 position_m = {0.0, 0.0};    // centre; y is ignored in 1D
  core::Vec2 velocity_mps = {0.0, 0.0};  // y is ignored in 1D
  // 2D only: the body hangs from the fixed point pivot_m on a massless, inextensible string as
  // long as the distance from the pivot to position_m (> 0); see physics/string_engine.hpp.
  bool on_string = false;
  core::Vec2 pivot_m = {0.0, 0.0};
  // Sliding friction with the surface the body slides on (a track, a table), pressed onto it by
  // WorldDef::surface_gravity_mps2: kinetic mu while it slides, static mu (>= friction) while it
  // rests. 0: frictionless (the default).
  double friction = 0.0;
  double static_friction = 0.0;
  // Air drag: linear, F = -k v (k in kg/s), and quadratic, F = -c |v| v (c in kg/m; 1D, and only
  // without gravity along the line). 0: none (the default). See physics/drag_motion.hpp.
  double drag_linear_kgps = 0.0;
  double drag_quadratic_kgpm = 0.0;
  // Rolling balls (WorldDef::rolling): the coefficient of rolling resistance with the cloth (the
  // kinetic `friction` is the cloth's sliding one) and the spin about the table's x and y axes at
  // t = 0, rad/s (a ball rolling at v: (-v_y, v_x) / R).
  double rolling_friction = 0.0;
  core::Vec2 spin_radps = {0.0, 0.0};
};

// An infinitely massive wall: the half-plane behind `point_m` opposite to `normal`. In 1D only the
// sign of normal.x matters (+1: a wall on the left of the bodies, -1: on the right).
struct WallDef {
  std::string name;                 // reported as the partner in collision events
  core::Vec2 point_m = {0.0, 0.0};  // any point on the wall
  core::Vec2 normal = {1.0, 0.0};   // unit normal pointing into the free space
  double restitution = 1.0;         // e for impacts on this wall, in [0, 1] (above 1: see
                                    // WorldDef::restitution)
};

// e for one pair of bodies, overriding WorldDef::restitution. Order of a and b does not matter.
struct PairRestitution {
  int body_a = 0;            // index into WorldDef::bodies
  int body_b = 1;            // index into WorldDef::bodies
  double restitution = 1.0;  // in [0, 1] (above 1: see WorldDef::restitution)
};

// Stored energy (a compressed spring, a charge) released at a stated time between two bodies that
// touch: they are pushed apart along the line, momentum conserved, and the kinetic energy of their
// relative motion grows by energy_J (1/2 mu (s'^2 - s^2) = energy_J, s the rate at which they
// separate). 1D only: body_a is on the left of body_b. Exactly one of energy_J and
// separation_speed_mps is above 0; a stated speed adds to s (the impulse is mu times it).
struct ReleaseDef {
  int body_a = 0;                     // index into WorldDef::bodies, the left one
  int body_b = 1;                     // index into WorldDef::bodies, the right one
  double time_s = 0.0;                // when the energy is released, >= 0
  double energy_J = 0.0;              // released energy Q, J, >= 0
  double separation_speed_mps = 0.0;  // or: the separation speed it adds, m/s, >= 0
};

// How the e of a pair or wall (e0 below) turns into the e applied at an impact of normal speed u.
enum class RestitutionLaw {
  kConstant,        // e = e0 at every speed
  kSpeedThreshold,  // e = e0 for u <= threshold_speed_mps, e0 * (threshold / u)^exponent above:
                    // once the impact yields the material, e falls as a power of the speed
                    // (Johnson, Contact Mechanics, 1985: exponent 1/4 for elastic-plastic metals)
  kTable,           // e read from `table` by linear interpolation in u, clamped at both ends;
                    // e0 is ignored
};

struct RestitutionPoint {
  double speed_mps = 0.0;    // normal impact speed, >= 0
  double restitution = 1.0;  // e at that speed, in [0, 1]
};

struct RestitutionModel {
  RestitutionLaw law = RestitutionLaw::kConstant;
  double threshold_speed_mps = 1.0;     // kSpeedThreshold: yield speed, > 0
  double exponent = 0.25;               // kSpeedThreshold: fall-off power, >= 0
  std::vector<RestitutionPoint> table;  // kTable: at least one point, speeds strictly increasing
};

enum class ContactModel {
  kImpulse,       // rigid bodies: instantaneous impulse at the time of impact (default)
  kSpringDamper,  // linear spring and dashpot during a finite contact; see soft_contact.hpp
};

// What a perfectly inelastic (e = 0) impact of two disks does in 2D. In 1D bodies always merge.
enum class InelasticMode {
  kSlip,   // normal velocity components equalize; the disks slide on (default)
  kStick,  // the disks join into one rigid cluster that translates and rotates about its centre
           // of mass, conserving linear and angular momentum
};

struct WorldDef {
  int dimensions = 1;  // 1: blocks on a line, 2: disks in a plane
  std::vector<BodyDef> bodies;
  std::vector<WallDef> walls;
  core::Vec2 gravity_mps2 = {0.0, 0.0};  // uniform acceleration (1D: only x is used)
  // Default e for every body pair, in [0, 1]; above 1 (a super-elastic impact: the impact releases
  // 1/2 m_eff (e^2 - 1) u^2 of stored energy, booked as released) where the scene opted in.
  double restitution = 1.0;
  double duration_s = 1.0;  // simulated time span, > 0

  std::vector<PairRestitution> pair_restitution;  // per-pair e; later entries win; default none
  RestitutionModel restitution_model;             // speed dependence of e; default constant
  ContactModel contact_model = ContactModel::kImpulse;
  double contact_duration_s = 0.01;  // kSpringDamper: duration of one contact, > 0
  InelasticMode inelastic_mode = InelasticMode::kSlip;  // 2D only
  std::vector<ReleaseDef> releases;                     // 1D only; in order of time
  // e of a string snapping taut (0: the radial velocity is removed, the usual string), in [0, 1].
  double string_restitution = 0.0;
  // The acceleration pressing the bodies onto the surface they slide on, m/s^2, > 0: the normal
  // force of sliding friction is m times this (a level track on Earth: 9.81; on a slope of angle
  // theta, 9.81 cos theta with gravity_mps2 the part along it). Used only where a body has
  // friction.
  double surface_gravity_mps2 = 9.81;
  // Rolling balls (2D, a level table): every disk is a solid ball of its radius that slides on
  // the cloth with its `friction` until it rolls, then rolls with its `rolling_friction`
  // (physics/rolling_law.hpp). Impacts act along the normal only and keep the spins.
  bool rolling = false;
  // Molecules with insides (2D): each disk carries internal energy in this many internal degrees
  // of freedom (0: none, 1 or 2), starting at 0, and every impact of two free disks shares the
  // pair's relative translational energy and internal energies anew by the Borgnakke-Larsen
  // model (physics/internal_energy.hpp), drawn from a generator seeded with internal_seed. Such
  // impacts conserve energy and momentum; pair restitution does not apply to them.
  int internal_dof = 0;
  std::uint64_t internal_seed = 0x9E3779B97F4A7C15ull;

  // Inelastic collapse guard (docs/physics.md). An impact with e < 1 between two bodies that are
  // both deep in a burst (1000 or more impacts, each within 1e-9 of the scene's own time scale of
  // the one before; for walls: the body alone) is made perfectly inelastic: an accumulation of
  // impacts without end. A wall impact whose rebound would fly for less than collapse_time_s
  // under gravity ends with the body resting on the wall. 0 disables both rules.
  double collapse_time_s = 1e-9;  // s, >= 0

  // Hard limits that keep every run finite and memory bounded.
  // pi-blocks with 9 digits needs 314,159,265; the run stops here with a warning.
  std::int64_t max_collisions = 400'000'000;
  // Optional: the run also stops, with a warning, once more than this many collisions fall
  // within one simulated second. Units: collisions per simulated second; <= 0 (the default)
  // disables it. A fixed rate cuts off legitimate dense processes (pi-blocks with 9 digits has
  // 100 million collisions in well under a second); accumulations of impacts are the collapse
  // guard's job, which looks at what happens (a burst of impacts without end), not at a rate.
  std::int64_t max_collisions_per_second = 0;
  std::int64_t max_recorded_collisions = 100'000;  // kept in Timeline::collisions(); later ones
                                                   // are counted exactly and can be replayed
  std::int64_t max_keyframe_bytes = 64 << 20;      // memory for exact-sampling checkpoints, bytes
};

// Whether a body slides with friction on the surface: the books then gain what went into the
// surface (energy as heat, momentum as the surface's impulse).
inline bool hasFriction(const WorldDef& world) {
  if (world.rolling) return true;  // the cloth
  for (const BodyDef& body : world.bodies) {
    if (body.friction > 0.0 || body.static_friction > 0.0) return true;
  }
  return false;
}

// Whether a body feels air drag: its motion between events is then drag's closed form and the
// books gain what went to the air.
inline bool hasDrag(const WorldDef& world) {
  for (const BodyDef& body : world.bodies) {
    if (body.drag_linear_kgps > 0.0 || body.drag_quadratic_kgpm > 0.0) return true;
  }
  return false;
}

// Whether energy can come in: a release, or an e above 1 for a pair or a wall (or under a law
// that scales one). Reports then book what was released beside what was lost.
inline bool canReleaseEnergy(const WorldDef& world) {
  if (!world.releases.empty() || world.restitution > 1.0) return true;
  for (const WallDef& wall : world.walls) {
    if (wall.restitution > 1.0) return true;
  }
  for (const PairRestitution& pair : world.pair_restitution) {
    if (pair.restitution > 1.0) return true;
  }
  for (const RestitutionPoint& point : world.restitution_model.table) {
    if (point.restitution > 1.0) return true;
  }
  return false;
}

}  // namespace collide::physics
