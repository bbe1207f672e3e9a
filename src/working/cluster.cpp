// SPDX-License-Identifier: MIT
// Two disks that stick into one rigid body (2D, e = 0, `inelastic = "stick"`): the centre of mass
// moves on with the momentum, and the body turns with the angular momentum about it, L = I ω.
#include <cmath>
#include <utility>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

double cross(const core::Vec2& a, const core::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

struct Cluster {
  int i = 0, j = 1;
  double m_i = 1.0, m_j = 1.0;
  core::Vec2 centre_velocity_mps = {0.0, 0.0};
  double inertia_kgm2 = 0.0;      // about the centre of mass: disks' own and the offsets'
  double angular_momentum = 0.0;  // kg m²/s about the centre of mass
  double before_J = 0.0, after_J = 0.0;
};

Cluster clusterOf(const Impact& impact) {
  const physics::CollisionEvent& event = impact.event;
  const std::vector<physics::BodyDef>& bodies = impact.timeline.world().bodies;
  const physics::Snapshot at = impact.timeline.sample(event.time_s);
  Cluster c;
  c.i = event.body_a;
  c.j = event.body_b;
  c.m_i = bodies[std::size_t(c.i)].mass_kg;
  c.m_j = bodies[std::size_t(c.j)].mass_kg;
  const double total = c.m_i + c.m_j;
  const core::Vec2 p_i = at.bodies[std::size_t(c.i)].position_m;
  const core::Vec2 p_j = at.bodies[std::size_t(c.j)].position_m;
  const core::Vec2 centre = (c.m_i * p_i + c.m_j * p_j) / total;
  const core::Vec2 v_i = event.velocity_a_before_mps, v_j = event.velocity_b_before_mps;
  c.centre_velocity_mps = (c.m_i * v_i + c.m_j * v_j) / total;
  const double r_i = bodies[std::size_t(c.i)].size_m, r_j = bodies[std::size_t(c.j)].size_m;
  c.inertia_kgm2 = c.m_i * ((p_i - centre).squaredNorm() + 0.5 * r_i * r_i) +
                   c.m_j * ((p_j - centre).squaredNorm() + 0.5 * r_j * r_j);
  c.angular_momentum = c.m_i * cross(p_i - centre, v_i - c.centre_velocity_mps) +
                       c.m_j * cross(p_j - centre, v_j - c.centre_velocity_mps);
  c.before_J = 0.5 * c.m_i * v_i.squaredNorm() + 0.5 * c.m_j * v_j.squaredNorm();
  const double omega = c.angular_momentum / c.inertia_kgm2;
  c.after_J =
      0.5 * total * c.centre_velocity_mps.squaredNorm() + 0.5 * c.inertia_kgm2 * omega * omega;
  return c;
}

Math centreSymbol() {
  return text::scripts(plainSymbol(text::symbol(text::Symbol::kVelocity)),
                       text::row({text::word("cm")}), {}, 1);
}
Math omegaSymbol() {
  return plainSymbol(text::symbol(text::Symbol::kAngularVelocity));
}

void addGiven(const Impact& impact, const Cluster& c, Working& working) {
  Step& given = stepOf(working, StepKind::kGiven);
  given.equations.push_back(equation(massSymbol(c.i), mass(c.m_i)));
  given.equations.push_back(equation(massSymbol(c.j), mass(c.m_j)));
  given.equations.push_back(equation(
      velocitySymbol(c.i), velocity(impact.event.velocity_a_before_mps, 2, impact.formats)));
  given.equations.push_back(equation(
      velocitySymbol(c.j), velocity(impact.event.velocity_b_before_mps, 2, impact.formats)));
}

void addLaws(const Cluster& c, Working& working) {
  Step& law = stepOf(working, StepKind::kLaw);
  law.equations.push_back(
      equation(juxtaposed({text::fenced(sum(massSymbol(c.i), massSymbol(c.j))), centreSymbol()}),
               sum(juxtaposed({massSymbol(c.i), velocitySymbol(c.i)}),
                   juxtaposed({massSymbol(c.j), velocitySymbol(c.j)})),
               text::tr("momentum is conserved")));
  law.equations.push_back(
      equation(plainSymbol("L"), juxtaposed({plainSymbol("I"), omegaSymbol()}),
               // TRANSLATORS: a note beside L = Iω when two disks stick into one turning body.
               text::tr("angular momentum about the centre of mass is conserved")));
}

void addNumbers(const Impact& impact, const Cluster& c, Working& working) {
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  numbers.equations.push_back(
      equation(centreSymbol(), velocity(c.centre_velocity_mps, 2, impact.formats)));
  numbers.equations.push_back(equation(plainSymbol("L"), amount(c.angular_momentum, "kg·m²/s")));
  numbers.equations.push_back(equation(plainSymbol("I"), amount(c.inertia_kgm2, "kg·m²")));
  const double omega = c.angular_momentum / c.inertia_kgm2;
  numbers.equations.push_back(
      equation3(omegaSymbol(),
                text::fraction(amount(c.angular_momentum, "kg·m²/s").parts[0],
                               amount(c.inertia_kgm2, "kg·m²").parts[0]),
                amount(omega, "rad/s")));
  numbers.equations.push_back(equation3(energyLostSymbol(),
                                        difference(energy(c.before_J, impact.formats).parts[0],
                                                   energy(c.after_J, impact.formats).parts[0]),
                                        energy(c.before_J - c.after_J, impact.formats)));
  Step& result = stepOf(working, StepKind::kResult);
  result.equations.push_back(
      equation(centreSymbol(), velocity(c.centre_velocity_mps, 2, impact.formats)));
  result.equations.push_back(equation(omegaSymbol(), amount(omega, "rad/s")));
  result.equations.push_back(
      equation(energyLostSymbol(), energy(impact.event.energy_lost_J, impact.formats)));
}

}  // namespace

void addStuckCluster(const Impact& impact, Working& working) {
  const Cluster cluster = clusterOf(impact);
  addGiven(impact, cluster, working);
  addLaws(cluster, working);
  addNumbers(impact, cluster, working);
}

}  // namespace collide::working
