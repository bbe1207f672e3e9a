#pragma once
// Exact motion of a body hanging from a fixed pivot on a massless, inextensible string: the
// simple pendulum at any amplitude (Jacobi elliptic functions, never the small-angle
// approximation), the instant its string goes slack, the free flight that follows and the jerk
// that ends it. Pure functions of plain structs; the engine turns them into events.
//
// Conventions: x to the right, y up, gravity g > 0 pulls along -y. The angle theta is measured
// from the straight-down position, counterclockwise positive, so the body sits at
// pivot + L (sin theta, -cos theta) and moves with velocity L omega (cos theta, sin theta).
#include <optional>

#include "core/vec.hpp"

namespace collide::physics {

struct PendulumState {
  double angle_rad = 0.0;               // from straight down, counterclockwise positive
  double angular_velocity_rad_s = 0.0;  // d(angle)/dt
};

// How the taut string moves for a given energy (per unit mass, with the pivot as zero height):
// below the pivot's top it swings back and forth, with enough energy it goes round and round,
// exactly at the top's energy it creeps towards the top forever.
enum class PendulumKind { kRest, kLibration, kRotation };

// One stretch of taut-string motion from a start state. The energy parameter
//   h = omega^2 / (4 omega0^2) + sin^2(theta / 2),  omega0 = sqrt(g / L),
// is constant along it: h < 1 libration with modulus k = sqrt(h), h > 1 rotation with modulus
// 1 / sqrt(h), h = 1 the separatrix (handled by the rotation form with modulus 1).
class PendulumArc {
 public:
  // length_m > 0, gravity_m_s2 > 0; the start state is taken as is (angles of any size).
  PendulumArc(double length_m, double gravity_m_s2, PendulumState start);

  // The state t_s seconds after the start (t_s may be negative). The angle is continuous in
  // time: a rotating pendulum's angle grows by 2 pi per turn.
  PendulumState at(double t_s) const;

  PendulumKind kind() const { return kind_; }
  double energyParameter() const { return h_; }
  // Libration: the time of a full swing there and back, 4 K(k) / omega0. Rotation: the time of
  // one full turn, 2 K(1/sqrt(h)) / (sqrt(h) omega0). At rest: the small-swing period.
  // Infinite on the separatrix.
  double period_s() const;
  // Libration: the largest angle reached, 2 asin(k). Rotation: pi.
  double amplitude_rad() const;

  // Tension in the string divided by the body's mass, at a state of this arc: L omega^2 + g cos.
  double tensionPerMass_m_s2(PendulumState state) const;
  // The first time t > 0 at which the tension falls to zero with the body rising (after which the
  // string would have to push), or nothing when the string stays taut for ever. That happens only
  // for 1/2 < h < 5/4, at sin^2(theta / 2) = (4 h + 1) / 6, above the pivot's height.
  std::optional<double> slackTime_s() const;

 private:
  double length_m_;
  double gravity_m_s2_;
  double omega0_rad_s_;
  PendulumState start_;
  PendulumKind kind_ = PendulumKind::kRest;
  double h_ = 0.0;
  double modulus_ = 0.0;    // Jacobi modulus k of the elliptic functions used
  double quarter_ = 0.0;    // K(modulus), infinite for modulus 1
  double phase0_ = 0.0;     // elliptic argument at t = 0
  double direction_ = 1.0;  // rotation: the sign of omega (it never changes)
  double turns0_ = 0.0;     // rotation: whole half-turns of theta/2 removed from the start angle
};

// Position and velocity of the body relative to its pivot on a taut string.
core::Vec2 pendulumPosition_m(double length_m, double angle_rad);
core::Vec2 pendulumVelocity_m_s(double length_m, PendulumState state);
// The state on a taut string of the body at offset r from the pivot moving with velocity v: the
// angle of r and the tangential part of v (a radial part is not representable and is dropped).
PendulumState pendulumStateOf(core::Vec2 offset_m, core::Vec2 velocity_m_s);

// The first time t > 0 at which a body in free flight (offset r0 from the pivot, velocity v0,
// gravity g along -y) is again at distance L from the pivot with its string pulling taut (moving
// outwards), or nothing if that never happens. The body must start inside the circle or on it;
// on the circle it must not be moving outwards. Starting on the circle exactly where a swing went
// slack (no radial velocity and zero tension) the answer has the closed form 4 v0y / g; the
// general case is a quartic whose root is isolated and bracketed, never stepped.
std::optional<double> tautTime_s(double length_m, double gravity_m_s2, core::Vec2 offset_m,
                                 core::Vec2 velocity_m_s);

// The string snapping taut at offset r with velocity v: the radial velocity is reversed and
// scaled by the string's restitution e (0: removed, the usual inextensible string); the
// tangential velocity is kept. The kinetic energy taken, per unit mass, is
// (1 - e^2) v_r^2 / 2.
struct StringJerk {
  core::Vec2 velocity_m_s;
  double energy_lost_per_mass_J_kg = 0.0;
};
StringJerk stringJerk(core::Vec2 offset_m, core::Vec2 velocity_m_s, double restitution);

}  // namespace collide::physics
