#pragma once
// The impulse of an impact between two partners of which either may hang on a taut string
// (docs/physics.md, "Impacts of hanging bodies"). A string can pull but never push: when the
// contact impulse would stretch it, the string answers with an impulsive tension T >= 0 that
// keeps the body's radial velocity at zero; when the contact pushes the body towards its pivot,
// the string goes slack and takes nothing. The contact obeys Newton's law of restitution along
// the normal (smooth bodies: no tangential impulse). Together these are a linear
// complementarity problem of size at most three with a positive definite matrix, so exactly one
// choice of holding strings is consistent; it is found by trying each choice in turn.
#include "core/vec.hpp"

namespace collide::physics::detail {

struct ImpactPartner {
  double inverse_mass_per_kg = 0.0;      // 1 / m; 0 for a wall
  core::Vec2 velocity_mps = {0.0, 0.0};  // of the centre of mass, just before
  bool taut = false;                     // hangs on a taut string
  core::Vec2 string_out = {0.0, -1.0};   // taut: unit vector from the pivot to the centre of mass
};

struct StringImpact {
  core::Vec2 velocity_a_mps = {0.0, 0.0}, velocity_b_mps = {0.0, 0.0};  // just after
  double contact_impulse_Ns = 0.0;  // J >= 0, on b along the normal, on a against it
  double tension_impulse_a_Ns = 0.0, tension_impulse_b_Ns = 0.0;  // >= 0, towards the pivots
  bool string_a_holds = false, string_b_holds = false;            // taut strings that stay taut
  // J u (1 - e) / 2: the strings do no work (their bodies have no radial velocity before or
  // after), so this is the whole loss, the analytic 1/2 m_eff (1 - e^2) u^2 with m_eff the mass
  // the contact feels through the strings.
  double energy_lost_J = 0.0;
};

// normal: unit vector from a towards b (for a wall: out of the wall, towards a, is -normal).
// closing speed u = normal . (v_a - v_b) > 0; restitution e in [0, 1].
StringImpact resolveStringImpact(const ImpactPartner& a, const ImpactPartner& b,
                                 const core::Vec2& normal, double restitution);

}  // namespace collide::physics::detail
