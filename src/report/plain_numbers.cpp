#include "report/plain_numbers.hpp"

#include <cmath>
#include <cstdio>

#include "text/number_format.hpp"
#include "text/translate.hpp"

namespace collide::report {

std::string plainNumber(double value) {
  return text::formatPlain(value);
}

std::string quantity(double value, const std::string& unit) {
  return plainNumber(value) + " " + unit;
}

std::string amount(double value, const std::string& unit) {
  return text::formatValue(value, unit);
}

std::string percentOf(double part, double whole) {
  if (whole == 0.0) return text::formatValue(0.0, "%");
  return text::formatQuantity(100.0 * part / whole, text::quantityFormat(100.0, "%"));
}

std::string motionInWords(const core::Vec2& velocity_mps, int dimensions) {
  const double speed = dimensions == 1 ? std::fabs(velocity_mps.x()) : velocity_mps.norm();
  // Below half a millimetre per second the arrow is invisible and "at rest" is what one sees.
  if (speed < 5e-4) return text::tr("at rest");
  if (dimensions == 1) {
    return text::fill(velocity_mps.x() > 0 ? text::tr("moving right at {speed}")
                                           : text::tr("moving left at {speed}"),
                      {{"speed", amount(speed, "m/s")}});
  }
  // TRANSLATORS: {direction} is an angle from the x axis, "30°".
  return text::fill(
      text::tr("moving at {speed} towards {direction}"),
      {{"speed", amount(speed, "m/s")},
       {"direction",
        text::formatAngle(std::atan2(velocity_mps.y(), velocity_mps.x()) * 180.0 / M_PI)}});
}

std::string partnerName(const physics::Timeline& timeline, int partner) {
  if (partner >= 0) return timeline.world().bodies.at(static_cast<std::size_t>(partner)).name;
  const int wall = physics::kWallPartnerBase - partner;
  return text::fill(text::tr("the wall \"{name}\""),
                    {{"name", timeline.world().walls.at(static_cast<std::size_t>(wall)).name}});
}

double pairKineticEnergyBefore(const physics::Timeline& timeline,
                               const physics::CollisionEvent& event) {
  const auto& bodies = timeline.world().bodies;
  double energy = 0.5 * bodies.at(static_cast<std::size_t>(event.body_a)).mass_kg *
                  event.velocity_a_before_mps.squaredNorm();
  if (!event.hitsWall()) {
    energy += 0.5 * bodies.at(static_cast<std::size_t>(event.body_b)).mass_kg *
              event.velocity_b_before_mps.squaredNorm();
  }
  return energy;
}

}  // namespace collide::report
