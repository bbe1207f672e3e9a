#pragma once
// Soft contact (ContactModel::kSpringDamper): during a contact the surfaces overlap by s >= 0 and
// a linear spring and dashpot push them apart with F = k s + c ds/dt. The relative normal motion
//     m_eff s'' = -(k s + c s') + m_eff a_push,    s(0) = 0,  s'(0) = u  (closing speed)
// is a damped oscillator. Without a_push the contact lasts half a damped period, T = pi / w_d, and
// ends with s'(T) = -e u where e = exp(-zeta pi / sqrt(1 - zeta^2)). Inverting these gives k and
// c from the requested e and T; the contact is then integrated (RK4, a step of T / 400) rather
// than taken from the closed form, so gravity pushing into a wall is handled as well.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "physics/engine.hpp"
#include "physics/timeline.hpp"

namespace collide::physics::detail {

struct SpringDamper {
  double stiffness_Npm = 0.0;  // k
  double damping_Nspm = 0.0;   // c
};

// k and c for an effective mass m_eff_kg, restitution e in (0, 1] and contact duration_s.
SpringDamper springDamperFor(double m_eff_kg, double e, double duration_s);

struct SoftContactPath {
  bool separated = false;                // false: still in contact after the step budget
  double duration_s = 0.0;               // until s returned to 0
  double separation_speed_mps = 0.0;     // -s' at the end, > 0 when the surfaces part
  std::vector<double> time_s;            // from the start of the contact
  std::vector<double> overlap_m;         // s
  std::vector<double> overlap_rate_mps;  // s'
  std::vector<double> force_N;           // k s + c s' (may turn slightly tensile at the end)
};

// Integrates one contact. a_push_mps2 is the relative normal acceleration pressing the surfaces
// together from outside (gravity towards a wall), 0 between two free bodies.
SoftContactPath integrateSoftContact(double m_eff_kg, double closing_speed_mps, double a_push_mps2,
                                     const SpringDamper& law, double duration_s);

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
