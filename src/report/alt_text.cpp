#include "report/alt_text.hpp"

#include "report/plain_numbers.hpp"

namespace collide::report {
namespace {

constexpr std::size_t kMaxBodiesInAltText = 8;  // beyond this the alt text gives totals only

std::string position(const core::Vec2& x_m, int dimensions) {
  if (dimensions == 1) return "x = " + quantity(x_m.x(), "m");
  return "(" + plainNumber(x_m.x()) + ", " + plainNumber(x_m.y()) + ") m";
}

std::string vector(const core::Vec2& v, int dimensions, const std::string& unit) {
  if (dimensions == 1) return quantity(v.x(), unit);
  return "(" + plainNumber(v.x()) + ", " + plainNumber(v.y()) + ") " + unit;
}

}  // namespace

std::string describeStill(const physics::Timeline& timeline, const std::string& title, double t_s) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot now = timeline.sample(t_s);
  const bool line = world.dimensions == 1;
  std::string text = "Still image at t = " + quantity(t_s, "s") + " of a collision simulation";
  text += title.empty() ? "" : " (\"" + title + "\")";
  text += ". ";
  text += line ? std::to_string(world.bodies.size()) + " blocks slide on a horizontal track"
               : std::to_string(world.bodies.size()) + " disks move in a plane";
  if (!world.walls.empty()) {
    text += " with " + std::to_string(world.walls.size()) +
            (world.walls.size() == 1 ? " wall" : " walls");
  }
  text += ".";
  if (world.bodies.size() <= kMaxBodiesInAltText) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      text += " " + world.bodies[i].name + " (" + quantity(world.bodies[i].mass_kg, "kg") +
              ") is at " + position(now.bodies[i].position_m, world.dimensions) + ", " +
              motionInWords(now.bodies[i].velocity_mps, world.dimensions) + ".";
    }
    text += " An arrow on each moving body shows its velocity.";
  }
  const int n = now.collision_count;
  text += n == 0 ? " No collision has happened yet."
                 : " " + std::to_string(n) + (n == 1 ? " collision has" : " collisions have") +
                       " happened so far.";
  const double ke0 = timeline.initialKineticEnergy();
  const double ke = timeline.kineticEnergy(now);
  text += " The energy bar, whose full length stands for the " + quantity(ke0, "J") +
          " of kinetic energy at the start, shows " + quantity(ke, "J") + " of kinetic energy";
  text += now.energy_lost_J > 0.0
              ? " and " + quantity(now.energy_lost_J, "J") + " (" +
                    percentOf(now.energy_lost_J, ke0) + ") turned into heat and deformation."
              : " and no energy lost.";
  return text;
}

std::string describeParameters(const physics::Timeline& timeline) {
  const physics::WorldDef& world = timeline.world();
  std::string text = std::to_string(world.dimensions) + "D; e = " + plainNumber(world.restitution) +
                     "; duration " + quantity(world.duration_s, "s");
  if (world.gravity_mps2.norm() > 0.0) {
    text += "; gravity " + vector(world.gravity_mps2, world.dimensions, "m/s²");
  }
  for (const physics::BodyDef& body : world.bodies) {
    text += "; " + body.name + ": " + quantity(body.mass_kg, "kg") + ", " +
            (body.shape == physics::Shape::kDisk ? "radius " : "") + quantity(body.size_m, "m") +
            (body.shape == physics::Shape::kDisk ? "" : " wide") + ", " +
            position(body.position_m, world.dimensions) +
            ", v = " + vector(body.velocity_mps, world.dimensions, "m/s");
  }
  for (const physics::WallDef& wall : world.walls) {
    text += "; wall " + wall.name + ": at " + position(wall.point_m, world.dimensions) +
            ", e = " + plainNumber(wall.restitution);
  }
  return text;
}

}  // namespace collide::report
