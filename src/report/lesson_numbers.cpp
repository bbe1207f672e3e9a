// SPDX-License-Identifier: MIT
// The lesson page's table of numbers (report/lesson_page.hpp's lessonNumbers).
#include "report/lesson_page.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"

namespace collide::report {

std::vector<LessonRow> lessonNumbers(const physics::Timeline& timeline) {
  const physics::Snapshot start = timeline.sample(0.0);
  const physics::Snapshot end = timeline.sample(timeline.duration_s());
  const double ke0 = timeline.kineticEnergy(start);
  const text::QuantityFormat energy = text::quantityFormat(ke0, "J");
  const core::Vec2 p0 = timeline.momentum(start), p1 = timeline.momentum(end);
  const text::QuantityFormat momentum_format =
      text::quantityFormat(std::max(p0.norm(), p1.norm()), "kg·m/s");
  const auto momentum = [&](const core::Vec2& p) {
    if (timeline.world().dimensions == 1) return text::formatQuantity(p.x(), momentum_format);
    return text::formatComponentsIn(p.x(), p.y(), momentum_format) + " kg·m/s";
  };
  return {
      // TRANSLATORS: a row of the lesson page's table of numbers.
      {text::trc("lesson page", "Collisions"),
       text::formatScaled(static_cast<long long>(timeline.collisionCount()), 0)},
      // TRANSLATORS: a row of the lesson page's table of numbers.
      {text::trc("lesson page", "Kinetic energy at the start"), text::formatQuantity(ke0, energy)},
      // TRANSLATORS: a row of the lesson page's table of numbers.
      {text::trc("lesson page", "Kinetic energy at the end"),
       text::formatQuantity(timeline.kineticEnergy(end), energy)},
      // TRANSLATORS: a row of the lesson page's table of numbers: kinetic energy turned into heat
      // and deformation by the collisions.
      {text::trc("lesson page", "Energy lost"), text::formatQuantity(end.energy_lost_J, energy)},
      // TRANSLATORS: a row of the lesson page's table of numbers.
      {text::trc("lesson page", "Total momentum at the start"), momentum(p0)},
      // TRANSLATORS: a row of the lesson page's table of numbers.
      {text::trc("lesson page", "Total momentum at the end"), momentum(p1)},
  };
}

}  // namespace collide::report
