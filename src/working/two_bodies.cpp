// SPDX-License-Identifier: MIT
// Two bodies meeting: momentum conservation and the definition of e along the line of impact
// (in 2D on the normal components, the tangential ones unchanged), the common velocity when
// e = 0, and the energy lost 1/2 mu (1 - e^2) u^2 (gained, 1/2 mu (e^2 - 1) u^2, where e > 1).
#include <utility>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

// The impact along its line: 1D the x components, 2D the normal ones (component "n").
struct Line {
  int i = 0, j = 1;  // body indices
  double m_i = 1.0, m_j = 1.0;
  double u_i = 0.0, u_j = 0.0;  // before, along the line
  double e = 1.0;
  const char* component = "";  // "" in 1D, "n" in 2D

  Math v(int body, int primes = 0) const { return velocitySymbol(body, primes, component); }
  Math m(int body) const { return massSymbol(body); }
};

core::Vec2 tangentOf(const core::Vec2& normal) {
  return {-normal.y(), normal.x()};
}

Line lineOf(const Impact& impact) {
  const physics::CollisionEvent& event = impact.event;
  const std::vector<physics::BodyDef>& bodies = impact.timeline.world().bodies;
  Line line;
  line.i = event.body_a;
  line.j = event.body_b;
  line.m_i = bodies[std::size_t(event.body_a)].mass_kg;
  line.m_j = bodies[std::size_t(event.body_b)].mass_kg;
  line.e = event.restitution;
  if (impact.dimensions == 1) {
    line.u_i = event.velocity_a_before_mps.x();
    line.u_j = event.velocity_b_before_mps.x();
  } else {
    line.component = "n";
    line.u_i = event.velocity_a_before_mps.dot(event.normal);
    line.u_j = event.velocity_b_before_mps.dot(event.normal);
  }
  return line;
}

// v′ in 1D, vₙ′ in 2D: the common velocity along the line when e = 0.
Math commonSymbol(const Line& line) {
  Math index = *line.component == '\0' ? Math{} : text::row({text::word(line.component)});
  return text::scripts(plainSymbol(text::symbol(text::Symbol::kVelocity)), std::move(index), {}, 1);
}

Math reducedMassSymbol() {
  return plainSymbol("μ");
}
Math closingSymbol() {
  return plainSymbol("u");
}

void addGiven(const Impact& impact, const Line& line, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  Step& given = stepOf(working, StepKind::kGiven);
  given.equations.push_back(equation(line.m(line.i), mass(line.m_i)));
  given.equations.push_back(equation(line.m(line.j), mass(line.m_j)));
  given.equations.push_back(
      equation(velocitySymbol(line.i),
               velocity(event.velocity_a_before_mps, impact.dimensions, impact.formats)));
  given.equations.push_back(
      equation(velocitySymbol(line.j),
               velocity(event.velocity_b_before_mps, impact.dimensions, impact.formats)));
  given.equations.push_back(
      equation(plainSymbol(text::symbol(text::Symbol::kRestitution)), plain(line.e)));
  if (impact.dimensions == 2) {
    const Math pair =
        text::fenced(text::row({plain(event.normal.x()), text::op(","), plain(event.normal.y())}));
    // TRANSLATORS: a note beside n̂ in the working of a 2D impact.
    given.equations.push_back(
        equation(plainSymbol("n̂"), pair, text::tr("the unit normal along the line of impact")));
  }
}

Math momentumSum(const Line& line, int primes) {
  return sum(juxtaposed({line.m(line.i), line.v(line.i, primes)}),
             juxtaposed({line.m(line.j), line.v(line.j, primes)}));
}

// v_i' = ((m_i - e m_j) v_i + (1 + e) m_j v_j) / (m_i + m_j), and v_j' with i and j swapped.
Math solvedFor(const Line& line, int first, int second) {
  const Math e = restitutionSymbol();
  const Math own = text::fenced(difference(line.m(first), juxtaposed({e, line.m(second)})));
  const Math gained = text::fenced(sum(plain(1.0), e));
  const Math top =
      sum(juxtaposed({own, line.v(first)}), juxtaposed({gained, line.m(second), line.v(second)}));
  return text::fraction(top, sum(line.m(line.i), line.m(line.j)));
}

Math lossFormula(bool merged, double e) {
  std::vector<Math> factors = {half(), reducedMassSymbol()};
  if (!merged) factors.push_back(restitutionFactor(restitutionSymbol(), e));
  factors.push_back(squared(closingSymbol()));
  return juxtaposed(std::move(factors));
}

void addLaws(const Line& line, bool merged, Working& working) {
  Step& law = stepOf(working, StepKind::kLaw);
  // TRANSLATORS: a note beside the law m₁v₁ + m₂v₂ = m₁v₁′ + m₂v₂′ in a working.
  const std::string conserved = text::tr("momentum is conserved");
  if (merged) {
    const Math common = commonSymbol(line);
    law.equations.push_back(
        equation(momentumSum(line, 0),
                 juxtaposed({text::fenced(sum(line.m(line.i), line.m(line.j))), common}),
                 // TRANSLATORS: a note beside the law of a perfectly inelastic impact (e = 0).
                 conserved + text::clauseSeparator() + text::tr("e = 0: they move on together")));
  } else {
    law.equations.push_back(equation(momentumSum(line, 0), momentumSum(line, 1), conserved));
    law.equations.push_back(equation(
        difference(line.v(line.j, 1), line.v(line.i, 1)),
        juxtaposed({restitutionSymbol(), text::fenced(difference(line.v(line.i), line.v(line.j)))}),
        // TRANSLATORS: a note beside v₂′ − v₁′ = e(v₁ − v₂) in a working.
        text::tr("the definition of e along the line of impact")));
  }
  law.equations.push_back(
      equation(energyChangeSymbol(line.e), lossFormula(merged, line.e), energyChangeNote(line.e)));
  const Math masses = juxtaposed({line.m(line.i), line.m(line.j)});
  law.equations.push_back(equation(reducedMassSymbol(),
                                   text::fraction(masses, sum(line.m(line.i), line.m(line.j))),
                                   // TRANSLATORS: a note beside μ = m₁m₂/(m₁ + m₂) in a working.
                                   text::tr("the reduced mass")));
  law.equations.push_back(equation(closingSymbol(), difference(line.v(line.i), line.v(line.j)),
                                   // TRANSLATORS: a note beside u = v₁ − v₂ in a working.
                                   text::tr("the closing speed along the line of impact")));
}

void addSolved(const Line& line, bool merged, Working& working) {
  Step& solved = stepOf(working, StepKind::kSolved);
  if (merged) {
    const Math common = commonSymbol(line);
    solved.equations.push_back(equation(
        common, text::fraction(momentumSum(line, 0), sum(line.m(line.i), line.m(line.j)))));
    return;
  }
  solved.equations.push_back(equation(line.v(line.i, 1), solvedFor(line, line.i, line.j)));
  solved.equations.push_back(equation(line.v(line.j, 1), solvedFor(line, line.j, line.i)));
}

// The velocities after along the line, from the solved laws.
double afterAlong(const Line& line, bool first) {
  const double m_own = first ? line.m_i : line.m_j, m_other = first ? line.m_j : line.m_i;
  const double u_own = first ? line.u_i : line.u_j, u_other = first ? line.u_j : line.u_i;
  return ((m_own - line.e * m_other) * u_own + (1.0 + line.e) * m_other * u_other) /
         (line.m_i + line.m_j);
}

Math substitutedAfter(const Line& line, bool first, const Formats& formats) {
  const double m_own = first ? line.m_i : line.m_j, m_other = first ? line.m_j : line.m_i;
  const double u_own = first ? line.u_i : line.u_j, u_other = first ? line.u_j : line.u_i;
  const Math e = plain(line.e);
  const Math own = text::fenced(difference(massValue(m_own), product({e, massValue(m_other)})));
  const Math gained = text::fenced(sum(plain(1.0), e));
  const Math top = sum(product({own, speedValue(u_own, formats)}),
                       product({gained, massValue(m_other), speedValue(u_other, formats)}));
  return text::fraction(top, sum(massValue(line.m_i), massValue(line.m_j)));
}

void addSubstituted(const Impact& impact, const Line& line, bool merged, Working& working) {
  const Formats& formats = impact.formats;
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  const double mu_kg = line.m_i * line.m_j / (line.m_i + line.m_j);
  const double u_mps = line.u_i - line.u_j;
  numbers.equations.push_back(
      equation3(reducedMassSymbol(),
                text::fraction(product({massValue(line.m_i), massValue(line.m_j)}),
                               sum(massValue(line.m_i), massValue(line.m_j))),
                mass(mu_kg)));
  numbers.equations.push_back(equation3(
      closingSymbol(), difference(speedValue(line.u_i, formats), speedValue(line.u_j, formats)),
      speed(u_mps, formats, text::Sign::kNegativeOnly)));
  if (merged) {
    const double common_mps = (line.m_i * line.u_i + line.m_j * line.u_j) / (line.m_i + line.m_j);
    const Math top = sum(product({massValue(line.m_i), speedValue(line.u_i, formats)}),
                         product({massValue(line.m_j), speedValue(line.u_j, formats)}));
    numbers.equations.push_back(equation3(
        commonSymbol(line), text::fraction(top, sum(massValue(line.m_i), massValue(line.m_j))),
        speed(common_mps, formats)));
  } else {
    numbers.equations.push_back(equation3(line.v(line.i, 1), substitutedAfter(line, true, formats),
                                          speed(afterAlong(line, true), formats)));
    numbers.equations.push_back(equation3(line.v(line.j, 1), substitutedAfter(line, false, formats),
                                          speed(afterAlong(line, false), formats)));
  }
  std::vector<Math> factors = {half(), massValue(mu_kg)};
  if (!merged) factors.push_back(restitutionFactor(plain(line.e), line.e));
  factors.push_back(squared(speedValue(u_mps, formats)));
  numbers.equations.push_back(equation3(energyChangeSymbol(line.e), product(std::move(factors)),
                                        energy(energyChange_J(mu_kg, u_mps, line.e), formats)));
}

// 2D: the components along the normal and the tangent, before; the velocities after rebuilt.
void addComponents(const Impact& impact, const Line& line, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  const core::Vec2 tangent = tangentOf(event.normal);
  Step& law = stepOf(working, StepKind::kLaw);
  for (int body : {line.i, line.j}) {
    law.equations.push_back(
        equation(velocitySymbol(body, 1, "t"), velocitySymbol(body, 0, "t"),
                 // TRANSLATORS: a note beside v₁ₜ′ = v₁ₜ in a 2D working.
                 text::tr("smooth surfaces: the tangential part is unchanged")));
  }
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  const core::Vec2 before[2] = {event.velocity_a_before_mps, event.velocity_b_before_mps};
  for (int k = 0; k < 2; ++k) {
    const int body = k == 0 ? line.i : line.j;
    numbers.equations.push_back(
        equation(velocitySymbol(body, 0, "n"),
                 speed(before[k].dot(event.normal), impact.formats, text::Sign::kNegativeOnly)));
    numbers.equations.push_back(
        equation(velocitySymbol(body, 0, "t"),
                 speed(before[k].dot(tangent), impact.formats, text::Sign::kNegativeOnly)));
  }
}

void addVectorsAfter(const Impact& impact, const Line& line, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  const core::Vec2 before[2] = {event.velocity_a_before_mps, event.velocity_b_before_mps};
  const core::Vec2 tangent = tangentOf(event.normal);
  for (int k = 0; k < 2; ++k) {
    const int body = k == 0 ? line.i : line.j;
    const double normal_mps = afterAlong(line, k == 0);
    const core::Vec2 after = normal_mps * event.normal + before[k].dot(tangent) * tangent;
    numbers.equations.push_back(
        equation3(velocitySymbol(body, 1),
                  sum(juxtaposed({velocitySymbol(body, 1, "n"), plainSymbol("n̂")}),
                      juxtaposed({velocitySymbol(body, 0, "t"), plainSymbol("t̂")})),
                  velocity(after, 2, impact.formats)));
  }
}

void addResult(const Impact& impact, const Line& line, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  Step& result = stepOf(working, StepKind::kResult);
  result.equations.push_back(
      equation(velocitySymbol(line.i, 1),
               velocity(event.velocity_a_after_mps, impact.dimensions, impact.formats)));
  result.equations.push_back(
      equation(velocitySymbol(line.j, 1),
               velocity(event.velocity_b_after_mps, impact.dimensions, impact.formats)));
  result.equations.push_back(energyChangeResult(impact));
}

}  // namespace

void addTwoBodies(const Impact& impact, Working& working) {
  const Line line = lineOf(impact);
  const bool merged = line.e == 0.0;
  addGiven(impact, line, working);
  addLaws(line, merged, working);
  if (impact.dimensions == 2) addComponents(impact, line, working);
  addSolved(line, merged, working);
  addSubstituted(impact, line, merged, working);
  if (impact.dimensions == 2) addVectorsAfter(impact, line, working);
  addResult(impact, line, working);
}

}  // namespace collide::working
