// Presets on a line. Numbers are chosen so that the expected results are easy to derive by hand
// (conservation of momentum and the definition of e); each comment gives them.
#include <cmath>

#include "scene/preset_builders.hpp"
#include "text/translate.hpp"

namespace collide::scene::detail {

// The reference article's worked example: equal 1 kg carts closing at 2 m/s and -1 m/s, e = 0.5.
// They meet at t = 3.5 m / 3 m/s = 7/6 s; after: v1 = -0.25 m/s, v2 = 1.25 m/s.
SceneDesc workedExample(const Parameters&) {
  return presetScene(1, "worked-example", text::tr("Inelastic collision, e = {restitution}"), 4.0,
                     0.5,
                     {block(text::trc("preset body", "cart 1"), 1.0, 0.5, -2.0, 2.0),
                      block(text::trc("preset body", "cart 2"), 1.0, 0.5, 2.0, -1.0)});
}

// e = 1, 1 kg at 3 m/s onto 2 kg at rest: after, -1 m/s and +2 m/s; kinetic energy 4.5 J kept.
SceneDesc elastic(const Parameters&) {
  return presetScene(1, "elastic",
                     text::tr("A cart bounces back off a heavier one, e = {restitution}"), 4.0, 1.0,
                     {block(text::trc("preset body", "cart 1"), 1.0, 0.5, -3.0, 3.0),
                      block(text::trc("preset body", "cart 2"), 2.0, 0.6, 1.0, 0.0)});
}

// e = 0, 2 kg at 3 m/s onto 1 kg at rest: together at 2 m/s; 3 J of 9 J lost.
SceneDesc perfectlyInelastic(const Parameters&) {
  return presetScene(1, "perfectly-inelastic",
                     text::tr("Carts that couple on impact, e = {restitution}"), 4.0, 0.0,
                     {block(text::trc("preset body", "cart 1"), 2.0, 0.6, -3.0, 3.0),
                      block(text::trc("preset body", "cart 2"), 1.0, 0.5, 1.0, 0.0)});
}

// Equal 1 kg carts, one at rest, hit at 2 m/s. Panels: e = 1 (they swap: 0 and 2 m/s), e = 0.5
// (0.5 and 1.5 m/s), e = 0 (both 1 m/s).
SceneDesc compareRestitution(const Parameters&) {
  SceneDesc scene = presetScene(1, "compare-restitution",
                                text::tr("The same collision with e = 1, 0.5 and 0"), 4.0, 0.5,
                                {block(text::trc("preset body", "cart 1"), 1.0, 0.5, -2.0, 2.0),
                                 block(text::trc("preset body", "cart 2"), 1.0, 0.5, 1.0, 0.0)});
  scene.view.panel_parameter = "restitution";
  scene.view.panel_values = {1.0, 0.5, 0.0};
  return scene;
}

// Mass ratio 100, elastic: the light cart leaves at 2·10/10.1 = 1.98 m/s, the heavy one slows
// only to 9.9/10.1 = 0.98 m/s.
SceneDesc heavyLight(const Parameters&) {
  return presetScene(
      1, "heavy-light",
      text::tr("Heavy meets light: {body.1.mass} kg and {body.2.mass} kg, e = {restitution}"), 5.0,
      1.0,
      {block(text::trc("preset body", "heavy cart"), 10.0, 1.0, -2.0, 1.0),
       block(text::trc("preset body", "light cart"), 0.1, 0.25, 0.0, 0.0)});
}

// Head-on: 1500 kg at 54 km/h against 1000 kg at 36 km/h. Real e falls with impact speed: 0.4 up
// to 1.5 m/s, then 0.4·(1.5/u)^0.5, so at the closing speed of 25 m/s e = 0.098. The common
// velocity is 5 m/s; after: 4.02 m/s and 6.47 m/s.
SceneDesc carCrash(const Parameters&) {
  SceneDesc scene =
      presetScene(1, "car-crash", text::tr("Head-on crash: e falls with impact speed"), 4.0, 0.4,
                  {block(text::trc("preset body", "car 1"), 1500.0, 4.5, -20.0, 15.0),
                   block(text::trc("preset body", "car 2"), 1000.0, 4.2, 20.0, -10.0)});
  scene.restitution_law.kind = RestitutionLawKind::kSpeedThreshold;
  scene.restitution_law.threshold_speed_mps = 1.5;
  scene.restitution_law.exponent = 0.5;
  // Car 2 comes back over its own path: on one track its images after the crash lie on those
  // before it, so a strobe leaves out one way or the other. The still after the crash, both
  // cars moving right and slower, shows it instead.
  scene.view.best_still_s = 1.8;
  return scene;
}

// Accident reconstruction: a 1500 kg car skids with locked wheels (mu = 0.7) from 20 m/s into a
// 1000 kg car waiting 8 m ahead, and they lock together (e = 0). The car hits at
// sqrt(20^2 - 2 mu g 8 m) = 17.0 m/s; momentum gives the pair 1500/2500 of that, 10.2 m/s, and
// they skid v^2 / (2 mu g) = 7.60 m to rest: from that skid, momentum gives the speed at impact.
SceneDesc accidentReconstruction(const Parameters&) {
  SceneDesc scene =
      presetScene(1, "accident-reconstruction",
                  text::tr("Accident reconstruction: the skid gives the speed"), 3.0, 0.0,
                  {block(text::trc("preset body", "car 1"), 1500.0, 4.5, -10.25, 20.0),
                   block(text::trc("preset body", "car 2"), 1000.0, 4.2, 2.1, 0.0)});
  for (BodyDesc& car : scene.bodies) {
    car.friction = 0.7;
    car.static_friction = 0.8;
  }
  return scene;
}

// A 0.4 kg glider with a card sail (quadratic drag, c = 0.08 kg/m) leaves at 1.5 m/s towards an
// equal glider at rest 1.5 m ahead. Drag slows it as v = v0 e^(-c x / m): it arrives at
// 1.5 e^(-0.3) = 1.11 m/s after (m / (c v0))(e^(0.3) - 1) = 1.17 s, having given 0.20 J of its
// 0.45 J to the air; e = 1 hands the glider without a sail all it has left.
SceneDesc airDrag(const Parameters&) {
  SceneDesc scene = presetScene(
      1, "air-drag", text::tr("Air drag: a glider with a sail slows before it hits"), 2.5, 1.0,
      {body(text::trc("preset body", "glider 1"), "glider", 0.4, 0.15, {-1.5, 0.0}, {1.5, 0.0}),
       body(text::trc("preset body", "glider 2"), "glider", 0.4, 0.15, {0.15, 0.0}, {0.0, 0.0})});
  scene.bodies[0].drag_quadratic_kgpm = 0.08;
  return scene;
}

// e = 0 head-on: 0.5 kg at 2 m/s and 0.3 kg at -2 m/s stick and move on at 0.5 m/s.
SceneDesc clay(const Parameters&) {
  SceneDesc scene =
      presetScene(1, "clay", text::tr("Lumps of clay meet head-on, e = {restitution}"), 3.0, 0.0,
                  {block(text::trc("preset body", "clay 1"), 0.5, 0.3, -1.5, 2.0),
                   block(text::trc("preset body", "clay 2"), 0.3, 0.25, 1.5, -2.0)});
  scene.bodies[0].color = Rgb{181, 101, 29};
  scene.bodies[1].color = Rgb{120, 144, 72};
  return scene;
}

// A 10 g bullet at 200 m/s embeds in a 1 kg block: 2 kg·m/s shared by 1.01 kg gives 1.98 m/s;
// of 200 J only 1.98 J remain. The impact comes 9 ms in: slow motion shows it.
SceneDesc bulletBlock(const Parameters&) {
  SceneDesc scene = presetScene(1, "bullet-block",
                                text::tr("A bullet meets a block, e = {restitution}"), 3.0, 0.0,
                                {block(text::trc("preset body", "bullet"), 0.01, 0.05, -2.0, 200.0),
                                 block(text::trc("preset body", "block"), 1.0, 0.4, 0.0, 0.0)});
  scene.view.slow_motion_factor = 10.0;
  return scene;
}

// Two gliders with spring bumpers (e = 0.95) on a 2 m air track whose end stops give e = 0.9.
// Total momentum 0 at the start, so the gliders meet again and again around the middle. The
// bumpers are soft contacts of 0.05 s: the picture shows them compressed and the energy bar the
// energy they hold meanwhile; each contact still ends with the requested e.
SceneDesc airTrack(const Parameters&) {
  SceneDesc scene = presetScene(
      1, "air-track", text::tr("Air track: gliders with spring bumpers"), 10.0, 0.95,
      {body(text::trc("preset body", "glider 1"), "glider", 0.2, 0.15, {-0.5, 0.0}, {0.4, 0.0}),
       body(text::trc("preset body", "glider 2"), "glider", 0.4, 0.15, {0.3, 0.0}, {-0.2, 0.0})});
  scene.box = BoxDesc{{-1.0, 0.0}, {1.0, 0.0}, 0.9};
  scene.contact.model = ContactModelKind::kSpringDamper;
  scene.contact.duration_s = 0.05;
  return scene;
}

// A 1 kg striker at 2 m/s runs into five 1 kg blocks 0.2 m apart; the pairs along the chain
// have e = 0.9, 0.7, 0.5, 0.3, 0.1, so each hand-off passes on less. The blocks are named 2 to 6,
// the numbers the pictures give them (the striker is body 1).
SceneDesc granularChain(const Parameters&) {
  SceneDesc scene = presetScene(1, "granular-chain",
                                text::tr("A chain of blocks with e varying along it"), 6.0, 0.5);
  scene.bodies.push_back(block(text::trc("preset body", "striker"), 1.0, 0.3, -2.0, 2.0));
  for (int k = 0; k < 5; ++k) {
    scene.bodies.push_back(body(
        text::fill(text::trc("preset body", "block {number}"), {{"number", std::to_string(k + 2)}}),
        "block", 1.0, 0.3, {0.5 * k, 0.0}, {0.0, 0.0}));
  }
  const double chain_e[] = {0.9, 0.7, 0.5, 0.3, 0.1};
  for (int k = 0; k < 5; ++k) scene.pairs.push_back({k, k + 1, chain_e[k]});
  // Six blocks a block's width apart pass the momentum along one line: their images over time
  // lie on each other's, so no strobe rate tells the hand-offs apart (numbered or not). The
  // still at 1.3 s, the hand-off under way with every block's velocity, shows it.
  scene.view.best_still_s = 1.3;
  return scene;
}

// Rubber-like contact: a spring and dashpot tuned for e = 0.7 over 0.2 s. 1 kg at 1.5 m/s meets
// 2 kg at -0.5 m/s; the force chart shows the contact force over those 0.2 s. Its area is the
// impulse (1 + e)·mu·u = 1.7·(2/3)·2 = 2.27 N·s.
SceneDesc softContact(const Parameters&) {
  SceneDesc scene =
      presetScene(1, "soft-contact",
                  text::tr("Soft contact: a spring and a damper, e = {restitution}"), 3.0, 0.7,
                  {block(text::trc("preset body", "cart 1"), 1.0, 0.5, -1.5, 1.5),
                   block(text::trc("preset body", "cart 2"), 2.0, 0.6, 1.0, -0.5)});
  scene.contact.model = ContactModelKind::kSpringDamper;
  scene.contact.duration_s = 0.2;
  scene.view.chart = true;
  scene.view.chart_quantity = "force";
  return scene;
}

// Galperin's billiard: a small block between a wall and a big block 100^(d-1) times heavier, all
// elastic: the number of collisions is the first d digits of pi (3, 31, 314, ...).
SceneDesc piBlocks(const Parameters& parameters) {
  const int digits = static_cast<int>(parameters.at("digits"));
  double big_mass_kg = 1.0;
  for (int k = 1; k < digits; ++k) big_mass_kg *= 100.0;  // exact in binary up to 100^8
  // The ratio 100^(d-1) = 10^(2d-2), written as a power of ten with a superscript exponent.
  const std::string exponent = std::to_string(2 * (digits - 1));
  std::string ratio = "10";
  for (char digit : exponent) {
    static const char* const kSuperscripts[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                                "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
    ratio += kSuperscripts[digit - '0'];
  }
  const unsigned long count = static_cast<unsigned long>(digits);
  const std::string title =
      digits > 1 ? text::trn("Counting pi: {count} digit, mass ratio {ratio}",
                             "Counting pi: {count} digits, mass ratio {ratio}", count)
                 : text::trn("Counting pi: {count} digit, equal masses",
                             "Counting pi: {count} digits, equal masses", count);
  SceneDesc scene = presetScene(
      1, "pi-blocks", text::fill(title, {{"count", std::to_string(digits)}, {"ratio", ratio}}),
      12.0, 1.0);
  scene.walls.push_back({text::trc("preset wall", "wall"), {0.0, 0.0}, {1.0, 0.0}, 1.0});
  scene.bodies.push_back(block(text::trc("preset body", "small"), 1.0, 0.4, 1.5, 0.0));
  scene.bodies.push_back(block(text::trc("preset body", "big"), big_mass_kg, 1.0, 3.5, -1.0));
  return scene;
}

}  // namespace collide::scene::detail
