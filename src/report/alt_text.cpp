#include "report/alt_text.hpp"

#include <algorithm>
#include <cmath>

#include "physics/energy_books.hpp"
#include "report/plain_numbers.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::report {
namespace {

constexpr std::size_t kMaxBodiesInAltText = 8;  // beyond this the alt text gives totals only
constexpr int kFloorSamples = 400;              // samples searched for gravity's lowest level

// A position is a reading on the scene's scale: one number of decimals for every body.
std::string position(const core::Vec2& x_m, int dimensions, const text::QuantityFormat& length) {
  if (dimensions == 1) {
    return text::equation(text::symbol(text::Symbol::kPosition),
                          text::formatReading(x_m.x(), length));
  }
  text::QuantityFormat number = length;
  number.unit.clear();
  return text::numberPair(text::formatReading(x_m.x(), number),
                          text::formatReading(x_m.y(), number)) +
         " m";
}

// The parameter line is a record in English (its words are not translated), numbers included.
std::string englishNumber(double value) {
  return text::formatPlain(value, text::englishStyle());
}

std::string englishQuantity(double value, const std::string& unit) {
  return englishNumber(value) + " " + unit;
}

std::string englishVector(const core::Vec2& v, int dimensions, const std::string& unit) {
  if (dimensions == 1) return englishQuantity(v.x(), unit);
  return text::numberPair(englishNumber(v.x()), englishNumber(v.y()), text::englishStyle()) + " " +
         unit;
}

std::string count(std::size_t n) {
  return text::formatScaled(static_cast<long long>(n), 0);
}

enum class Setting { kPlane, kAirTrack, kTrack };

// "2 blocks slide on a horizontal track with 1 wall."
std::string sceneSentence(std::size_t bodies, std::size_t walls, Setting setting) {
  if (walls == 0) {
    const std::string sentence =
        setting == Setting::kPlane
            ? text::trn("{count} disk moves in a plane.", "{count} disks move in a plane.", bodies)
        : setting == Setting::kAirTrack
            ? text::trn("{count} glider rides on an air track.",
                        "{count} gliders ride on an air track.", bodies)
            : text::trn("{count} block slides on a horizontal track.",
                        "{count} blocks slide on a horizontal track.", bodies);
    return text::fill(sentence, {{"count", count(bodies)}});
  }
  // TRANSLATORS: {walls} is "with 1 wall" or "with 2 walls".
  const std::string with = text::fill(text::trn("with {count} wall", "with {count} walls", walls),
                                      {{"count", count(walls)}});
  const std::string sentence =
      setting == Setting::kPlane ? text::trn("{count} disk moves in a plane {walls}.",
                                             "{count} disks move in a plane {walls}.", bodies)
      : setting == Setting::kAirTrack
          ? text::trn("{count} glider rides on an air track {walls}.",
                      "{count} gliders ride on an air track {walls}.", bodies)
          : text::trn("{count} block slides on a horizontal track {walls}.",
                      "{count} blocks slide on a horizontal track {walls}.", bodies);
  return text::fill(sentence, {{"count", count(bodies)}, {"walls", with}});
}

// The format of positions: the scene's extent sets the decimals, so round-off (1e-16 m) reads 0.
text::QuantityFormat lengthFormat(const physics::WorldDef& world, const physics::Snapshot& now) {
  double extent = 0.0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    extent = std::max({extent, world.bodies[i].position_m.lpNorm<Eigen::Infinity>(),
                       now.bodies[i].position_m.lpNorm<Eigen::Infinity>(), world.bodies[i].size_m});
  }
  return text::quantityFormat(extent, "m");
}

// Gravity's lowest potential energy over the run (the energy bar counts from there), J.
double gravityFloor(const physics::Timeline& timeline) {
  if (timeline.world().gravity_mps2.squaredNorm() == 0.0) return 0.0;
  double lowest = INFINITY;
  auto visit = [&](double t) {
    lowest = std::min(lowest, timeline.potentialEnergy(timeline.sample(t)));
  };
  for (int k = 0; k <= kFloorSamples; ++k) visit(timeline.duration_s() * k / kFloorSamples);
  for (const physics::CollisionEvent& event : timeline.collisions()) visit(event.time_s);
  return lowest;
}

std::string barSentence(const physics::Timeline& timeline, double t_s);

constexpr int kMaxReleasesInAltText = 4;  // the first ones; the bar sums up all

// The releases (stored energy pushing two bodies apart) up to t_s, one sentence each, each after
// a sentence gap: what a still of spring-carts or recoil after the push shows.
std::string releaseSentences(const physics::Timeline& timeline, double t_s) {
  std::string text;
  int told = 0;
  const text::QuantityFormat time = text::quantityFormat(timeline.duration_s(), "s", 4);
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s > t_s || told == kMaxReleasesInAltText) break;
    if (!event.release) continue;
    const std::vector<physics::BodyDef>& bodies = timeline.world().bodies;
    // TRANSLATORS: a still's alt text; {time} is "t = 0.500 s", {energy} "3.00 J", {a} and {b}
    // the bodies' names.
    text += text::sentenceGap() +
            text::fill(text::tr("At {time} stored energy of {energy} pushed {a} and {b} apart."),
                       {{"time", text::equation(text::symbol(text::Symbol::kTime),
                                                text::formatReading(event.time_s, time))},
                        {"energy", amount(event.energy_released_J, "J")},
                        {"a", bodies[std::size_t(event.body_a)].name},
                        {"b", bodies[std::size_t(event.body_b)].name}});
    ++told;
  }
  return text;
}

// The paragraph of one scene (no title): bodies, collisions, the energy books.
std::string describeScene(const physics::Timeline& timeline, double t_s, bool gliders) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot now = timeline.sample(t_s);
  const bool line = world.dimensions == 1;
  std::string text = sceneSentence(world.bodies.size(), world.walls.size(),
                                   !line     ? Setting::kPlane
                                   : gliders ? Setting::kAirTrack
                                             : Setting::kTrack);
  if (world.bodies.size() <= kMaxBodiesInAltText) {
    const text::QuantityFormat length = lengthFormat(world, now);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      // TRANSLATORS: one body in a still's alt text: "cart 1 (1 kg) is at x = -2.00 m, moving
      // right at 2 m/s."
      text += text::sentenceGap() +
              text::sentenceStart(text::fill(
                  text::tr("{name} ({mass}) is at {position}, {motion}."),
                  {{"name", world.bodies[i].name},
                   {"mass", quantity(world.bodies[i].mass_kg, "kg")},
                   {"position", position(now.bodies[i].position_m, world.dimensions, length)},
                   {"motion", motionInWords(now.bodies[i].velocity_mps, world.dimensions)}}));
    }
    text += text::sentenceGap() + text::tr("An arrow on each moving body shows its velocity.");
  }
  text += releaseSentences(timeline, t_s);
  const int n = now.impactCount();  // releases are told as such, not as collisions
  text += text::sentenceGap() +
          (n == 0 ? text::tr("No collision has happened yet.")
                  : text::fill(text::trn("{count} collision has happened so far.",
                                         "{count} collisions have happened so far.",
                                         static_cast<unsigned long>(n)),
                               {{"count", count(static_cast<std::size_t>(n))}}));
  return text + text::sentenceGap() + barSentence(timeline, t_s);
}

// The energy bar in words: the books, the parts rounded together so that they add up to the
// total as written.
std::string barSentence(const physics::Timeline& timeline, double t_s) {
  const physics::WorldDef& world = timeline.world();
  const double floor = gravityFloor(timeline);
  const physics::EnergyBooks start = physics::energyBooks(timeline, 0.0, {0.0, 0.0}, floor);
  const physics::EnergyBooks books = physics::energyBooks(timeline, t_s, {0.0, 0.0}, floor);
  const bool gravity = world.gravity_mps2.squaredNorm() > 0.0;
  // Where energy comes in, the bar stands for the largest total the scene reaches: the start's
  // and all that is released; the parts add up to the start's and what is released so far.
  const bool releases = physics::canReleaseEnergy(world);
  const double total = start.total_J() + (releases ? timeline.totalEnergyReleased() : 0.0);
  const text::QuantityFormat energy = text::quantityFormat(total, "J");
  // Sliding friction's and air drag's work are heat too: with the impacts' losses in one part.
  // Molecules with insides hold a part inside them (internal energy), last.
  const bool insides = world.internal_dof > 0;
  std::vector<double> parts = {books.kineticTotal_J(), gravity ? books.gravity_J : 0.0,
                               books.springTotal_J(), books.lost_J + books.surface_J + books.air_J,
                               insides ? books.internal_J : 0.0};
  for (double& part : parts) part = std::max(0.0, part);
  const std::vector<std::string> shown =
      text::formatParts(parts, start.total_J() + books.released_J, energy);
  std::vector<std::string> shares = {
      text::fill(text::tr("{energy} of kinetic energy"), {{"energy", shown[0]}})};
  if (gravity) {
    shares.push_back(
        text::fill(text::tr("{energy} of potential energy above the lowest point reached"),
                   {{"energy", shown[1]}}));
  }
  if (!books.springs.empty()) {
    shares.push_back(
        text::fill(text::tr("{energy} stored in the compressed spring"), {{"energy", shown[2]}}));
  }
  if (insides) {
    // TRANSLATORS: a part of the energy bar's description for a gas whose molecules carry energy
    // inside them (rotation, vibration): "1.20 J held inside the molecules as internal energy".
    shares.push_back(text::fill(text::tr("{energy} held inside the molecules as internal energy"),
                                {{"energy", shown[4]}}));
  }
  const bool lost = total > 0.0 && !text::readsZero(parts[3], energy);
  // TRANSLATORS: {percent} is "67.5%".
  shares.push_back(lost
                       ? text::fill(text::tr("{energy} ({percent}) turned into heat and "
                                             "deformation so far"),
                                    {{"energy", shown[3]},
                                     {"percent", text::formatValue(100.0 * parts[3] / total, "%")}})
                       : text::tr("no energy lost"));
  if (releases) {
    // TRANSLATORS: a part of the energy bar's description where stored energy comes in (a
    // spring let go, a shot, e > 1): "3.00 J released from stored energy so far".
    shares.push_back(text::fill(text::tr("{energy} released from stored energy so far"),
                                {{"energy", text::formatQuantity(books.released_J, energy)}}));
  }
  std::string sentence;
  if (releases) {
    // TRANSLATORS: {parts} lists the energy bar's parts and what was released: "2.00 J of
    // kinetic energy, no energy lost and 3.00 J released from stored energy so far".
    sentence = text::tr(
        "The energy bar, whose full length stands for the {total} of energy at "
        "the start and released, shows {parts}.");
  } else if (gravity) {
    // TRANSLATORS: {parts} lists the energy bar's parts: "1.50 J of kinetic energy and 0.500 J
    // (25%) turned into heat and deformation so far".
    sentence = text::tr(
        "The energy bar, whose full length stands for the {total} of kinetic and "
        "potential energy at the start, shows {parts}.");
  } else {
    sentence = text::tr(
        "The energy bar, whose full length stands for the {total} of kinetic "
        "energy at the start, shows {parts}.");
  }
  return text::fill(sentence, {{"total", text::formatQuantity(total, energy)},
                               {"parts", text::listWithAnd(shares)}});
}

}  // namespace

std::string describeStill(const physics::Timeline& timeline, const std::string& title, double t_s,
                          bool gliders) {
  return describePanels({{"", &timeline, gliders}}, title, t_s);
}

std::string describePanels(const std::vector<PanelDescription>& panels, const std::string& title,
                           double t_s) {
  const physics::Timeline& first = *panels.front().timeline;
  const text::QuantityFormat time = text::quantityFormat(first.duration_s(), "s", 4);
  const std::string at =
      text::equation(text::symbol(text::Symbol::kTime), text::formatReading(t_s, time));
  std::string text =
      title.empty()
          ? text::fill(text::tr("Still image at {time} of a collision simulation."), {{"time", at}})
          : text::fill(text::tr("Still image at {time} of a collision simulation (\"{title}\")."),
                       {{"time", at}, {"title", title}});
  if (panels.size() == 1 && panels.front().heading.empty()) {
    return text + text::sentenceGap() + describeScene(first, t_s, panels.front().gliders);
  }
  std::vector<std::string> headings;
  for (const PanelDescription& panel : panels) headings.push_back(panel.heading);
  text += text::sentenceGap() +
          text::fill(text::trn("{count} panel compares {headings}.",
                               "{count} panels compare {headings}.", panels.size()),
                     {{"count", count(panels.size())}, {"headings", text::listWithAnd(headings)}});
  for (const PanelDescription& panel : panels) {
    // TRANSLATORS: {heading} is the panel's parameter, "e = 0.5"; {description} the sentences.
    text += text::sentenceGap() +
            text::fill(text::tr("Panel {heading}: {description}"),
                       {{"heading", panel.heading},
                        {"description", describeScene(*panel.timeline, t_s, panel.gliders)}});
  }
  return text;
}

std::string describeParameters(const physics::Timeline& timeline) {
  const physics::WorldDef& world = timeline.world();
  std::string text = std::to_string(world.dimensions) +
                     "D; e = " + englishNumber(world.restitution) + "; duration " +
                     englishQuantity(world.duration_s, "s");
  if (world.gravity_mps2.norm() > 0.0) {
    text += "; gravity " + englishVector(world.gravity_mps2, world.dimensions, "m/s²");
  }
  // Typed values, written as typed (three figures, no trailing zeros).
  auto typed = [&](const core::Vec2& x_m) {
    return world.dimensions == 1 ? "x = " + englishQuantity(x_m.x(), "m")
                                 : englishVector(x_m, world.dimensions, "m");
  };
  for (const physics::BodyDef& body : world.bodies) {
    text += "; " + body.name + ": " + englishQuantity(body.mass_kg, "kg") + ", " +
            (body.shape == physics::Shape::kDisk ? "radius " : "") +
            englishQuantity(body.size_m, "m") +
            (body.shape == physics::Shape::kDisk ? "" : " wide") + ", " + typed(body.position_m) +
            ", v = " + englishVector(body.velocity_mps, world.dimensions, "m/s");
  }
  for (const physics::WallDef& wall : world.walls) {
    text += "; wall " + wall.name + ": at " + typed(wall.point_m) +
            ", e = " + englishNumber(wall.restitution);
  }
  return text;
}

}  // namespace collide::report
