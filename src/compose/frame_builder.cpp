// buildPanel: one sampled state → bodies with labels and arrows, walls, bonds of stuck bodies,
// contact flashes, trails, the centre of mass, the momentum diagram, the energy bar and readouts.
#include "compose/frame_builder.hpp"

#include <algorithm>
#include <cmath>

#include "compose/arrow_rows.hpp"
#include "compose/frame_geometry.hpp"
#include "compose/frame_text.hpp"
#include "compose/gas_view.hpp"
#include "compose/moving_as_one.hpp"
#include "compose/readouts.hpp"
#include "compose/scale_arrow.hpp"
#include "compose/suspension_view.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {
namespace {

constexpr int kTrailSamples = 40;  // positions per trail
constexpr int kMaxFlashes = 6;     // contact flashes drawn at once

// Whether a scene's impacts do not all share one e (pairs, walls or a law of impact speed): then
// the e of each impact is a number the picture is about, and the readout shows it.
bool restitutionVaries(const scene::SceneDesc& scene) {
  if (!scene.pairs.empty() || scene.restitution_law.kind != scene::RestitutionLawKind::kConstant) {
    return true;
  }
  for (const scene::WallDesc& wall : scene::allWalls(scene)) {
    if (wall.restitution && *wall.restitution != scene.restitution) return true;
  }
  return false;
}

// "collisions: 3, last e = 0.5" (where e varies), "   ω = +1.23 rad/s" (a spinning stuck
// cluster), "   Σp: start …, now …" ("end" for a picture of the whole run): most important first,
// as fitWhole drops parts from the end.
std::string infoLine(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                     const physics::Snapshot& snapshot, const core::Vec2& momentum,
                     const FramePlan& plan, bool whole_run) {
  std::string info = collisionsSoFar(snapshot.impactCount());
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  auto after =
      std::upper_bound(events.begin(), events.end(), snapshot.time_s,
                       [](double t, const physics::CollisionEvent& e) { return t < e.time_s; });
  // The last impact's e: a release (stored energy pushing bodies apart) is no impact.
  while (after != events.begin() && std::prev(after)->release) --after;
  if (after != events.begin() && restitutionVaries(scene)) {
    // TRANSLATORS: after the collision count where e differs from pair to pair: ", last e = 0.5".
    info += text::listSeparator() +
            text::fill(
                text::tr("last {equation}"),
                {{"equation", text::equation(text::symbol(text::Symbol::kRestitution),
                                             text::formatPlain(std::prev(after)->restitution))}});
  }
  for (const physics::BodyState& body : snapshot.bodies) {
    // A stuck cluster's members share one ω: show it once.
    if (std::abs(body.angular_velocity_radps) > 1e-9) {
      info += std::string("   ") +
              text::equation(text::symbol(text::Symbol::kAngularVelocity),
                             text::formatValue(body.angular_velocity_radps, "rad/s",
                                               text::defaultStyle(), text::Sign::kAlways));
      break;
    }
  }
  const std::string symbol = std::string("Σ") + text::symbol(text::Symbol::kMomentum);
  const std::string start = momentumText(plan.initial_momentum_Ns, scene.dimensions, plan.formats);
  const std::string last = momentumText(momentum, scene.dimensions, plan.formats);
  if (whole_run) {
    // TRANSLATORS: the total momentum at the start and at the end of a picture of the whole run
    // (a stroboscopic image): "Σp: start +2.00 kg·m/s, end ...".
    info += "   " + text::fill(text::tr("{symbol}: start {start}, end {end}"),
                               {{"symbol", symbol}, {"start", start}, {"end", last}});
  } else {
    // TRANSLATORS: the total momentum at the start and now: "Σp: start +2.00 kg·m/s, now ...".
    info += "   " + text::fill(text::tr("{symbol}: start {start}, now {now}"),
                               {{"symbol", symbol}, {"start", start}, {"now", last}});
  }
  // With friction, what the surface took: with Σp now it makes up the start's. Not where walls
  // take momentum too (billiards-break's cushions): the two would not add up to the start.
  if (plan.friction && scene::allWalls(scene).empty()) {
    info += text::listSeparator() + surfaceWord(plan.cloth) + " " +
            momentumText(snapshot.surface_momentum_kgmps, scene.dimensions, plan.formats);
  }
  return info;
}

// Crowded scenes get a number inside each body instead of full labels.
bool crowded(const scene::SceneDesc& scene) {
  return scene.bodies.size() > (scene.dimensions == 1 ? 4u : 3u);
}

frame::BodyModel bodyModel(const scene::SceneDesc& scene, const Theme& theme, std::size_t i,
                           const physics::BodyState& state, double t_s, const FramePlan& plan) {
  const scene::BodyDesc& body = scene.bodies[i];
  frame::BodyModel model;
  model.shape = isDisk(body) ? frame::BodyShape::kDisk : frame::BodyShape::kRectangle;
  model.center_m = drawnCenter(scene, i, state, t_s, plan.frame_velocity_mps);
  model.half_extent_m = halfExtent(body);
  model.half_extent_m.x() -= bumperLength_m(body);  // the bumpers are drawn as springs
  model.fill = bodyColor(theme, i, body);
  model.velocity_mps = state.velocity_mps - plan.frame_velocity_mps;
  if (scene.dimensions == 1) model.velocity_mps.y() = 0.0;
  model.angle_rad = state.angle_rad;
  return model;
}

// The flash where two partners touched at a collision, in the drawing frame.
frame::FlashModel contactFlash(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                               const FramePlan& plan, const physics::CollisionEvent& event) {
  const physics::Snapshot at = timeline.sample(event.time_s);
  const std::size_t a = static_cast<std::size_t>(event.body_a);
  const core::Vec2 center =
      drawnCenter(scene, a, at.bodies[a], event.time_s, plan.frame_velocity_mps);
  const core::Vec2 half = halfExtent(scene.bodies[a]);
  frame::FlashModel flash;
  if (scene.dimensions == 1) {
    // At the top of the contact face (the shorter partner's top), no larger than that partner
    // is tall: the painter draws the flash under the bodies, so its upper half bursts above
    // them, neither body is hidden (a small block between a wall and a big one, pi-blocks,
    // vanished under two flashes at its middle) and the labels under the track stay clear.
    double height = 2.0 * half.y();
    if (!event.hitsWall()) {
      height = std::min(height, 2.0 * halfExtent(scene.bodies[event.body_b]).y());
    }
    flash.center_m = {center.x() + half.x() * (event.normal.x() >= 0.0 ? 1.0 : -1.0), height};
    flash.max_radius_m = height;
    return flash;
  }
  flash.center_m = center + half.x() * event.normal;
  // Sized to the bodies: no larger than the smaller partner (a burst wider than a billiard ball
  // hid the rack it struck).
  double size_m = std::min(half.x(), half.y());
  if (!event.hitsWall()) {
    const core::Vec2 other = halfExtent(scene.bodies[event.body_b]);
    size_m = std::min({size_m, other.x(), other.y()});
  }
  flash.max_radius_m = size_m;
  return flash;
}

// A panel's view, scale arrow and walls at t_s, with nothing in it yet.
frame::PanelModel emptyPanel(const scene::SceneDesc& scene, const FramePlan& plan, double t_s) {
  const int dims = scene.dimensions;
  frame::PanelModel panel;
  panel.view = plan.view;
  panel.two_d = dims == 2;
  panel.draw_track = dims == 1;
  panel.ruler = true;
  panel.calibration = scene.view.calibration;
  panel.arrow_m_per_mps = plan.arrow_m_per_mps;
  panel.arrow_max_length_m = plan.arrow_max_length_m;
  if (plan.scale_arrow_mps > 0.0) {
    panel.scale_arrow_mps = plan.scale_arrow_mps;
    panel.scale_arrow_label = scaleArrowLabel(plan.scale_arrow_mps);
  }
  for (const scene::WallDesc& wall : scene::allWalls(scene)) {
    core::Vec2 point = wall.position_m - t_s * plan.frame_velocity_mps;
    if (dims == 1) point.y() = 0.0;
    panel.walls.push_back({point, wall.normal.normalized()});
  }
  return panel;
}

// Body i at t_s (`snapshot`), with its trail.
frame::BodyModel panelBody(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                           const FramePlan& plan, const Theme& theme,
                           const physics::Snapshot& snapshot, std::size_t i, double t_s) {
  frame::BodyModel body = bodyModel(scene, theme, i, snapshot.bodies[i], t_s, plan);
  body.show_orientation =
      scene.dimensions == 2 && timeline.world().inelastic_mode == physics::InelasticMode::kStick;
  if (scene.view.trail_s > 0.0) {
    const double from = std::max(0.0, t_s - scene.view.trail_s);
    for (int k = 0; k <= kTrailSamples && t_s > from; ++k) {
      const double tau = from + (t_s - from) * k / kTrailSamples;
      const physics::Snapshot past = k == kTrailSamples ? snapshot : timeline.sample(tau);
      body.trail_m.push_back(drawnCenter(scene, i, past.bodies[i], tau, plan.frame_velocity_mps));
    }
  }
  return body;
}

// A body's texts: its mass label and velocity readout, or in a crowded scene its number (and in
// 1D its readout while it moves).
void labelBody(frame::BodyModel& body, int number, const std::string& velocity,
               const physics::BodyDef& def, bool is_crowded, int dims) {
  const bool moving = body.velocity_mps.norm() > 1e-6;
  if (is_crowded) {
    body.tag = std::to_string(number);
    if (dims == 1 && moving) body.velocity_label = velocity;
  } else {
    const bool with_air_drag = def.drag_linear_kgps > 0.0 || def.drag_quadratic_kgpm > 0.0;
    body.label = massLabel(number, def.mass_kg, with_air_drag);
    body.velocity_label = velocity;
  }
}

// The bodies' momentum, mass moment and mass, summed.
struct Totals {
  core::Vec2 momentum{0.0, 0.0}, mass_moment{0.0, 0.0};
  double mass = 0.0;
};

// The flashes of the latest collisions before t_s, at most kMaxFlashes, fading over
// plan.flash_s. A soft contact still under way shows its spring instead of a flash, which would
// hide it.
void addFlashes(frame::PanelModel& panel, const scene::SceneDesc& scene,
                const physics::Timeline& timeline, const FramePlan& plan,
                const physics::EnergyBooks& books, double t_s) {
  auto compressed = [&](const physics::CollisionEvent& event) {
    return std::any_of(
        books.springs.begin(), books.springs.end(),
        [&](const physics::SpringEnergy& s) { return s.collision_index == event.index; });
  };
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  auto it =
      std::upper_bound(events.begin(), events.end(), t_s,
                       [](double t, const physics::CollisionEvent& e) { return t < e.time_s; });
  std::vector<const physics::CollisionEvent*> flashed;  // the latest first, as they are drawn
  for (int shown = 0; it != events.begin() && shown < kMaxFlashes; ++shown) {
    --it;
    const double age = t_s - it->time_s;
    if (age >= plan.flash_s) break;
    if (compressed(*it)) continue;
    flashed.push_back(&*it);
  }
  // Sampled from the earliest: the timeline carries a re-simulation on to a later time but
  // starts one again from a checkpoint for an earlier one (physics/sample_cursors.hpp).
  const std::size_t first_flash = panel.flashes.size();
  panel.flashes.resize(first_flash + flashed.size());
  for (std::size_t k = flashed.size(); k-- > 0;) {
    frame::FlashModel flash = contactFlash(scene, timeline, plan, *flashed[k]);
    flash.strength = 1.0 - (t_s - flashed[k]->time_s) / plan.flash_s;
    panel.flashes[first_flash + k] = flash;
  }
}

// The small momentum diagram beside the scene: each body's momentum as an arrow.
frame::MomentumDiagram momentumDiagram(const frame::PanelModel& panel, const FramePlan& plan,
                                       const std::vector<physics::BodyDef>& defs) {
  frame::MomentumDiagram diagram;
  // TRANSLATORS: the heading of the small momentum diagram beside the scene.
  diagram.title = text::trc("momentum diagram", "momentum");
  diagram.full_scale_Ns = plan.momentum_full_scale_Ns;
  diagram.reach_low_Ns = plan.momentum_low_Ns;
  diagram.reach_high_Ns = plan.momentum_high_Ns;
  // Its scale stated: the largest round momentum up to half the chain's longer reach, a bar
  // long enough to read that leaves room for its value beside it.
  const core::Vec2 reach = plan.momentum_high_Ns - plan.momentum_low_Ns;
  diagram.scale_bar_Ns = roundValueBelow(reach.maxCoeff() / 2.0);
  if (diagram.scale_bar_Ns > 0.0) {
    diagram.scale_bar_label = text::formatPlain(diagram.scale_bar_Ns) + " kg·m/s";
  }
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    diagram.arrows.push_back({defs[i].mass_kg * panel.bodies[i].velocity_mps, panel.bodies[i].fill,
                              text::symbol(text::Symbol::kMomentum) + subscript(int(i) + 1)});
  }
  return diagram;
}

}  // namespace

std::vector<frame::BodyModel> bodyImages(const scene::SceneDesc& scene,
                                         const physics::Timeline& timeline, const FramePlan& plan,
                                         const Theme& theme, double t_s) {
  const physics::Snapshot snapshot = timeline.sample(t_s);
  std::vector<frame::BodyModel> images;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    images.push_back(bodyModel(scene, theme, i, snapshot.bodies[i], t_s, plan));
  }
  return images;
}

frame::PanelModel buildPanel(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                             const FramePlan& plan, const Theme& theme, double t_s,
                             bool whole_run) {
  const physics::Snapshot snapshot = timeline.sample(t_s);
  const bool is_crowded = crowded(scene);
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;

  frame::PanelModel panel = emptyPanel(scene, plan, t_s);
  Totals totals;
  std::vector<std::string> velocity_texts;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    frame::BodyModel body = panelBody(scene, timeline, plan, theme, snapshot, i, t_s);
    velocity_texts.push_back(velocityLabel(static_cast<int>(i) + 1, body.velocity_mps,
                                           t_s >= plan.first_collision_s[i], scene.dimensions,
                                           plan.formats));
    labelBody(body, static_cast<int>(i) + 1, velocity_texts.back(), defs[i], is_crowded,
              scene.dimensions);
    totals.momentum += defs[i].mass_kg * body.velocity_mps;
    totals.mass_moment += defs[i].mass_kg * body.center_m;
    totals.mass += defs[i].mass_kg;
    panel.bodies.push_back(std::move(body));
  }

  // Stuck partners up to now; flashes of the latest collisions (a burst of thousands, as in
  // pi-blocks, shows its last few).
  for (const FramePlan::Bond& bond : plan.bonds) {
    if (bond.time_s > t_s) break;
    panel.bonds.push_back({bond.body_a, bond.body_b});
  }
  const physics::EnergyBooks books = panelBooks(timeline, plan, t_s);
  addFlashes(panel, scene, timeline, plan, books, t_s);
  if (scene.view.center_of_mass && totals.mass > 0.0) {
    panel.center_of_mass_m = core::Vec2(totals.mass_moment / totals.mass);
  }
  if (scene.view.momentum_diagram) panel.momentum = momentumDiagram(panel, plan, defs);
  addSuspension(panel, scene, timeline, plan, t_s);
  addSkids(panel, timeline, plan.skids, plan.formats.length, t_s);
  std::vector<double> masses_kg;
  for (const physics::BodyDef& def : defs) masses_kg.push_back(def.mass_kg);
  showMovingAsOne(panel, masses_kg, !is_crowded);
  // A margin of 2 % of the view: an arrowhead's width at the usual sizes.
  assignArrowRows(panel, 0.02 * (plan.view.max_m.x() - plan.view.min_m.x()));

  const std::vector<double> spin_J = spinEnergies_J(scene, timeline, plan, books);
  panel.energy_bar = energyBar(scene, plan, theme, books, spin_J);
  addSprings(scene, books, panel);
  panel.info = infoLine(scene, timeline, snapshot, totals.momentum, plan, whole_run);
  // The reference simulator's caption: time, velocities, energy lost and the fraction lost.
  panel.caption = panelCaption(scene, plan, theme, books, velocity_texts, spin_J);
  if (isGas(scene)) drawAsGas(panel);
  return panel;
}

}  // namespace collide::compose
