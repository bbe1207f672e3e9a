#pragma once
// Soft contact (ContactModel::kSpringDamper): during a contact the surfaces overlap by s >= 0 and
// a Hunt-Crossley law pushes them apart (Hunt & Crossley, J. Appl. Mech. 42, 1975):
//     F = k s^n (1 + lambda ds/dt),   n = 1 (a linear spring whose damper grows with compression).
// Unlike a linear spring and dashpot (F = k s + c s'), whose force jumps to c u at first touch and
// turns tensile before the surfaces part, this force starts at 0, ends at 0 and never pulls: the
// relative motion m_eff s'' = -F can only approach the rate s' = -1/lambda where F would vanish,
// never cross it. The relative normal motion
//     m_eff s'' = -k s^n (1 + lambda s') + m_eff a_push,    s(0) = 0,  s'(0) = u  (closing speed)
// scales to X'' = -X^n (1 + d X') with d = lambda u: the restitution depends on d alone, so d is
// found by bisection for the requested e on that dimensionless contact, and k from its duration
// so that the contact lasts the requested time. The contact is then integrated (RK4, a step of
// T / 400) rather than taken from a closed form, so gravity pushing into a wall is handled as well.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "physics/engine.hpp"
#include "physics/timeline.hpp"

namespace collide::physics::detail {

struct ContactLaw {
  double stiffness = 0.0;        // k, N/m^n
  double exponent = 1.0;         // n
  double damping_per_mps = 0.0;  // lambda, s/m: F = k s^n (1 + lambda s')
  // The force at overlap s and overlap rate w: never negative.
  double force_N(double s_m, double w_mps) const;
};

// The law for an effective mass m_eff_kg closing at u_mps > 0 with restitution e in (0, 1],
// whose contact lasts duration_s (between free bodies).
ContactLaw huntCrossleyFor(double m_eff_kg, double u_mps, double e, double duration_s);

struct SoftContactPath {
  bool separated = false;                // false: still in contact after the step budget
  double duration_s = 0.0;               // until s returned to 0
  double separation_speed_mps = 0.0;     // -s' at the end, > 0 when the surfaces part
  std::vector<double> time_s;            // from the start of the contact
  std::vector<double> overlap_m;         // s
  std::vector<double> overlap_rate_mps;  // s'
  std::vector<double> force_N;           // the law's force, >= 0
};

// Integrates one contact. a_push_mps2 is the relative normal acceleration pressing the surfaces
// together from outside (gravity towards a wall), 0 between two free bodies.
SoftContactPath integrateSoftContact(double m_eff_kg, double closing_speed_mps, double a_push_mps2,
                                     const ContactLaw& law, double duration_s);

// One side of a soft contact at its start: centre-of-mass state and inverse mass (0: immovable).
struct SoftSide {
  core::Vec2 x_m = {0.0, 0.0}, v_mps = {0.0, 0.0}, a_mps2 = {0.0, 0.0};
  double inverse_mass_per_kg = 0.0;
};

struct SoftOutcome {
  bool resolved = false;  // false: the contact did not end; fall back to an impulse
  double duration_s = 0.0;
  std::shared_ptr<Track> track_a, track_b;    // null for an immovable side
  core::Vec2 x_a_m, v_a_mps, x_b_m, v_b_mps;  // at the end of the contact
  SoftContact record;                         // samples, k, c, measured and requested values
  bool within_tolerance = true;               // measured e and energy loss within 1%
};

// Resolves a contact that starts at t_s with unit normal n (from a to b) and restitution e in
// (0, 1]. Each side follows its free motion (velocity, acceleration) and is pushed back along n by
// its share of the lost approach, in proportion to its inverse mass, so momentum is conserved.
SoftOutcome resolveSoftContact(const SoftSide& a, const SoftSide& b, const core::Vec2& n, double e,
                               double contact_duration_s, double t_s);

// "soft contact N: measured e ... (requested ...), energy lost ... (requested ...)".
std::string softMismatchMessage(const SoftContact& record);

// Files a finished soft contact as collision `index` between bodies a and b (b < 0: a wall) at
// time t_s, with a warning when its measured e or energy loss is off target. Both engines use it.
void fileSoftContact(const Recorder& out, SoftOutcome& soft, std::int64_t index, int body_a,
                     int body_b, double t_s);

}  // namespace collide::physics::detail
