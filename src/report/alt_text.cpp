#include "report/alt_text.hpp"

#include <algorithm>
#include <cmath>

#include "physics/energy_books.hpp"
#include "report/plain_numbers.hpp"
#include "text/number_format.hpp"

namespace collide::report {
namespace {

constexpr std::size_t kMaxBodiesInAltText = 8;  // beyond this the alt text gives totals only
constexpr int kFloorSamples = 400;              // samples searched for gravity's lowest level

// A position is a reading on the scene's scale: one number of decimals for every body.
std::string position(const core::Vec2& x_m, int dimensions, const text::QuantityFormat& length) {
  if (dimensions == 1) return "x = " + text::formatReading(x_m.x(), length);
  text::QuantityFormat number = length;
  number.unit.clear();
  return "(" + text::formatReading(x_m.x(), number) + ", " + text::formatReading(x_m.y(), number) +
         ") m";
}

std::string vector(const core::Vec2& v, int dimensions, const std::string& unit) {
  if (dimensions == 1) return quantity(v.x(), unit);
  return "(" + plainNumber(v.x()) + ", " + plainNumber(v.y()) + ") " + unit;
}

// "1 block slides", "3 disks move".
std::string counted(std::size_t n, const std::string& one, const std::string& many,
                    const std::string& verb_one, const std::string& verb_many) {
  return std::to_string(n) + " " + (n == 1 ? one + " " + verb_one : many + " " + verb_many);
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

// The paragraph of one scene (no title): bodies, collisions, the energy books.
std::string describeScene(const physics::Timeline& timeline, double t_s, bool gliders) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot now = timeline.sample(t_s);
  const bool line = world.dimensions == 1;
  const std::size_t n_bodies = world.bodies.size();
  std::string text =
      !line ? counted(n_bodies, "disk", "disks", "moves", "move") + " in a plane"
      : gliders
          ? counted(n_bodies, "glider", "gliders", "rides", "ride") + " on an air track"
          : counted(n_bodies, "block", "blocks", "slides", "slide") + " on a horizontal track";
  if (!world.walls.empty()) {
    text += " with " + std::to_string(world.walls.size()) +
            (world.walls.size() == 1 ? " wall" : " walls");
  }
  text += ".";
  if (world.bodies.size() <= kMaxBodiesInAltText) {
    const text::QuantityFormat length = lengthFormat(world, now);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      text += " " + world.bodies[i].name + " (" + quantity(world.bodies[i].mass_kg, "kg") +
              ") is at " + position(now.bodies[i].position_m, world.dimensions, length) + ", " +
              motionInWords(now.bodies[i].velocity_mps, world.dimensions) + ".";
    }
    text += " An arrow on each moving body shows its velocity.";
  }
  const int n = now.collision_count;
  text += n == 0 ? " No collision has happened yet."
                 : " " + std::to_string(n) + (n == 1 ? " collision has" : " collisions have") +
                       " happened so far.";

  // The books: the parts are rounded together so that they add up to the total as written.
  const double floor = gravityFloor(timeline);
  const physics::EnergyBooks start = physics::energyBooks(timeline, 0.0, {0.0, 0.0}, floor);
  const physics::EnergyBooks books = physics::energyBooks(timeline, t_s, {0.0, 0.0}, floor);
  const bool gravity = world.gravity_mps2.squaredNorm() > 0.0;
  const double total = start.total_J();
  const text::QuantityFormat energy = text::quantityFormat(total, "J");
  std::vector<double> parts = {books.kineticTotal_J(), gravity ? books.gravity_J : 0.0,
                               books.springTotal_J(), books.lost_J};
  for (double& part : parts) part = std::max(0.0, part);
  const std::vector<std::string> shown = text::formatParts(parts, total, energy);
  auto joule = [&](std::size_t k) { return shown[k]; };
  text += " The energy bar, whose full length stands for the " +
          text::formatQuantity(total, energy) + " of " +
          (gravity ? "kinetic and potential energy" : "kinetic energy") + " at the start, shows " +
          joule(0) + " of kinetic energy";
  if (gravity) text += ", " + joule(1) + " of potential energy above the lowest point reached";
  if (!books.springs.empty()) text += ", " + joule(2) + " stored in the compressed spring";
  const bool lost = total > 0.0 && !text::readsZero(parts[3], energy);
  text += lost ? " and " + joule(3) + " (" + text::formatValue(100.0 * parts[3] / total, "%") +
                     ") turned into heat and deformation so far."
               : " and no energy lost.";
  return text;
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
  std::string text =
      "Still image at t = " + text::formatReading(t_s, time) + " of a collision simulation";
  text += title.empty() ? "" : " (\"" + title + "\")";
  text += ".";
  if (panels.size() == 1 && panels.front().heading.empty()) {
    return text + " " + describeScene(first, t_s, panels.front().gliders);
  }
  text += " " + std::to_string(panels.size()) + " panels compare ";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    text += (p == 0 ? "" : p + 1 == panels.size() ? " and " : ", ") + panels[p].heading;
  }
  text += ".";
  for (const PanelDescription& panel : panels) {
    text += " Panel " + panel.heading + ": " + describeScene(*panel.timeline, t_s, panel.gliders);
  }
  return text;
}

std::string describeParameters(const physics::Timeline& timeline) {
  const physics::WorldDef& world = timeline.world();
  std::string text = std::to_string(world.dimensions) + "D; e = " + plainNumber(world.restitution) +
                     "; duration " + quantity(world.duration_s, "s");
  if (world.gravity_mps2.norm() > 0.0) {
    text += "; gravity " + vector(world.gravity_mps2, world.dimensions, "m/s²");
  }
  // Typed values, written as typed (three figures, no trailing zeros).
  auto typed = [&](const core::Vec2& x_m) {
    return world.dimensions == 1 ? "x = " + quantity(x_m.x(), "m")
                                 : vector(x_m, world.dimensions, "m");
  };
  for (const physics::BodyDef& body : world.bodies) {
    text += "; " + body.name + ": " + quantity(body.mass_kg, "kg") + ", " +
            (body.shape == physics::Shape::kDisk ? "radius " : "") + quantity(body.size_m, "m") +
            (body.shape == physics::Shape::kDisk ? "" : " wide") + ", " + typed(body.position_m) +
            ", v = " + vector(body.velocity_mps, world.dimensions, "m/s");
  }
  for (const physics::WallDef& wall : world.walls) {
    text += "; wall " + wall.name + ": at " + typed(wall.point_m) +
            ", e = " + plainNumber(wall.restitution);
  }
  return text;
}

}  // namespace collide::report
