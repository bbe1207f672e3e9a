#include "report/narration.hpp"

#include <algorithm>
#include <cmath>

#include "report/plain_numbers.hpp"
#include "text/number_format.hpp"

namespace collide::report {
namespace {

// Beyond this many bodies the opening cue gives totals instead of a sentence per body.
constexpr std::size_t kMaxBodiesInCue = 6;

// A time in the cues: one number of decimals for the whole video, as on its frames
// ("t = 1.167 s" ... "End, t = 4.000 s").
std::string timeReading(const physics::Timeline& timeline, double t_s) {
  return text::formatReading(t_s, text::quantityFormat(timeline.duration_s(), "s", 4));
}

std::string bodyWithMass(const physics::BodyDef& body) {
  return body.name + " (" + quantity(body.mass_kg, "kg") + ")";
}

std::string openingText(const physics::Timeline& timeline, const std::string& title) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot start = timeline.initialState();
  std::string text = title.empty() ? "" : title + ".\n";
  if (world.bodies.size() <= kMaxBodiesInCue) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      text += (i == 0 ? "" : "; ") + bodyWithMass(world.bodies[i]) + " is " +
              motionInWords(start.bodies[i].velocity_mps, world.dimensions);
    }
    text += ".\n";
  } else {
    text += std::to_string(world.bodies.size()) + " bodies.\n";
  }
  text += "Total kinetic energy " + amount(timeline.kineticEnergy(start), "J") + ".";
  return text;
}

std::string collisionText(const physics::Timeline& timeline, const physics::CollisionEvent& event) {
  const physics::WorldDef& world = timeline.world();
  const std::string& a = world.bodies.at(static_cast<std::size_t>(event.body_a)).name;
  std::string text = "t = " + timeReading(timeline, event.time_s) + ": " + a + " hits " +
                     partnerName(timeline, event.body_b) + " at a closing speed of " +
                     amount(event.closing_speed_mps, "m/s") +
                     " (e = " + plainNumber(event.restitution) + ").\n";
  const double before_J = pairKineticEnergyBefore(timeline, event);
  const double lost_J = std::max(0.0, event.energy_lost_J);
  if (lost_J <= 1e-12 * std::max(1.0, before_J)) {
    text += "No kinetic energy is lost: the collision is elastic.";
  } else {
    text += amount(lost_J, "J") + " of " + (event.hitsWall() ? "its " : "their ") +
            amount(before_J, "J") + " of kinetic energy (" + percentOf(lost_J, before_J) +
            ") turns into heat and deformation.";
  }
  if (event.merged && !event.hitsWall()) {
    text += "\nThey stick together, " +
            motionInWords(event.velocity_a_after_mps, world.dimensions) + ".";
  } else if (event.merged) {
    text += "\n" + a + " comes to rest against the wall.";
  } else {
    text +=
        "\nAfterwards " + a + " is " + motionInWords(event.velocity_a_after_mps, world.dimensions);
    if (!event.hitsWall()) {
      text += " and " + partnerName(timeline, event.body_b) + " is " +
              motionInWords(event.velocity_b_after_mps, world.dimensions);
    }
    text += ".";
  }
  return text;
}

std::string closingText(const physics::Timeline& timeline, double end_s) {
  const physics::Snapshot start = timeline.initialState();
  const physics::Snapshot end = timeline.sample(end_s);
  const double ke0 = timeline.kineticEnergy(start);
  const int n = end.collision_count;
  // Energies in the unit of the energy at the start, so the three compare at a glance.
  const text::QuantityFormat energy = text::quantityFormat(ke0, "J");
  const auto joules = [&](double value) { return text::formatQuantity(value, energy); };
  std::string text = "End, t = " + timeReading(timeline, end_s) + ": " + std::to_string(n) +
                     (n == 1 ? " collision" : " collisions") + ".\nKinetic energy " +
                     joules(timeline.kineticEnergy(end)) + " of " + joules(ke0) +
                     " at the start; " + joules(end.energy_lost_J) + " (" +
                     percentOf(end.energy_lost_J, ke0) + ") turned into heat and deformation.";
  const core::Vec2 p0 = timeline.momentum(start), p1 = timeline.momentum(end);
  const text::QuantityFormat momentum_format =
      text::quantityFormat(std::max(p0.norm(), p1.norm()), "kg·m/s");
  const auto momentum = [&](const core::Vec2& p) {
    if (timeline.world().dimensions == 1) return text::formatQuantity(p.x(), momentum_format);
    return "(" + text::formatIn(p.x(), momentum_format) + ", " +
           text::formatIn(p.y(), momentum_format) + ") kg·m/s";
  };
  const bool conserved = (p1 - p0).norm() <= 1e-9 * std::max(1.0, p0.norm());
  text += conserved ? "\nTotal momentum " + momentum(p0) + " before and after."
                    : "\nTotal momentum " + momentum(p0) + " at the start, " + momentum(p1) +
                          " at the end (walls or gravity act on the bodies).";
  return text;
}

struct Moment {
  double start_s;
  std::string text;
};

}  // namespace

std::vector<Cue> narrate(const physics::Timeline& timeline, const NarrationOptions& options) {
  const double end_s = options.end_s > 0.0 ? options.end_s : timeline.duration_s();
  std::vector<Moment> moments{{0.0, openingText(timeline, options.title)}};

  // Collisions within the video, grouped when they share an instant.
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  int groups = 0;
  std::size_t i = 0;
  while (i < events.size() && events[i].time_s <= end_s && groups < options.max_collision_cues) {
    const double t0 = events[i].time_s;
    std::string text;
    for (; i < events.size() && events[i].time_s - t0 < kSameInstantS; ++i) {
      if (!text.empty()) text += '\n';
      text += collisionText(timeline, events[i]);
    }
    if (t0 < kSameInstantS) {
      moments.front().text += "\n" + text;  // a collision at t = 0 joins the opening cue
    } else {
      moments.push_back({t0, text});
    }
    ++groups;
  }
  const int shown = static_cast<int>(i);
  const int in_video = timeline.sample(end_s).collision_count;
  if (in_video > shown) {
    const double t = i < events.size() ? events[i].time_s : moments.back().start_s + kSameInstantS;
    const int more = in_video - shown;
    const std::string line = std::to_string(more) + " more " +
                             (more == 1 ? "collision follows" : "collisions follow") +
                             " before the end.";
    if (t - moments.back().start_s < kSameInstantS || t >= end_s) {
      moments.back().text += "\n" + line;
    } else {
      moments.push_back({t, line});
    }
  }

  // The closing cue: shown for end_cue_s, but not before the last cue has had its time.
  const double closing_s =
      std::max(end_s - options.end_cue_s, moments.back().start_s + options.min_collision_shown_s);
  if (closing_s <= end_s - 0.05) {
    moments.push_back({closing_s, closingText(timeline, end_s)});
  } else {
    moments.back().text += "\n" + closingText(timeline, end_s);
  }

  std::vector<Cue> cues;
  for (std::size_t k = 0; k < moments.size(); ++k) {
    const double next_s = k + 1 < moments.size() ? moments[k + 1].start_s : end_s;
    // A video shorter than a millisecond still gets a cue that lasts.
    cues.push_back({moments[k].start_s, std::max(next_s, moments[k].start_s + kSameInstantS),
                    moments[k].text});
  }
  return cues;
}

}  // namespace collide::report
