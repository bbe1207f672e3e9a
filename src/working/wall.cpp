// SPDX-License-Identifier: MIT
// A body and a wall: the wall does not move, so the definition of e alone gives the rebound
// (v′ = −e v along the normal, the tangential part unchanged); a ball bouncing under gravity
// adds the heights, e = √(h₂/h₁).
#include <cmath>
#include <utility>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

struct Rebound {
  int body = 0;
  double m = 1.0, e = 1.0;
  double u = 0.0;              // along the line before: 1D the x component, 2D the normal one
  const char* component = "";  // "" in 1D, "n" in 2D
};

Rebound reboundOf(const Impact& impact) {
  const physics::CollisionEvent& event = impact.event;
  Rebound rebound;
  rebound.body = event.body_a;
  rebound.m = impact.timeline.world().bodies[std::size_t(event.body_a)].mass_kg;
  rebound.e = event.restitution;
  if (impact.dimensions == 1) {
    rebound.u = event.velocity_a_before_mps.x();
  } else {
    rebound.u = event.velocity_a_before_mps.dot(event.normal);
    rebound.component = "n";
  }
  return rebound;
}

void addGiven(const Impact& impact, const Rebound& rebound, Working& working) {
  Step& given = stepOf(working, StepKind::kGiven);
  given.equations.push_back(equation(massSymbol(rebound.body), mass(rebound.m)));
  given.equations.push_back(
      equation(velocitySymbol(rebound.body),
               velocity(impact.event.velocity_a_before_mps, impact.dimensions, impact.formats)));
  given.equations.push_back(equation(restitutionSymbol(), plain(rebound.e)));
  if (impact.dimensions == 2) {
    const core::Vec2 n = impact.event.normal;
    given.equations.push_back(equation(
        plainSymbol("n̂"), text::fenced(text::row({plain(n.x()), text::op(","), plain(n.y())})),
        text::tr("the unit normal along the line of impact")));
  }
}

void addLaws(const Impact& impact, const Rebound& rebound, Working& working) {
  Step& law = stepOf(working, StepKind::kLaw);
  const int i = rebound.body;
  law.equations.push_back(equation(
      velocitySymbol(i, 1, rebound.component),
      text::row({text::op("−"),
                 juxtaposed({restitutionSymbol(), velocitySymbol(i, 0, rebound.component)})}),
      // TRANSLATORS: a note beside v′ = −e v for an impact on a wall in a working.
      text::tr("the wall does not move: the definition of e")));
  if (impact.dimensions == 2) {
    law.equations.push_back(
        equation(velocitySymbol(i, 1, "t"), velocitySymbol(i, 0, "t"),
                 text::tr("smooth surfaces: the tangential part is unchanged")));
  }
  law.equations.push_back(
      equation(energyChangeSymbol(rebound.e),
               juxtaposed({half(), massSymbol(i), restitutionFactor(restitutionSymbol(), rebound.e),
                           squared(velocitySymbol(i, 0, rebound.component))}),
               energyChangeNote(rebound.e)));
}

void addNumbers(const Impact& impact, const Rebound& rebound, Working& working) {
  const Formats& formats = impact.formats;
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  const int i = rebound.body;
  if (impact.dimensions == 2) {
    numbers.equations.push_back(
        equation(velocitySymbol(i, 0, "n"), speed(rebound.u, formats, text::Sign::kNegativeOnly)));
  }
  numbers.equations.push_back(equation3(
      velocitySymbol(i, 1, rebound.component),
      text::row({text::op("−"), product({plain(rebound.e), speedValue(rebound.u, formats)})}),
      speed(-rebound.e * rebound.u, formats, text::Sign::kNegativeOnly)));
  numbers.equations.push_back(equation3(
      energyChangeSymbol(rebound.e),
      product({half(), massValue(rebound.m), restitutionFactor(plain(rebound.e), rebound.e),
               squared(speedValue(rebound.u, formats))}),
      energy(energyChange_J(rebound.m, rebound.u, rebound.e), formats)));
}

void addResult(const Impact& impact, const Rebound& rebound, Working& working) {
  Step& result = stepOf(working, StepKind::kResult);
  result.equations.push_back(
      equation(velocitySymbol(rebound.body, 1),
               velocity(impact.event.velocity_a_after_mps, impact.dimensions, impact.formats)));
  result.equations.push_back(energyChangeResult(impact));
}

Math heightSymbol(int index) {
  return text::scripts(plainSymbol("h"), text::row({text::number(std::to_string(index))}));
}

// The fall before and the rise after: 1/2 v² = g h for the speed along the normal (vertical).
void addHeights(const Impact& impact, const Rebound& rebound, Working& working) {
  const double g = impact.timeline.world().gravity_mps2.norm();
  const double fall_m = rebound.u * rebound.u / (2.0 * g);
  const double rebound_mps = -impact.event.velocity_a_after_mps.dot(impact.event.normal);
  const double rise_m = rebound_mps * rebound_mps / (2.0 * g);
  const int i = rebound.body;
  Step& given = stepOf(working, StepKind::kGiven);
  given.equations.push_back(equation(plainSymbol("g"), amount(g, "m/s²")));
  Step& law = stepOf(working, StepKind::kLaw);
  const Math two_g_symbols = juxtaposed({plain(2.0), plainSymbol("g")});
  law.equations.push_back(
      equation(heightSymbol(1), text::fraction(squared(velocitySymbol(i, 0, "n")), two_g_symbols),
               // TRANSLATORS: a note beside h₁ = vₙ²/(2g) in the working of a bouncing ball.
               text::tr("the fall before and the rise after: ½v² = gh")));
  law.equations.push_back(
      equation(heightSymbol(2), text::fraction(squared(velocitySymbol(i, 1, "n")), two_g_symbols)));
  law.equations.push_back(
      equation(restitutionSymbol(), text::root(text::fraction(heightSymbol(2), heightSymbol(1))),
               // TRANSLATORS: a note beside e = √(h₂/h₁) in the working of a bouncing ball.
               text::tr("each bounce reaches e² of the height before")));
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  const Math two_g = product({plain(2.0), amount(g, "m/s²").parts[0]});
  numbers.equations.push_back(equation3(
      heightSymbol(1), text::fraction(squared(speedValue(rebound.u, impact.formats)), two_g),
      amount(fall_m, "m")));
  numbers.equations.push_back(equation3(
      heightSymbol(2), text::fraction(squared(speedValue(rebound_mps, impact.formats)), two_g),
      amount(rise_m, "m")));
  numbers.equations.push_back(equation3(
      restitutionSymbol(),
      text::root(text::fraction(amount(rise_m, "m").parts[0], amount(fall_m, "m").parts[0])),
      plain(std::sqrt(rise_m / fall_m))));
  Step& result = stepOf(working, StepKind::kResult);
  result.equations.push_back(equation(heightSymbol(2), amount(rise_m, "m")));
  result.equations.push_back(equation(restitutionSymbol(), plain(std::sqrt(rise_m / fall_m))));
}

}  // namespace

void addWall(const Impact& impact, Working& working) {
  const Rebound rebound = reboundOf(impact);
  addGiven(impact, rebound, working);
  addLaws(impact, rebound, working);
  addNumbers(impact, rebound, working);
  addResult(impact, rebound, working);
}

void addBouncingBall(const Impact& impact, Working& working) {
  addWall(impact, working);
  addHeights(impact, reboundOf(impact), working);
}

}  // namespace collide::working
