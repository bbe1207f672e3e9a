// SPDX-License-Identifier: MIT
// Energy that comes in. A release: stored energy Q pushes two touching bodies apart, momentum
// conserved, so Σp is kept and ½m₁v₁′² + ½m₂v₂′² = ½m₁v₁² + ½m₂v₂² + Q (from rest: Σp = 0 and
// ½m₁v₁′² + ½m₂v₂′² = Q). A super-elastic impact (e > 1): the energy the restitution law gives
// is a gain, Q = ½μ(e² − 1)u², where e ≤ 1 loses ΔKE = ½μ(1 − e²)u².
#include <cmath>
#include <utility>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

// The pair along the line (a release acts in 1D): a behind b, pushed apart.
struct ReleasePair {
  int i = 0, j = 1;
  double m_i = 1.0, m_j = 1.0;
  double v_i = 0.0, v_j = 0.0;  // before, m/s
  double q_J = 0.0;             // released
  bool at_rest = true;
};

ReleasePair releasePairOf(const Impact& impact) {
  const physics::CollisionEvent& event = impact.event;
  const std::vector<physics::BodyDef>& bodies = impact.timeline.world().bodies;
  ReleasePair pair;
  pair.i = event.body_a;
  pair.j = event.body_b;
  pair.m_i = bodies[std::size_t(pair.i)].mass_kg;
  pair.m_j = bodies[std::size_t(pair.j)].mass_kg;
  pair.v_i = event.velocity_a_before_mps.x();
  pair.v_j = event.velocity_b_before_mps.x();
  pair.q_J = event.energy_released_J;
  pair.at_rest = pair.v_i == 0.0 && pair.v_j == 0.0;
  return pair;
}

Math separationSymbol(int primes = 0) {
  return text::scripts(plainSymbol("s"), {}, {}, primes);
}
Math releaseCentreSymbol() {
  return text::scripts(plainSymbol(text::symbol(text::Symbol::kVelocity)),
                       text::row({text::word("cm")}));
}

// ½m₁v₁² + ½m₂v₂², primed after.
Math releaseKinetic(const ReleasePair& pair, int primes) {
  return sum(juxtaposed({half(), massSymbol(pair.i), squared(velocitySymbol(pair.i, primes))}),
             juxtaposed({half(), massSymbol(pair.j), squared(velocitySymbol(pair.j, primes))}));
}
Math releaseMomentum(const ReleasePair& pair, int primes) {
  return sum(juxtaposed({massSymbol(pair.i), velocitySymbol(pair.i, primes)}),
             juxtaposed({massSymbol(pair.j), velocitySymbol(pair.j, primes)}));
}
Math releaseMassSum(const ReleasePair& pair) {
  return sum(massSymbol(pair.i), massSymbol(pair.j));
}
Math releaseMassValues(const ReleasePair& pair) {
  return sum(massValue(pair.m_i), massValue(pair.m_j));
}

// The speeds after, from the laws: the centre of mass keeps its velocity, the separation speed
// grows to s′ = √(s² + 2Q/μ), shared in the inverse ratio of the masses.
struct ReleaseAfter {
  double v_i, v_j, centre, s, s_after, mu;
};
ReleaseAfter releaseAfterOf(const ReleasePair& pair) {
  ReleaseAfter after{};
  const double total = pair.m_i + pair.m_j;
  after.mu = pair.m_i * pair.m_j / total;
  after.centre = (pair.m_i * pair.v_i + pair.m_j * pair.v_j) / total;
  after.s = pair.v_j - pair.v_i;
  after.s_after = std::sqrt(after.s * after.s + 2.0 * pair.q_J / after.mu);
  after.v_i = after.centre - pair.m_j * after.s_after / total;
  after.v_j = after.centre + pair.m_i * after.s_after / total;
  return after;
}

void addReleaseGiven(const Impact& impact, const ReleasePair& pair, Working& working) {
  Step& given = stepOf(working, StepKind::kGiven);
  given.equations.push_back(equation(massSymbol(pair.i), mass(pair.m_i)));
  given.equations.push_back(equation(massSymbol(pair.j), mass(pair.m_j)));
  given.equations.push_back(equation(velocitySymbol(pair.i), speed(pair.v_i, impact.formats)));
  given.equations.push_back(equation(velocitySymbol(pair.j), speed(pair.v_j, impact.formats)));
  given.equations.push_back(equation(releasedSymbol(), energy(pair.q_J, impact.formats),
                                     // TRANSLATORS: a note beside Q = 3.00 J in the working of
                                     // a release (a spring let go, a shot fired).
                                     text::tr("the stored energy released")));
}

void addReleaseLaws(const ReleasePair& pair, Working& working) {
  Step& law = stepOf(working, StepKind::kLaw);
  // TRANSLATORS: a note beside the law ½m₁v₁′² + ½m₂v₂′² = Q in the working of a release.
  const std::string into_motion = text::tr("the stored energy becomes kinetic energy");
  if (pair.at_rest) {
    law.equations.push_back(
        equation(releaseMomentum(pair, 1), plain(0.0, 1),
                 // TRANSLATORS: a note beside m₁v₁′ + m₂v₂′ = 0 in the working of a release.
                 text::tr("momentum is conserved: at rest before, Σp = 0")));
    law.equations.push_back(equation(releaseKinetic(pair, 1), releasedSymbol(), into_motion));
    return;
  }
  law.equations.push_back(equation(releaseMomentum(pair, 0), releaseMomentum(pair, 1),
                                   text::tr("momentum is conserved")));
  law.equations.push_back(equation(releaseKinetic(pair, 1),
                                   sum(releaseKinetic(pair, 0), releasedSymbol()), into_motion));
}

// From rest: v₂′ = √(2Qm₁ / (m₂(m₁ + m₂))), v₁′ = −m₂v₂′ / m₁.
void addSolvedFromRest(const Impact& impact, const ReleasePair& pair, Working& working) {
  const ReleaseAfter after = releaseAfterOf(pair);
  const Math second_speed = text::root(
      text::fraction(juxtaposed({plain(2.0, 1), releasedSymbol(), massSymbol(pair.i)}),
                     juxtaposed({massSymbol(pair.j), text::fenced(releaseMassSum(pair))})));
  const Math first_speed = text::row(
      {text::op("−"), text::fraction(juxtaposed({massSymbol(pair.j), velocitySymbol(pair.j, 1)}),
                                     massSymbol(pair.i))});
  Step& solved = stepOf(working, StepKind::kSolved);
  solved.equations.push_back(equation(velocitySymbol(pair.j, 1), second_speed));
  solved.equations.push_back(equation(velocitySymbol(pair.i, 1), first_speed));
  const Formats& formats = impact.formats;
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  numbers.equations.push_back(equation3(
      velocitySymbol(pair.j, 1),
      text::root(text::fraction(
          product({plain(2.0, 1), energy(pair.q_J, formats).parts[0], massValue(pair.m_i)}),
          product({massValue(pair.m_j), text::fenced(releaseMassValues(pair))}))),
      speed(after.v_j, formats)));
  numbers.equations.push_back(equation3(
      velocitySymbol(pair.i, 1),
      text::row({text::op("−"),
                 text::fraction(product({massValue(pair.m_j), speedValue(after.v_j, formats)}),
                                massValue(pair.m_i))}),
      speed(after.v_i, formats)));
}

// Moving before: the centre of mass keeps its velocity; the separation speed grows by Q.
void addSolvedMoving(const Impact& impact, const ReleasePair& pair, Working& working) {
  const ReleaseAfter after = releaseAfterOf(pair);
  const Math mu = plainSymbol("μ");
  Step& solved = stepOf(working, StepKind::kSolved);
  solved.equations.push_back(equation(
      releaseCentreSymbol(), text::fraction(releaseMomentum(pair, 0), releaseMassSum(pair)),
      // TRANSLATORS: a note beside v_cm = (m₁v₁ + m₂v₂)/(m₁ + m₂) in a working.
      text::tr("the centre of mass moves on unchanged")));
  solved.equations.push_back(
      equation(separationSymbol(1),
               text::root(sum(squared(separationSymbol()),
                              text::fraction(juxtaposed({plain(2.0, 1), releasedSymbol()}), mu))),
               // TRANSLATORS: a note beside s′ = √(s² + 2Q/μ) in the working of a release; s is
               // v₂ − v₁.
               text::tr("the speed of separation, s = v₂ − v₁, from ½μs′² = ½μs² + Q")));
  const Math total = text::fenced(releaseMassSum(pair));
  solved.equations.push_back(equation(
      velocitySymbol(pair.i, 1),
      difference(releaseCentreSymbol(),
                 text::fraction(juxtaposed({massSymbol(pair.j), separationSymbol(1)}), total))));
  solved.equations.push_back(
      equation(velocitySymbol(pair.j, 1),
               sum(releaseCentreSymbol(),
                   text::fraction(juxtaposed({massSymbol(pair.i), separationSymbol(1)}), total))));
  const Formats& formats = impact.formats;
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  numbers.equations.push_back(equation3(
      mu,
      text::fraction(product({massValue(pair.m_i), massValue(pair.m_j)}), releaseMassValues(pair)),
      mass(after.mu)));
  numbers.equations.push_back(equation(releaseCentreSymbol(), speed(after.centre, formats)));
  numbers.equations.push_back(equation(separationSymbol(), speed(after.s, formats)));
  numbers.equations.push_back(equation(separationSymbol(1), speed(after.s_after, formats)));
  numbers.equations.push_back(equation(velocitySymbol(pair.i, 1), speed(after.v_i, formats)));
  numbers.equations.push_back(equation(velocitySymbol(pair.j, 1), speed(after.v_j, formats)));
}

void addReleaseResult(const Impact& impact, const ReleasePair& pair, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  Step& result = stepOf(working, StepKind::kResult);
  result.equations.push_back(
      equation(velocitySymbol(pair.i, 1), velocity(event.velocity_a_after_mps, 1, impact.formats)));
  result.equations.push_back(
      equation(velocitySymbol(pair.j, 1), velocity(event.velocity_b_after_mps, 1, impact.formats)));
  result.equations.push_back(
      equation(releasedSymbol(), energy(event.energy_released_J, impact.formats)));
}

}  // namespace

Math releasedSymbol() {
  return plainSymbol("Q");
}

bool gainsEnergy(double e) {
  return e > 1.0;
}

Math energyChangeSymbol(double e) {
  return gainsEnergy(e) ? releasedSymbol() : energyLostSymbol();
}

Math restitutionFactor(Math e_shown, double e) {
  return text::fenced(gainsEnergy(e) ? difference(squared(std::move(e_shown)), plain(1.0))
                                     : difference(plain(1.0), squared(std::move(e_shown))));
}

std::string energyChangeNote(double e) {
  if (gainsEnergy(e)) {
    // TRANSLATORS: a note beside Q = ½μ(e² − 1)u² in the working of a super-elastic impact.
    return text::tr("the energy released: e > 1, stored energy becomes kinetic energy");
  }
  // TRANSLATORS: a note beside ΔKE = ½μ(1 − e²)u² in a working.
  return text::tr("the energy lost");
}

double energyChange_J(double m_kg, double u_mps, double e) {
  return 0.5 * m_kg * std::abs(1.0 - e * e) * u_mps * u_mps;
}

Equation energyChangeResult(const Impact& impact) {
  const physics::CollisionEvent& event = impact.event;
  const double e = event.restitution;
  return equation(
      energyChangeSymbol(e),
      energy(gainsEnergy(e) ? event.energy_released_J : event.energy_lost_J, impact.formats));
}

void addRelease(const Impact& impact, Working& working) {
  const ReleasePair pair = releasePairOf(impact);
  addReleaseGiven(impact, pair, working);
  addReleaseLaws(pair, working);
  if (pair.at_rest) {
    addSolvedFromRest(impact, pair, working);
  } else {
    addSolvedMoving(impact, pair, working);
  }
  addReleaseResult(impact, pair, working);
}

}  // namespace collide::working
