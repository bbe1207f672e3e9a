#include "report/narration.hpp"

#include <algorithm>
#include <cmath>

#include "report/plain_numbers.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

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
  return text::fill(text::tr("{name} ({mass})"),
                    {{"name", body.name}, {"mass", quantity(body.mass_kg, "kg")}});
}

std::string openingText(const physics::Timeline& timeline, const std::string& title) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot start = timeline.initialState();
  // TRANSLATORS: a sentence's full stop after the title, and after the list of bodies.
  std::string text =
      title.empty() ? "" : text::fill(text::tr("{title}."), {{"title", title}}) + "\n";
  if (world.bodies.size() <= kMaxBodiesInCue) {
    std::string bodies;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      // TRANSLATORS: "cart 1 (1 kg) is moving right at 2 m/s".
      bodies +=
          (i == 0 ? "" : text::clauseSeparator()) +
          text::fill(text::tr("{body} is {motion}"),
                     {{"body", bodyWithMass(world.bodies[i])},
                      {"motion", motionInWords(start.bodies[i].velocity_mps, world.dimensions)}});
    }
    text += text::fill(text::tr("{sentence}."), {{"sentence", text::sentenceStart(bodies)}}) + "\n";
  } else {
    text += text::fill(
                text::trn("{count} body.", "{count} bodies.", world.bodies.size()),
                {{"count", text::formatScaled(static_cast<long long>(world.bodies.size()), 0)}}) +
            "\n";
  }
  text += text::fill(text::tr("Total kinetic energy {energy}."),
                     {{"energy", amount(timeline.kineticEnergy(start), "J")}});
  return text;
}

// Molecules with insides: what a collision traded between the pair's kinetic energy and the
// energy inside them (Borgnakke-Larsen: about half the collisions gain, half lose).
std::string insidesEnergyText(const physics::Timeline& timeline,
                              const physics::CollisionEvent& event) {
  const auto& bodies = timeline.world().bodies;
  const double after_J =
      0.5 * bodies.at(std::size_t(event.body_a)).mass_kg *
          event.velocity_a_after_mps.squaredNorm() +
      0.5 * bodies.at(std::size_t(event.body_b)).mass_kg * event.velocity_b_after_mps.squaredNorm();
  const double change_J = after_J - pairKineticEnergyBefore(timeline, event);
  const std::string energy = amount(std::abs(change_J), "J");
  if (change_J > 0.0) {
    // TRANSLATORS: a caption of a collision between two molecules with insides (rotation,
    // vibration) that gained kinetic energy from them; {energy} is an energy.
    return text::fill(text::tr("{energy} of internal energy turns into kinetic energy."),
                      {{"energy", energy}});
  }
  // TRANSLATORS: a caption of a collision between two molecules with insides that gave kinetic
  // energy to them; {energy} is an energy.
  return text::fill(text::tr("{energy} of kinetic energy goes inside the molecules."),
                    {{"energy", energy}});
}

// What an impact did to the kinetic energy: lost, kept, or (e > 1) gained from a store.
std::string impactEnergyText(const physics::Timeline& timeline,
                             const physics::CollisionEvent& event) {
  const double before_J = pairKineticEnergyBefore(timeline, event);
  const double lost_J = std::max(0.0, event.energy_lost_J);
  std::string text;
  if (timeline.world().internal_dof > 0 && !event.hitsWall())
    return insidesEnergyText(timeline, event);
  if (event.energy_released_J > 0.0) {
    // TRANSLATORS: a super-elastic collision's caption (e > 1); {released} is an energy.
    text += text::fill(text::tr("{released} of stored energy turns into kinetic energy: the "
                                "collision is super-elastic."),
                       {{"released", amount(event.energy_released_J, "J")}});
  } else if (lost_J <= 1e-12 * std::max(1.0, before_J)) {
    text += text::tr("No kinetic energy is lost: the collision is elastic.");
  } else {
    text += text::fill(
        event.hitsWall()
            ? text::tr("{lost} of its {before} of kinetic energy ({percent}) turns into heat and "
                       "deformation.")
            : text::tr("{lost} of their {before} of kinetic energy ({percent}) turns into heat "
                       "and deformation."),
        {{"lost", amount(lost_J, "J")},
         {"before", amount(before_J, "J")},
         {"percent", percentOf(lost_J, before_J)}});
  }
  return text;
}

std::string collisionText(const physics::Timeline& timeline, const physics::CollisionEvent& event) {
  const physics::WorldDef& world = timeline.world();
  const std::string& a = world.bodies.at(static_cast<std::size_t>(event.body_a)).name;
  const std::string time =
      text::equation(text::symbol(text::Symbol::kTime), timeReading(timeline, event.time_s));
  std::string text;
  if (event.release) {
    // TRANSLATORS: a release's caption (a spring let go between two bodies, a shot fired);
    // {time} is "t = 0.500 s", {energy} the energy released.
    text = text::fill(text::tr("{time}: stored energy of {energy} pushes {body} and {partner} "
                               "apart."),
                      {{"time", time},
                       {"energy", amount(event.energy_released_J, "J")},
                       {"body", a},
                       {"partner", partnerName(timeline, event.body_b)}});
  } else {
    // TRANSLATORS: a collision's caption; {time} is "t = 1.167 s", {e} is "e = 0.5".
    text =
        text::fill(text::tr("{time}: {body} hits {partner} at a closing speed of {speed} ({e})."),
                   {{"time", time},
                    {"body", a},
                    {"partner", partnerName(timeline, event.body_b)},
                    {"speed", amount(event.closing_speed_mps, "m/s")},
                    {"e", text::equation(text::symbol(text::Symbol::kRestitution),
                                         plainNumber(event.restitution))}}) +
        "\n" + impactEnergyText(timeline, event);
  }
  const std::string motion = motionInWords(event.velocity_a_after_mps, world.dimensions);
  text += '\n';
  if (event.merged && !event.hitsWall()) {
    text += text::fill(text::tr("They stick together, {motion}."), {{"motion", motion}});
  } else if (event.merged) {
    text += text::sentenceStart(
        text::fill(text::tr("{body} comes to rest against the wall."), {{"body", a}}));
  } else if (event.hitsWall()) {
    text +=
        text::fill(text::tr("Afterwards {body} is {motion}."), {{"body", a}, {"motion", motion}});
  } else {
    text += text::fill(
        text::tr("Afterwards {body} is {motion} and {partner} is {partner_motion}."),
        {{"body", a},
         {"motion", motion},
         {"partner", partnerName(timeline, event.body_b)},
         {"partner_motion", motionInWords(event.velocity_b_after_mps, world.dimensions)}});
  }
  return text;
}

std::string closingText(const physics::Timeline& timeline, double end_s) {
  const physics::Snapshot start = timeline.initialState();
  const physics::Snapshot end = timeline.sample(end_s);
  const double ke0 = timeline.kineticEnergy(start);
  const int n = end.impactCount();  // releases are told as such, not as collisions
  // Energies in the unit of the energy at the start (and what was released since), so the numbers
  // compare at a glance; the share lost is of both.
  const double in_all = ke0 + end.energy_released_J;
  const text::QuantityFormat energy = text::quantityFormat(in_all, "J");
  const auto joules = [&](double value) { return text::formatQuantity(value, energy); };
  // TRANSLATORS: the closing caption: "End, t = 4.000 s: 1 collision."
  std::string text =
      text::fill(text::trn("End, {time}: {count} collision.", "End, {time}: {count} collisions.",
                           static_cast<unsigned long>(n)),
                 {{"time",
                   text::equation(text::symbol(text::Symbol::kTime), timeReading(timeline, end_s))},
                  {"count", text::formatScaled(n, 0)}}) +
      "\n" +
      text::fill(text::tr("Kinetic energy {now} of {start} at the start; {lost} ({percent}) turned "
                          "into heat and deformation."),
                 {{"now", joules(timeline.kineticEnergy(end))},
                  {"start", joules(ke0)},
                  {"lost", joules(end.energy_lost_J)},
                  {"percent", percentOf(end.energy_lost_J, in_all)}});
  if (end.energy_released_J > 0.0) {
    // TRANSLATORS: the closing caption where stored energy came in (a spring, a shot, e > 1).
    text += "\n" + text::fill(text::tr("{released} of stored energy was released into motion."),
                              {{"released", joules(end.energy_released_J)}});
  }
  if (timeline.world().internal_dof > 0) {
    // TRANSLATORS: the closing caption of a gas whose molecules carry energy inside them
    // (rotation, vibration); {internal} and {total} are energies.
    text +=
        "\n" + text::fill(text::tr("{internal} is held inside the molecules as internal "
                                   "energy; kinetic and internal energy add up to {total}."),
                          {{"internal", joules(end.internal_energy_J)},
                           {"total", joules(timeline.kineticEnergy(end) + end.internal_energy_J)}});
  }
  const core::Vec2 p0 = timeline.momentum(start), p1 = timeline.momentum(end);
  const text::QuantityFormat momentum_format =
      text::quantityFormat(std::max(p0.norm(), p1.norm()), "kg·m/s");
  const auto momentum = [&](const core::Vec2& p) {
    if (timeline.world().dimensions == 1) return text::formatQuantity(p.x(), momentum_format);
    return text::formatComponentsIn(p.x(), p.y(), momentum_format) + " kg·m/s";
  };
  const bool conserved = (p1 - p0).norm() <= 1e-9 * std::max(1.0, p0.norm());
  text += '\n';
  text += conserved ? text::fill(text::tr("Total momentum {momentum} before and after."),
                                 {{"momentum", momentum(p0)}})
                    : text::fill(text::tr("Total momentum {start} at the start, {end} at the end "
                                          "(walls or gravity act on the bodies)."),
                                 {{"start", momentum(p0)}, {"end", momentum(p1)}});
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
    const std::string line = text::fill(text::trn("{count} more collision follows before the end.",
                                                  "{count} more collisions follow before the end.",
                                                  static_cast<unsigned long>(more)),
                                        {{"count", text::formatScaled(more, 0)}});
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
    moments.back().text += std::string("\n") + closingText(timeline, end_s);
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
