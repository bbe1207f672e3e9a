// SPDX-License-Identifier: MIT
// The ballistic pendulum: momentum at the impact (the bullet sticks in the block), then energy on
// the rise, v = (m_block + m_bullet)/m_bullet · √(2gh), with h measured on the simulated swing.
#include <cmath>
#include <utility>

#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

using text::Math;

constexpr int kScanSteps = 400;   // samples of the swing before refining its top
constexpr int kRefineSteps = 60;  // golden-section steps: far below a micrometre
constexpr double kGolden = 0.6180339887498949;

double heightAt(const physics::Timeline& timeline, int body, const core::Vec2& up, double t_s) {
  return timeline.sample(t_s).bodies[std::size_t(body)].position_m.dot(up);
}

// The highest point of the block's first swing after the impact, above where it was struck.
double riseOf(const physics::Timeline& timeline, int block, double impact_s) {
  const core::Vec2 up = -timeline.world().gravity_mps2.normalized();
  const double start_m = heightAt(timeline, block, up, impact_s);
  const double step_s = (timeline.simulatedUntil_s() - impact_s) / kScanSteps;
  double best_t = impact_s, best_m = start_m;
  for (int k = 1; k <= kScanSteps; ++k) {
    const double t = impact_s + k * step_s;
    const double h = heightAt(timeline, block, up, t);
    if (h < best_m) break;  // past the top of the first swing
    best_t = t;
    best_m = h;
  }
  double low = std::max(impact_s, best_t - step_s), high = best_t + step_s;
  for (int k = 0; k < kRefineSteps; ++k) {
    const double a = high - kGolden * (high - low), b = low + kGolden * (high - low);
    if (heightAt(timeline, block, up, a) < heightAt(timeline, block, up, b)) {
      low = a;
    } else {
      high = b;
    }
  }
  return std::max(best_m, heightAt(timeline, block, up, 0.5 * (low + high))) - start_m;
}

Math heightSymbol() {
  return plainSymbol("h");
}

void addLaws(int block, int bullet, Working& working) {
  Step& law = stepOf(working, StepKind::kLaw);
  const Math masses = text::fenced(sum(massSymbol(block), massSymbol(bullet)));
  law.equations.push_back(
      equation(juxtaposed({massSymbol(bullet), velocitySymbol(bullet)}),
               juxtaposed({masses, commonVelocitySymbol()}),
               // TRANSLATORS: a note beside m₂v₂ = (m₁ + m₂)v′ in the ballistic pendulum's working.
               text::tr("momentum at the impact: the bullet stays in the block")));
  law.equations.push_back(equation(
      juxtaposed({half(), masses, squared(commonVelocitySymbol())}),
      juxtaposed({masses, plainSymbol("g"), heightSymbol()}),
      // TRANSLATORS: a note beside ½(m₁ + m₂)v′² = (m₁ + m₂)gh in the ballistic pendulum's working.
      text::tr("energy on the rise to the height h")));
  const Math reduced = text::fraction(juxtaposed({massSymbol(block), massSymbol(bullet)}),
                                      sum(massSymbol(block), massSymbol(bullet)));
  law.equations.push_back(equation(energyLostSymbol(),
                                   juxtaposed({half(), reduced, squared(velocitySymbol(bullet))}),
                                   text::tr("the energy lost")));
  Step& solved = stepOf(working, StepKind::kSolved);
  const Math rise = text::root(juxtaposed({plain(2.0), plainSymbol("g"), heightSymbol()}));
  solved.equations.push_back(equation(commonVelocitySymbol(), rise));
  solved.equations.push_back(equation(
      velocitySymbol(bullet),
      juxtaposed({text::fraction(sum(massSymbol(block), massSymbol(bullet)), massSymbol(bullet)),
                  text::op("·"), rise})));
}

}  // namespace

void addBallisticPendulum(const Impact& impact, Working& working) {
  const physics::CollisionEvent& event = impact.event;
  const std::vector<physics::BodyDef>& bodies = impact.timeline.world().bodies;
  const bool a_hangs = bodies[std::size_t(event.body_a)].on_string;
  const int block = a_hangs ? event.body_a : event.body_b;
  const int bullet = a_hangs ? event.body_b : event.body_a;
  const double m_block = bodies[std::size_t(block)].mass_kg;
  const double m_bullet = bodies[std::size_t(bullet)].mass_kg;
  const double g = impact.timeline.world().gravity_mps2.norm();
  const double h_m = riseOf(impact.timeline, block, event.time_s);
  Step& given = stepOf(working, StepKind::kGiven);
  given.equations.push_back(equation(massSymbol(block), mass(m_block)));
  given.equations.push_back(equation(massSymbol(bullet), mass(m_bullet)));
  given.equations.push_back(equation(plainSymbol("g"), amount(g, "m/s²")));
  given.equations.push_back(equation(heightSymbol(), amount(h_m, "m"),
                                     // TRANSLATORS: a note beside h in the ballistic pendulum's
                                     // working: the height measured on the simulated swing.
                                     text::tr("the rise of the block, measured")));
  addLaws(block, bullet, working);
  const double common_mps = std::sqrt(2.0 * g * h_m);
  const double bullet_mps = (m_block + m_bullet) / m_bullet * common_mps;
  Step& numbers = stepOf(working, StepKind::kSubstituted);
  const Math g_value = amount(g, "m/s²").parts[0];
  numbers.equations.push_back(equation3(
      commonVelocitySymbol(), text::root(product({plain(2.0), g_value, amount(h_m, "m").parts[0]})),
      speed(common_mps, impact.formats, text::Sign::kNegativeOnly)));
  numbers.equations.push_back(equation3(
      velocitySymbol(bullet),
      product({text::fraction(sum(massValue(m_block), massValue(m_bullet)), massValue(m_bullet)),
               speedValue(common_mps, impact.formats)}),
      speed(bullet_mps, impact.formats, text::Sign::kNegativeOnly)));
  const double mu_kg = m_block * m_bullet / (m_block + m_bullet);
  numbers.equations.push_back(
      equation3(energyLostSymbol(),
                product({half(),
                         text::fraction(product({massValue(m_block), massValue(m_bullet)}),
                                        sum(massValue(m_block), massValue(m_bullet))),
                         squared(speedValue(bullet_mps, impact.formats))}),
                energy(0.5 * mu_kg * bullet_mps * bullet_mps, impact.formats)));
  Step& result = stepOf(working, StepKind::kResult);
  result.equations.push_back(equation(
      velocitySymbol(bullet), speed(bullet_mps, impact.formats, text::Sign::kNegativeOnly)));
  result.equations.push_back(equation(
      commonVelocitySymbol(), speed(common_mps, impact.formats, text::Sign::kNegativeOnly)));
  result.equations.push_back(
      equation(energyLostSymbol(), energy(event.energy_lost_J, impact.formats)));
}

}  // namespace collide::working
