// SPDX-License-Identifier: MIT
// What some kinds of scene add to a working: Newton's cradle (equal masses exchange velocities),
// the pi-blocks' count (N = ⌈π/θ⌉ − 1), a soft contact's impulse (J = ∫F dt = Δp) and an e
// that falls with the impact speed.
#include <cmath>
#include <numbers>
#include <utility>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

Math angleSymbol() {
  return plainSymbol("θ");
}
Math countSymbol() {
  return plainSymbol("N");
}
Math impulseSymbol() {
  return plainSymbol("J");
}

// The body of the two nearer to the wall: it sits between the wall and the other.
int nearerToWall(const physics::Timeline& timeline) {
  const physics::WorldDef& world = timeline.world();
  const double wall_x = world.walls[0].point_m.x();
  const double d0 = std::fabs(world.bodies[0].position_m.x() - wall_x);
  const double d1 = std::fabs(world.bodies[1].position_m.x() - wall_x);
  return d0 <= d1 ? 0 : 1;
}

// The impulse the force of a soft contact gave: the area under its samples (trapezoids).
double forceIntegral(const physics::SoftContact& contact) {
  double area_Ns = 0.0;
  for (std::size_t k = 1; k < contact.samples.size(); ++k) {
    const physics::ContactForceSample& a = contact.samples[k - 1];
    const physics::ContactForceSample& b = contact.samples[k];
    area_Ns += 0.5 * (a.force_N + b.force_N) * (b.time_s - a.time_s);
  }
  return area_Ns;
}

const physics::SoftContact* softContactOf(const Impact& impact) {
  for (const physics::SoftContact& contact : impact.timeline.softContacts()) {
    if (contact.collision_index == impact.event.index) return &contact;
  }
  return nullptr;
}

}  // namespace

void addCradle(const Impact& impact, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  const std::vector<physics::BodyDef>& bodies = impact.timeline.world().bodies;
  if (event.restitution != 1.0 ||
      bodies[std::size_t(event.body_a)].mass_kg != bodies[std::size_t(event.body_b)].mass_kg) {
    return;
  }
  Step& law = stepOf(working, StepKind::kLaw);
  const int i = event.body_a, j = event.body_b;
  law.equations.push_back(
      equation(velocitySymbol(i, 1, "n"), velocitySymbol(j, 0, "n"),
               // TRANSLATORS: a note in the working of Newton's cradle, beside v₁′ = v₂.
               text::tr("equal masses, e = 1: the velocities are exchanged, so the impulse "
                        "passes along the row")));
  law.equations.push_back(equation(velocitySymbol(j, 1, "n"), velocitySymbol(i, 0, "n")));
}

void addPiBlocks(const Impact& impact, Working& working) {
  const physics::WorldDef& world = impact.timeline.world();
  const int inner = nearerToWall(impact.timeline), outer = 1 - inner;
  const double ratio =
      world.bodies[std::size_t(inner)].mass_kg / world.bodies[std::size_t(outer)].mass_kg;
  const double theta_rad = std::atan(std::sqrt(ratio));
  const auto count = static_cast<long long>(std::ceil(std::numbers::pi / theta_rad)) - 1;
  Step& law = stepOf(working, StepKind::kLaw);
  const Math arctan = text::word("arctan");
  law.equations.push_back(equation(
      angleSymbol(),
      text::row({arctan, text::root(text::fraction(massSymbol(inner), massSymbol(outer)))}),
      // TRANSLATORS: a note in the pi-blocks' working, beside θ = arctan √(m₁/m₂).
      text::tr("each collision with the block turns the state on the energy circle by "
               "2θ")));
  const Math ceiling = text::fenced(text::fraction(plainSymbol("π"), angleSymbol()), "⌈", "⌉");
  law.equations.push_back(equation(countSymbol(), difference(ceiling, plain(1.0)),
                                   // TRANSLATORS: a note in the pi-blocks' working, beside
                                   // N = ⌈π/θ⌉ − 1.
                                   text::tr("collisions until the blocks part for good")));
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  numbers.equations.push_back(equation3(
      angleSymbol(),
      text::row({arctan,
                 text::root(text::fraction(massValue(world.bodies[std::size_t(inner)].mass_kg),
                                           massValue(world.bodies[std::size_t(outer)].mass_kg)))}),
      withUnit(plain(theta_rad, 6), "rad")));
  const Math shown_ceiling =
      text::fenced(text::fraction(plainSymbol("π"), plain(theta_rad, 6)), "⌈", "⌉");
  numbers.equations.push_back(equation3(countSymbol(), difference(shown_ceiling, plain(1.0)),
                                        text::number(text::formatScaled(count, 0))));
  stepOf(working, StepKind::kResult)
      .equations.push_back(equation(countSymbol(), text::number(text::formatScaled(count, 0))));
}

void addSoftContact(const Impact& impact, Working& working) {
  addTwoBodies(impact, working);
  const physics::SoftContact* contact = softContactOf(impact);
  if (contact == nullptr) return;
  const physics::CollisionEvent& event = impact.event;
  const int j = event.body_b;
  const double m_j = impact.timeline.world().bodies[std::size_t(j)].mass_kg;
  const double along_before = event.velocity_b_before_mps.dot(event.normal);
  const double along_after = event.velocity_b_after_mps.dot(event.normal);
  Step& law = stepOf(working, StepKind::kLaw);
  const Math force = plainSymbol(text::symbol(text::Symbol::kForce));
  const Math integral = text::row(
      {text::op("∫"), force, text::word("d"), plainSymbol(text::symbol(text::Symbol::kTime))});
  law.equations.push_back(
      equation3(impulseSymbol(), integral,
                juxtaposed({massSymbol(j),
                            text::fenced(difference(velocitySymbol(j, 1), velocitySymbol(j)))}),
                // TRANSLATORS: a note beside J = ∫F dt = m₂(v₂′ − v₂) in a soft contact's working.
                text::tr("the impulse: the area under the force curve is the change of momentum")));
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  numbers.equations.push_back(equation(
      integral, amount(forceIntegral(*contact), "N·s"),
      // TRANSLATORS: a note beside ∫F dt in a soft contact's working: the force was sampled.
      text::tr("summed over the simulated force")));
  numbers.equations.push_back(equation3(
      juxtaposed(
          {massSymbol(j), text::fenced(difference(velocitySymbol(j, 1), velocitySymbol(j)))}),
      product({massValue(m_j), text::fenced(difference(speedValue(along_after, impact.formats),
                                                       speedValue(along_before, impact.formats)))}),
      amount(m_j * (along_after - along_before), "N·s")));
  stepOf(working, StepKind::kResult)
      .equations.push_back(
          equation(impulseSymbol(), amount(m_j * (along_after - along_before), "N·s")));
}

void addRestitutionLaw(const Impact& impact, Working& working) {
  const physics::WorldDef& world = impact.timeline.world();
  const physics::RestitutionModel& model = world.restitution_model;
  const physics::CollisionEvent& event = impact.event;
  if (model.law != physics::RestitutionLaw::kSpeedThreshold ||
      !(event.closing_speed_mps > model.threshold_speed_mps) ||
      event.restitution_requested <= 0.0) {
    return;
  }
  // e = e0 (u_y / u)^k above the yield speed, so e0 is the requested e scaled back.
  const double ratio = model.threshold_speed_mps / event.closing_speed_mps;
  const double base_e = event.restitution_requested / std::pow(ratio, model.exponent);
  const Math e0 = text::scripts(restitutionSymbol(), text::row({text::number("0")}));
  const Math yield = text::scripts(plainSymbol("u"), text::row({text::word("y")}));
  const Math power = text::row({plain(model.exponent)});
  Equation law = equation3(
      restitutionSymbol(),
      juxtaposed(
          {e0, text::scripts(text::fenced(text::fraction(yield, plainSymbol("u"))), {}, power)}),
      product({plain(base_e),
               text::scripts(text::fenced(text::fraction(plain(model.threshold_speed_mps),
                                                         plain(event.closing_speed_mps))),
                             {}, power)}),
      // TRANSLATORS: a note beside e = e₀(u_y/u)^k in a working: e falls with the impact
      // speed above the yield speed u_y.
      text::tr("e falls with the impact speed u above the yield speed"));
  law.sides.push_back(plain(event.restitution));
  // In place of the given "e = 0.0980": the same value, with where it comes from.
  Step& given = stepOf(working, StepKind::kGiven);
  for (Equation& line : given.equations) {
    if (line.sides.size() == 2 && line.sides[0].text == restitutionSymbol().text &&
        line.sides[0].kind == text::MathKind::kSymbol) {
      line = std::move(law);
      return;
    }
  }
  given.equations.push_back(std::move(law));
}

}  // namespace collide::working
