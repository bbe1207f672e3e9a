// SPDX-License-Identifier: MIT
// Accident reconstruction: a body skids into one at rest on a level surface with sliding
// friction, they lock (e = 0) and skid to rest together. The working reads it as a police report
// does, backwards from the marks: the skid after the impact, d, gives the pair's speed by energy,
// v′ = √(2μₖgd); momentum gives the striker's speed at the impact, v₁ = (m₁ + m₂)/m₁ · v′; and
// its skid before the impact, s, the speed at which its wheels locked, v₀ = √(v₁² + 2μₖgs).
// d and s are measured on the simulated run, as the ballistic pendulum's rise is.
#include <cmath>
#include <optional>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

constexpr double kAtRest_mps = 1e-9;

// What the run shows of the skids, in metres.
struct Skids {
  int striker = 0, struck = 1;  // body indices: the one that skids into the one at rest
  double after_m = 0.0;         // d: the pair's travel from the impact to rest
  double before_m = 0.0;        // s: the striker's travel from t = 0 to the impact
};

bool involves(const physics::CollisionEvent& event, int body) {
  return event.body_a == body || event.body_b == body;
}

// The other collisions of the two bodies: an earlier one ends the striker's skid before this
// one, a later one any skid after it.
bool onlyImpactOfPair(const physics::Timeline& timeline, const physics::CollisionEvent& impact) {
  for (const physics::CollisionEvent& other : timeline.collisions()) {
    if (other.index == impact.index) continue;
    if (involves(other, impact.body_a) || involves(other, impact.body_b)) return false;
  }
  return !timeline.collisionsTruncated();
}

// Both bodies slide with one kinetic μ on a level surface, nothing else acting along it.
bool skidsAlike(const physics::WorldDef& world, const physics::CollisionEvent& event) {
  const physics::BodyDef& a = world.bodies[std::size_t(event.body_a)];
  const physics::BodyDef& b = world.bodies[std::size_t(event.body_b)];
  const bool level = world.gravity_mps2.norm() == 0.0 && world.surface_gravity_mps2 > 0.0;
  const bool no_air =
      a.drag_linear_kgps + a.drag_quadratic_kgpm + b.drag_linear_kgps + b.drag_quadratic_kgpm ==
      0.0;
  return level && no_air && a.friction > 0.0 && a.friction == b.friction;
}

std::optional<Skids> skidsOf(const Impact& impact) {
  const physics::Timeline& timeline = impact.timeline;
  const physics::WorldDef& world = timeline.world();
  const physics::CollisionEvent& event = impact.event;
  if (world.dimensions != 1 || event.hitsWall() || event.release || event.restitution != 0.0 ||
      !skidsAlike(world, event) || !onlyImpactOfPair(timeline, event)) {
    return std::nullopt;
  }
  const bool a_waits = event.velocity_a_before_mps.norm() <= kAtRest_mps;
  const int striker = a_waits ? event.body_b : event.body_a;
  const int struck = a_waits ? event.body_a : event.body_b;
  const core::Vec2 struck_before =
      a_waits ? event.velocity_a_before_mps : event.velocity_b_before_mps;
  const physics::Snapshot start = timeline.sample(0.0), at_impact = timeline.sample(event.time_s);
  const physics::Snapshot end = timeline.sample(timeline.simulatedUntil_s());
  if (struck_before.norm() > kAtRest_mps ||
      start.bodies[std::size_t(struck)].velocity_mps.norm() > kAtRest_mps ||
      end.bodies[std::size_t(striker)].velocity_mps.norm() > kAtRest_mps) {
    return std::nullopt;  // the struck body was not waiting, or the pair has not come to rest
  }
  const double impact_x_m = at_impact.bodies[std::size_t(striker)].position_m.x();
  Skids skids;
  skids.striker = striker;
  skids.struck = struck;
  skids.after_m = std::fabs(end.bodies[std::size_t(striker)].position_m.x() - impact_x_m);
  skids.before_m = std::fabs(impact_x_m - start.bodies[std::size_t(striker)].position_m.x());
  return skids;
}

Math frictionSymbol() {
  return text::scripts(plainSymbol("μ"), text::row({text::word("k")}));
}
Math skidAfterSymbol() {
  return plainSymbol("d");
}
Math skidBeforeSymbol() {
  return plainSymbol("s");
}
Math startSymbol() {
  return text::scripts(plainSymbol(text::symbol(text::Symbol::kVelocity)),
                       text::row({text::number("0")}));
}

void addGiven(const Impact& impact, const Skids& skids, Working& working) {
  const physics::WorldDef& world = impact.timeline.world();
  Step& given = stepOf(working, StepKind::kGiven);
  const int i = skids.striker, j = skids.struck;
  given.equations.push_back(equation(massSymbol(i), mass(world.bodies[std::size_t(i)].mass_kg)));
  given.equations.push_back(equation(massSymbol(j), mass(world.bodies[std::size_t(j)].mass_kg)));
  given.equations.push_back(
      equation(velocitySymbol(j), speed(0.0, impact.formats, text::Sign::kNegativeOnly)));
  given.equations.push_back(equation(restitutionSymbol(), plain(0.0)));
  given.equations.push_back(
      equation(frictionSymbol(), plain(world.bodies[std::size_t(i)].friction),
               // TRANSLATORS: a note beside μₖ in the working of a skid (accident reconstruction).
               text::tr("the coefficient of sliding friction")));
  given.equations.push_back(equation(plainSymbol("g"), amount(world.surface_gravity_mps2, "m/s²")));
  given.equations.push_back(
      equation(skidAfterSymbol(), amount(skids.after_m, "m"),
               // TRANSLATORS: a note beside d in the working of a skid: how far the locked bodies
               // slid after the impact, measured on the simulated run.
               text::tr("the skid after the impact, measured")));
  if (skids.before_m > 0.0) {
    given.equations.push_back(
        equation(skidBeforeSymbol(), amount(skids.before_m, "m"),
                 // TRANSLATORS: a note beside s in the working of a skid: how far the striking body
                 // slid with locked wheels before the impact, measured on the simulated run.
                 text::tr("the skid before the impact, measured")));
  }
}

void addLaws(const Skids& skids, Working& working) {
  const int i = skids.striker, j = skids.struck;
  const Math masses = text::fenced(sum(massSymbol(i), massSymbol(j)));
  const Math mu_g = juxtaposed({frictionSymbol(), plainSymbol("g")});
  Step& law = stepOf(working, StepKind::kLaw);
  law.equations.push_back(equation(
      juxtaposed({massSymbol(i), velocitySymbol(i)}), juxtaposed({masses, commonVelocitySymbol()}),
      // TRANSLATORS: a note beside m₁v₁ = (m₁ + m₂)v′ in the working of a skid.
      text::tr("momentum at the impact: they lock and move on together")));
  law.equations.push_back(
      equation(juxtaposed({half(), masses, squared(commonVelocitySymbol())}),
               juxtaposed({frictionSymbol(), masses, plainSymbol("g"), skidAfterSymbol()}),
               // TRANSLATORS: a note beside ½(m₁ + m₂)v′² = μₖ(m₁ + m₂)gd in the working of a skid.
               text::tr("friction's work over the skid d takes their kinetic energy")));
  if (skids.before_m > 0.0) {
    law.equations.push_back(equation(
        squared(startSymbol()),
        sum(squared(velocitySymbol(i)), juxtaposed({plain(2.0), mu_g, skidBeforeSymbol()})),
        // TRANSLATORS: a note beside v₀² = v₁² + 2μₖgs in the working of a skid.
        text::tr("before the impact, friction slowed it over the skid s")));
  }
  const Math reduced =
      text::fraction(juxtaposed({massSymbol(i), massSymbol(j)}), sum(massSymbol(i), massSymbol(j)));
  law.equations.push_back(equation(energyLostSymbol(),
                                   juxtaposed({half(), reduced, squared(velocitySymbol(i))}),
                                   text::tr("the energy lost")));
  Step& solved = stepOf(working, StepKind::kSolved);
  const Math from_skid = text::root(juxtaposed({plain(2.0), mu_g, skidAfterSymbol()}));
  solved.equations.push_back(equation(commonVelocitySymbol(), from_skid));
  solved.equations.push_back(
      equation(velocitySymbol(i),
               juxtaposed({text::fraction(sum(massSymbol(i), massSymbol(j)), massSymbol(i)),
                           text::op("·"), commonVelocitySymbol()})));
  if (skids.before_m > 0.0) {
    solved.equations.push_back(equation(
        startSymbol(), text::root(sum(squared(velocitySymbol(i)),
                                      juxtaposed({plain(2.0), mu_g, skidBeforeSymbol()})))));
  }
}

// The speeds the skids give, each from the one before.
struct Speeds {
  double common_mps = 0.0, striker_mps = 0.0, start_mps = 0.0;
};

void addNumbers(const Impact& impact, const Skids& skids, const Speeds& v, Working& working) {
  const physics::WorldDef& world = impact.timeline.world();
  const double m_i = world.bodies[std::size_t(skids.striker)].mass_kg;
  const double m_j = world.bodies[std::size_t(skids.struck)].mass_kg;
  const Math mu = plain(world.bodies[std::size_t(skids.striker)].friction);
  const Math g = amount(world.surface_gravity_mps2, "m/s²").parts[0];
  const auto length = [](double m) { return amount(m, "m").parts[0]; };
  const auto shown = [&](double mps) {
    return speed(mps, impact.formats, text::Sign::kNegativeOnly);
  };
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  numbers.equations.push_back(equation3(
      commonVelocitySymbol(), text::root(product({plain(2.0), mu, g, length(skids.after_m)})),
      shown(v.common_mps)));
  numbers.equations.push_back(
      equation3(velocitySymbol(skids.striker),
                product({text::fraction(sum(massValue(m_i), massValue(m_j)), massValue(m_i)),
                         speedValue(v.common_mps, impact.formats)}),
                shown(v.striker_mps)));
  if (skids.before_m > 0.0) {
    numbers.equations.push_back(
        equation3(startSymbol(),
                  text::root(sum(squared(speedValue(v.striker_mps, impact.formats)),
                                 product({plain(2.0), mu, g, length(skids.before_m)}))),
                  shown(v.start_mps)));
  }
  numbers.equations.push_back(equation3(
      energyLostSymbol(),
      product({half(),
               text::fraction(product({massValue(m_i), massValue(m_j)}),
                              sum(massValue(m_i), massValue(m_j))),
               squared(speedValue(v.striker_mps, impact.formats))}),
      energy(0.5 * m_i * m_j / (m_i + m_j) * v.striker_mps * v.striker_mps, impact.formats)));
}

}  // namespace

bool addSkid(const Impact& impact, Working& working) {
  const std::optional<Skids> skids = skidsOf(impact);
  if (!skids) return false;
  const physics::WorldDef& world = impact.timeline.world();
  const double mu_g =
      world.bodies[std::size_t(skids->striker)].friction * world.surface_gravity_mps2;
  const double m_i = world.bodies[std::size_t(skids->striker)].mass_kg;
  const double m_j = world.bodies[std::size_t(skids->struck)].mass_kg;
  Speeds v;
  v.common_mps = std::sqrt(2.0 * mu_g * skids->after_m);
  v.striker_mps = (m_i + m_j) / m_i * v.common_mps;
  v.start_mps = std::sqrt(v.striker_mps * v.striker_mps + 2.0 * mu_g * skids->before_m);
  addGiven(impact, *skids, working);
  addLaws(*skids, working);
  addNumbers(impact, *skids, v, working);
  const auto shown = [&](double mps) {
    return speed(mps, impact.formats, text::Sign::kNegativeOnly);
  };
  Step& result = stepOf(working, StepKind::kResult);
  if (skids->before_m > 0.0)
    result.equations.push_back(equation(startSymbol(), shown(v.start_mps)));
  result.equations.push_back(equation(velocitySymbol(skids->striker), shown(v.striker_mps)));
  result.equations.push_back(equation(commonVelocitySymbol(), shown(v.common_mps)));
  result.equations.push_back(energyChangeResult(impact));
  return true;
}

}  // namespace collide::working
