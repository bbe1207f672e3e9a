#include "compose/readouts.hpp"

#include <algorithm>

#include "compose/frame_geometry.hpp"
#include "compose/frame_text.hpp"
#include "compose/label_timeline.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {
namespace {

constexpr std::size_t kMaxBarBodies = 7;  // more bodies share one "KE" segment (palette repeats)
constexpr double kTinyShare = 0.005;      // crowded bars: no label for a segment below this share

}  // namespace

std::string springWord() {
  // TRANSLATORS: the energy stored in a spring, in the energy bar and chart ("spring 0.5 J").
  return text::trc("energy part", "spring");
}

std::string lostWord() {
  // TRANSLATORS: the energy turned into heat and deformation so far, in the energy bar and the
  // energy chart ("lost 1.5 J").
  return text::trc("energy part", "lost");
}

std::string releasedWord() {
  // TRANSLATORS: stored energy (a spring let go, a shot fired) turned into motion so far, in the
  // energy bar and the energy chart ("released 3 J").
  return text::trc("energy part", "released");
}

std::string surfaceWord(bool cloth) {
  // TRANSLATORS: what the cloth of a billiard table has taken so far from rolling and sliding
  // balls (their spin's energy included), in the energy bar and the charts ("to the cloth 2.5 J").
  if (cloth) return text::trc("energy part", "to the cloth");
  // TRANSLATORS: what sliding friction has taken so far (heat in the surface the bodies slide
  // on), in the energy bar and the charts ("to the surface 2.5 J").
  return text::trc("energy part", "to the surface");
}

std::string internalWord() {
  // TRANSLATORS: energy held inside the molecules of a gas (their rotation, say), in the energy
  // bar and the energy chart ("internal 3 J").
  return text::trc("energy part", "internal");
}

std::string airWord() {
  // TRANSLATORS: what air drag has taken so far (the drag's work, given to the air), in the
  // energy bar and the charts ("to the air 2.5 J").
  return text::trc("energy part", "to the air");
}

std::string spinWord() {
  // TRANSLATORS: the kinetic energy of the disks' spin about their own centres (a stuck pair
  // turning as one body), in the energy bar and chart ("spin 0.0768 J").
  return text::trc("energy part", "spin");
}

physics::EnergyBooks panelBooks(const physics::Timeline& timeline, const FramePlan& plan,
                                double t_s) {
  return physics::energyBooks(timeline, t_s, plan.frame_velocity_mps,
                              plan.potential ? plan.potential_floor_J : 0.0);
}

std::vector<double> spinEnergies_J(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                                   const FramePlan& plan, const physics::EnergyBooks& books) {
  // Disks spin where a stuck pair turns as one body, and balls on a cloth spin as they roll.
  const bool can_spin = scene.contact.inelastic == scene::InelasticMode::kStick || scene.rolling;
  if (scene.dimensions != 2 || !can_spin) return {};
  const physics::Snapshot snapshot = timeline.sample(books.time_s);
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  std::vector<double> spin(books.kinetic_J.size(), 0.0);
  for (std::size_t i = 0; i < spin.size() && i < defs.size(); ++i) {
    const core::Vec2 v = snapshot.bodies[i].velocity_mps - plan.frame_velocity_mps;
    spin[i] = std::max(0.0, books.kinetic_J[i] - 0.5 * defs[i].mass_kg * v.squaredNorm());
  }
  return spin;
}

namespace {

struct BarPart {
  std::string name;
  double energy_J;
  frame::Rgba color;
  // Holds still between impacts (the energy lost in them): its figures do not take the step
  // that makes the parts add up, which the changing parts take (formatParts' `steady`).
  bool steady = false;
};

// The bar's parts in order: kinetic energy per body (or in all, when crowded), the disks' spin
// where they can spin (spin_J, taken out of each body's KE), gravity, the springs compressed now
// (one part in all, in a run with soft contacts: the same parts in every frame, so that a legend
// entry keeps its place and its id), what friction took, internal energy (molecules with
// insides), lost; none negative. Colours from `theme`.
std::vector<BarPart> barParts(const scene::SceneDesc& scene, const FramePlan& plan,
                              const Theme& theme, const physics::EnergyBooks& books,
                              const std::vector<double>& spin_J) {
  std::vector<BarPart> parts;
  std::vector<double> kinetic = books.kinetic_J;
  double spin_total_J = 0.0;
  for (std::size_t i = 0; i < spin_J.size() && i < kinetic.size(); ++i) {
    kinetic[i] -= spin_J[i];
    spin_total_J += spin_J[i];
  }
  if (kinetic.size() > kMaxBarBodies) {
    double kinetic_total_J = 0.0;
    for (double energy : kinetic) kinetic_total_J += energy;
    parts.push_back({text::symbol(text::Symbol::kKineticEnergy), kinetic_total_J, theme.bodies[0]});
  } else {
    for (std::size_t i = 0; i < kinetic.size(); ++i) {
      parts.push_back({text::symbol(text::Symbol::kKineticEnergy) + subscript(int(i) + 1),
                       kinetic[i], bodyColor(theme, i, scene.bodies[i])});
    }
  }
  if (!spin_J.empty()) parts.push_back({spinWord(), spin_total_J, theme.total});
  if (plan.potential) {
    parts.push_back(
        {text::symbol(text::Symbol::kPotentialEnergy), books.gravity_J, theme.potential});
  }
  if (plan.springs || !books.springs.empty()) {
    parts.push_back({springWord(), books.springTotal_J(), theme.spring});
  }
  if (plan.friction) parts.push_back({surfaceWord(plan.cloth), books.surface_J, theme.surface});
  if (plan.drag) parts.push_back({airWord(), books.air_J, theme.air});
  // Molecules with insides: their internal energy, in the spring's colour (energy stored that
  // can come back; such scenes have no soft contacts).
  if (scene.internal_dof > 0) parts.push_back({internalWord(), books.internal_J, theme.spring});
  parts.push_back({lostWord(), books.lost_J, theme.lost, true});
  for (BarPart& part : parts) part.energy_J = std::max(0.0, part.energy_J);
  return parts;
}

// The parts as written: each with three figures, together adding up to the total as written.
std::vector<std::string> shownParts(const std::vector<BarPart>& parts, const FramePlan& plan,
                                    const physics::EnergyBooks& books) {
  std::vector<double> energies;
  std::vector<bool> steady;
  for (const BarPart& part : parts) {
    energies.push_back(part.energy_J);
    steady.push_back(part.steady);
  }
  return text::formatParts(energies, books.total_J(), plan.formats.energy, text::defaultStyle(),
                           steady);
}

// The released strip: what came in from a store so far, from the start's energy on. Like the
// parts, no legend entry while it has no width (before a spring is let go): the caption says
// "0 J released" then.
frame::EnergySegment releasedStrip(const FramePlan& plan, const Theme& theme,
                                   const physics::EnergyBooks& books) {
  frame::EnergySegment strip;
  strip.energy_J = std::max(0.0, books.released_J);
  strip.color = theme.released;
  if (strip.energy_J / plan.energy_full_scale_J >= kLabelledShare) {
    strip.label = releasedWord() + " " + text::formatQuantity(strip.energy_J, plan.formats.energy);
  }
  strip.strip = true;
  strip.from_J = plan.energy_start_J;
  return strip;
}

// The entries planned for the shot t_s falls in (FramePlan::bar_shots), null where not planned.
const std::vector<bool>* shotEntries(const FramePlan::BarShots& shots, double t_s) {
  if (shots.starts_s.empty() || shots.starts_s.size() != shots.shown.size()) return nullptr;
  return &shots.shown[shotOf(shots.starts_s, t_s)];
}

}  // namespace

frame::EnergyBar energyBar(const scene::SceneDesc& scene, const FramePlan& plan, const Theme& theme,
                           const physics::EnergyBooks& books, const std::vector<double>& spin_J) {
  frame::EnergyBar bar;
  bar.full_scale_J = plan.energy_full_scale_J;
  const std::vector<BarPart> parts = barParts(scene, plan, theme, books, spin_J);
  const std::vector<std::string> shown = shownParts(parts, plan, books);
  const bool busy = books.kinetic_J.size() > 4;
  const std::vector<bool>* in_shot = shotEntries(plan.bar_shots, books.time_s);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const double share = parts[k].energy_J / plan.energy_full_scale_J;
    const bool kept = in_shot && k < in_shot->size() && (*in_shot)[k];
    const bool tiny = (busy && share < kTinyShare && !kept) || share < kLabelledShare;
    bar.segments.push_back(
        {parts[k].energy_J, parts[k].color, tiny ? "" : parts[k].name + " " + shown[k]});
  }
  // The loss, always the last part, keeps a slot only in a run that loses energy.
  bar.segments.back().has_slot = plan.loses_energy;
  if (plan.releases) bar.segments.push_back(releasedStrip(plan, theme, books));
  // Planned over the picture: each entry keeps the room of its widest label, and one never
  // labelled has no slot.
  if (plan.bar_rooms.size() == bar.segments.size()) {
    for (std::size_t k = 0; k < bar.segments.size(); ++k) {
      bar.segments[k].label_room = plan.bar_rooms[k];
      bar.segments[k].has_slot = !plan.bar_rooms[k].empty();
    }
  }
  return bar;
}

std::vector<frame::SpringModel> gliderBumpers(const scene::SceneDesc& scene,
                                              const physics::EnergyBooks& books,
                                              const frame::PanelModel& panel, std::size_t body_i) {
  constexpr double kCoilShare = 0.3;  // bumper half width, of the glider's half height
  constexpr int kTurns = 2;
  constexpr double kMostSquashed = 0.9;  // of its length: a bumper never shrinks to nothing
  const int bodies = static_cast<int>(panel.bodies.size());
  const int i = static_cast<int>(body_i);
  if (i >= bodies || body_i >= scene.bodies.size()) return {};
  const double length = bumperLength_m(scene.bodies[body_i]);
  if (!(length > 0.0)) return {};
  const frame::BodyModel& body = panel.bodies[body_i];
  double squeezed[2] = {0.0, 0.0};  // left, right
  for (const physics::SpringEnergy& spring : books.springs) {
    if (spring.body_a != i && spring.body_b != i) continue;
    const int partner = spring.body_a == i ? spring.body_b : spring.body_a;
    bool right = true;
    double share = spring.overlap_m;
    if (partner >= 0 && partner < bodies) {
      right = panel.bodies[static_cast<std::size_t>(partner)].center_m.x() > body.center_m.x();
      // Two gliders: both bumpers give way, half each, so their tips just touch.
      if (isGlider(scene.bodies[static_cast<std::size_t>(partner)])) share *= 0.5;
    } else if (partner < 0) {
      const std::size_t wall = static_cast<std::size_t>(physics::kWallPartnerBase - partner);
      if (wall >= panel.walls.size()) continue;
      right = panel.walls[wall].normal.x() < 0.0;  // its free side faces left: on the right
    }
    squeezed[right ? 1 : 0] += share;
  }
  std::vector<frame::SpringModel> out;
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 1 ? 1.0 : -1.0;
    const double rest = std::max(length - squeezed[side], (1.0 - kMostSquashed) * length);
    frame::SpringModel bumper;
    bumper.from_m = body.center_m + core::Vec2{sign * body.half_extent_m.x(), 0.0};
    bumper.to_m = bumper.from_m + core::Vec2{sign * rest, 0.0};
    bumper.half_width_m = kCoilShare * body.half_extent_m.y();
    bumper.turns = kTurns;
    out.push_back(bumper);
  }
  return out;
}

void addSprings(const scene::SceneDesc& scene, const physics::EnergyBooks& books,
                frame::PanelModel& panel) {
  constexpr double kCoilShare = 0.35;  // coil half width, of the body's half height or radius
  const int bodies = static_cast<int>(panel.bodies.size());
  auto across = [](const frame::BodyModel& body) {
    return body.shape == frame::BodyShape::kDisk ? body.half_extent_m.x() : body.half_extent_m.y();
  };
  auto glider = [&](int k) {
    return k >= 0 && k < static_cast<int>(scene.bodies.size()) &&
           isGlider(scene.bodies[static_cast<std::size_t>(k)]);
  };
  for (const physics::SpringEnergy& spring : books.springs) {
    if (spring.body_a < 0 || spring.body_a >= bodies || spring.body_b >= bodies) continue;
    if (glider(spring.body_a) || glider(spring.body_b)) continue;  // its bumpers show it
    const frame::BodyModel& a = panel.bodies[static_cast<std::size_t>(spring.body_a)];
    frame::SpringModel coil;
    coil.from_m = a.center_m;
    coil.half_width_m = kCoilShare * across(a);
    if (spring.body_b >= 0) {
      const frame::BodyModel& b = panel.bodies[static_cast<std::size_t>(spring.body_b)];
      coil.to_m = b.center_m;
      coil.half_width_m = std::min(coil.half_width_m, kCoilShare * across(b));
    } else {
      const std::size_t wall = static_cast<std::size_t>(physics::kWallPartnerBase - spring.body_b);
      if (wall >= panel.walls.size()) continue;
      const frame::WallModel& w = panel.walls[wall];
      const core::Vec2 n = w.normal.normalized();
      coil.to_m = a.center_m + (w.point_m - a.center_m).dot(n) * n;
    }
    panel.springs.push_back(coil);
  }
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    for (const frame::SpringModel& bumper : gliderBumpers(scene, books, panel, i))
      panel.springs.push_back(bumper);
  }
}

std::string panelCaption(const scene::SceneDesc& scene, const FramePlan& plan, const Theme& theme,
                         const physics::EnergyBooks& books,
                         const std::vector<std::string>& velocity_texts,
                         const std::vector<double>& spin_J) {
  // Most important first: a caption too wide for the picture loses whole parts from its end
  // (render's TextPainter::fitWhole), and every velocity is also written beside its arrow.
  const double total = books.total_J();
  const std::vector<BarPart> parts = barParts(scene, plan, theme, books, spin_J);
  const double lost = parts.back().energy_J;
  // "lost" as the bar's legend writes it, so the two never differ in the last figure.
  const std::string lost_shown = shownParts(parts, plan, books).back();
  const bool none_lost = text::readsZero(lost, plan.formats.energy) || !(total > 0.0);
  // Nothing lost is said in words: "0 kJ of 5.00 kJ (0%)" reads like a rounded loss.
  std::string caption =
      none_lost ? text::fill(
                      // TRANSLATORS: a picture's caption when no kinetic energy has been lost
                      // (yet); {time} is "t = 1.25 s", {total} the energy at the start, "5.00 kJ".
                      text::tr("{time}: no energy lost (total {total})"),
                      {{"time", timeText(books.time_s, plan.formats)},
                       {"total", text::formatQuantity(total, plan.formats.energy)}})
                : text::fill(
                      // TRANSLATORS: a picture's caption; {time} is "t = 1.25 s", {lost} and
                      // {total} energies, {percent} "67.5%".
                      text::tr("{time}: energy lost {lost} of {total} ({percent})"),
                      {{"time", timeText(books.time_s, plan.formats)},
                       {"lost", lost_shown},
                       {"total", text::formatQuantity(total, plan.formats.energy)},
                       {"percent", text::formatValue(100.0 * lost / total, "%")}});
  // What friction took, once there is some to say.
  if (plan.friction && !text::readsZero(books.surface_J, plan.formats.energy)) {
    caption += text::clauseSeparator() + surfaceWord(plan.cloth) + " " +
               text::formatQuantity(books.surface_J, plan.formats.energy);
  }
  // Likewise what drag took.
  if (plan.drag && !text::readsZero(books.air_J, plan.formats.energy)) {
    caption += text::clauseSeparator() + airWord() + " " +
               text::formatQuantity(books.air_J, plan.formats.energy);
  }
  // Molecules with insides: what they hold inside, as the bar's legend names it.
  if (scene.internal_dof > 0) {
    caption += text::clauseSeparator() + internalWord() + " " +
               text::formatQuantity(std::max(0.0, books.internal_J), plan.formats.energy);
  }
  if (plan.releases) {
    caption += text::clauseSeparator() +
               text::fill(text::tr("{energy} released from stored energy so far"),
                          {{"energy", text::formatQuantity(std::max(0.0, books.released_J),
                                                           plan.formats.energy)}});
  }
  if (scene.view.center_of_momentum_frame) {
    const core::Vec2& v = plan.frame_velocity_mps;
    caption +=
        text::clauseSeparator() +
        text::fill(text::tr("centre-of-momentum frame, moving at {velocity}"),
                   {{"velocity",
                     scene.dimensions == 1
                         ? text::formatQuantity(v.x(), plan.formats.speed, text::defaultStyle(),
                                                text::Sign::kAlways)
                         : text::formatComponentsIn(v.x(), v.y(), plan.formats.speed) + " m/s"}});
  }
  // A caption lists every body's velocity or none. A crowd (a break's sixteen balls, a gas) lists
  // none: its balls are too small to carry their numbers, so "v₉′" would tie to no ball a reader
  // can find, and a list cut after the first few would say little; its arrows show the speeds
  // against the scale arrow.
  constexpr std::size_t kMostVelocitiesListed = 8;
  if (velocity_texts.size() > kMostVelocitiesListed) return caption;
  for (std::size_t i = 0; i < velocity_texts.size(); ++i) {
    caption += (i > 0 ? text::listSeparator() : text::clauseSeparator()) + velocity_texts[i];
  }
  return caption;
}

}  // namespace collide::compose
