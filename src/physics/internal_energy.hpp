// SPDX-License-Identifier: MIT
#pragma once
// Molecules with insides: the Borgnakke-Larsen exchange (Borgnakke & Larsen, J. Comput. Phys. 18,
// 1975; Bird, Molecular Gas Dynamics and the Direct Simulation of Gas Flows, 1994, section 5.4)
// for hard disks in a plane. At an impact the pair's collision energy E_c (the translational
// energy of their relative motion, 1/2 mu g^2, plus both internal energies) is shared anew:
//
//   E_tr' = X E_c,             X ~ Beta(3/2, zeta)       (zeta internal degrees of freedom each)
//   E_a'  = Y (E_c - E_tr'),   Y ~ Beta(zeta/2, zeta/2),  E_b' = E_c - E_tr' - E_a'
//
// Why 3/2: in a plane the relative velocity has 2 degrees of freedom, and hard disks meet at a
// rate proportional to g, so the relative energy of colliding pairs is distributed as
// E^(1/2) exp(-E/kT), a Gamma density of shape 3/2 ("3 degrees of freedom"); each disk's internal
// energy is Gamma of shape zeta/2. Splitting a sum of independent Gamma variables in the ratio of
// a Beta of their shapes gives them back: the exchange keeps the equilibrium (detailed balance),
// in which every degree of freedom holds kT/2 on average. Internal to collide_physics.
#include <cstdint>

#include "core/vec.hpp"

namespace collide::physics::detail {

// A generator of uniform numbers in (0, 1] (splitmix64: one 64-bit word of state, the same
// sequence on every platform), advanced in place.
double uniformDraw(std::uint64_t& state);

// A Gamma variate of shape half_shapes / 2 and scale 1 (a chi-square of half_shapes degrees of
// freedom, halved), half_shapes >= 1.
double gammaOfHalfShape(int half_shapes, std::uint64_t& state);

struct Shares {
  double translational_J = 0.0;  // of the relative motion, after
  double internal_a_J = 0.0, internal_b_J = 0.0;
};

// The Borgnakke-Larsen shares of E_c = translational_J + internal_a_J + internal_b_J for disks
// with internal_dof (1 or 2) internal degrees of freedom each.
Shares borgnakkeLarsen(double translational_J, double internal_a_J, double internal_b_J,
                       int internal_dof, std::uint64_t& state);

// The velocity change of disk a (disk b's is -impulse / m_b) when the pair's relative velocity
// g = v_a - v_b (closing along n, from a to b) is turned into the hard-disk rebound's direction,
// g - 2 (g.n) n, at the magnitude whose energy 1/2 mu g'^2 is translational_after_J: returned as
// the impulse on a, kg m/s, so that momentum is kept exactly as in every other impact.
core::Vec2 exchangeImpulse(const core::Vec2& v_a, const core::Vec2& v_b, const core::Vec2& n,
                           double reduced_mass_kg, double translational_after_J);

}  // namespace collide::physics::detail
