// Presets in a plane: disks, walls with normals, boxes, gravity.
#include <cmath>

#include "scene/preset_builders.hpp"
#include "text/translate.hpp"

namespace collide::scene::detail {
namespace {

// A pool ball: 57.15 mm diameter, 170 g.
constexpr double kBallRadiusM = 0.028575;
constexpr double kBallMassKg = 0.17;

}  // namespace

// A 0.6 kg ball of radius 0.12 m dropped from a centre height of 1.5 m while moving sideways at
// 0.6 m/s onto a floor with e = 0.8. The first fall takes sqrt(2·1.38/9.81) = 0.53 s; each
// rebound rises to e^2 = 0.64 of the previous height. The strobe draws the arcs.
SceneDesc bouncingBall(const Parameters&) {
  SceneDesc scene = presetScene(
      2, "bouncing-ball", text::tr("A bouncing ball, e = {restitution}"), 4.0, 0.8,
      {body(text::trc("preset body", "ball"), "disk", 0.6, 0.12, {0.0, 1.5}, {0.6, 0.0})});
  scene.gravity_mps2 = {0.0, -9.81};
  scene.walls.push_back(
      {text::trc("preset wall", "floor"), {0.0, 0.0}, {0.0, 1.0}, std::nullopt});  // e: the scene's
  return scene;
}

// Equal pool balls, elastic. The cue ball's path passes one radius from the object ball's centre,
// so the contact normal is 30 degrees off its path: the object ball leaves at -30 degrees with
// 1.5·cos 30 = 1.30 m/s, the cue ball at +60 degrees with 0.75 m/s: 90 degrees apart.
SceneDesc billiardsGlancing(const Parameters&) {
  SceneDesc scene = presetScene(
      2, "billiards-glancing", text::tr("A glancing elastic collision: 90 degrees apart"), 1.5, 1.0,
      {body(text::trc("preset body", "cue ball"), "disk", kBallMassKg, kBallRadiusM,
            {-0.6, kBallRadiusM}, {1.5, 0.0}),
       body(text::trc("preset body", "object ball"), "disk", kBallMassKg, kBallRadiusM, {0.0, 0.0},
            {0.0, 0.0})});
  scene.view.momentum_diagram = true;
  return scene;
}

namespace {

// Pool balls on a cloth: sliding mu 0.2, rolling resistance 0.01 (the values Leckie and
// Greenspan's simulator and pooltool use).
void putOnCloth(SceneDesc& scene) {
  scene.rolling = true;
  for (BodyDesc& ball : scene.bodies) {
    ball.friction = 0.2;
    ball.rolling_friction = 0.01;
  }
}

// A head-on shot on a cloth, elastic between the balls.
SceneDesc clothScene(const char* name, const std::string& title, double duration_s, BodyDesc cue) {
  SceneDesc scene =
      presetScene(2, name, title, duration_s, 1.0,
                  {std::move(cue), body(text::trc("preset body", "object ball"), "disk",
                                        kBallMassKg, kBallRadiusM, {0.0, 0.0}, {0.0, 0.0})});
  putOnCloth(scene);
  scene.view.trail_s = duration_s;
  return scene;
}

}  // namespace

// A 2.54 m x 1.27 m table (cushions e = 0.8), balls e = 0.95, on a cloth. The rack is a triangle
// of `rows` rows with its apex on the foot spot; racked balls sit 0.2 mm apart as in a real rack,
// and the cue ball at 8 m/s is 2 mm off the centre line, so the break is not perfectly symmetric.
// The cue ball is struck at its centre (a stun break): it slides into the rack without spin and
// stays near the middle of the table. The cloth brings every ball to rest within the 7 s.
SceneDesc billiardsBreak(const Parameters& parameters) {
  const int rows = static_cast<int>(parameters.at("rows"));
  SceneDesc scene = presetScene(2, "billiards-break",
                                text::tr("The break: a cue ball scatters the rack"), 7.0, 0.95);
  scene.box = BoxDesc{{-1.27, -0.635}, {1.27, 0.635}, 0.8};
  scene.bodies.push_back(body(text::trc("preset body", "cue ball"), "disk", kBallMassKg,
                              kBallRadiusM, {-0.635, 0.002}, {8.0, 0.0}));
  scene.bodies.back().spin = "stop";
  const double spacing_m = 2.0 * kBallRadiusM + 0.0002;
  int number = 1;
  for (int row = 0; row < rows; ++row) {
    const double x = 0.635 + row * spacing_m * std::sqrt(3.0) / 2.0;
    for (int j = 0; j <= row; ++j) {
      const double y = (j - 0.5 * row) * spacing_m;
      scene.bodies.push_back(body(text::fill(text::trc("preset body", "ball {number}"),
                                             {{"number", std::to_string(number++)}}),
                                  "disk", kBallMassKg, kBallRadiusM, {x, y}, {0.0, 0.0}));
    }
  }
  // A full rack's images are a cloud of dots (from three rows, seven balls, on): a still a second
  // in, the rack scattered and each ball's arrow on one scale, shows the break instead.
  if (rows >= 3) scene.view.best_still_s = 1.0;
  putOnCloth(scene);
  return scene;
}

// A rolling cue ball at 1.2 m/s hits the object ball 0.6 m ahead head-on. Rolling resistance
// slows it to v = sqrt(1.44 - 2 (0.0981) 0.543) = 1.15 m/s by then; the impact stops it but
// keeps its spin, so its slip is -v: it slides forward and rolls at 2/7 v = 0.33 m/s after
// 2v / (7 mu g) = 0.17 s, while the object ball, sliding without spin, settles to 5/7 v.
// The title fits one line in a figure printed 8 cm wide, and the 0.6 m run-up leaves the
// labels room there (at 0.4 m the object ball's mass found none just after the impact).
SceneDesc billiardsFollow(const Parameters&) {
  return clothScene("billiards-follow", text::tr("Follow: it stops, then follows"), 2.0,
                    body(text::trc("preset body", "cue ball"), "disk", kBallMassKg, kBallRadiusM,
                         {-0.6, 0.0}, {1.2, 0.0}));
}

// The cue ball struck below centre at 2 m/s, 0.6 m from the object ball, with backspin as large
// as rolling's (slip 4 m/s): the slip shrinks at 7/2 mu g, so at the impact (0.32 s, at
// 1.37 m/s) backspin of 0.42 m/s at the rim is left; the impact stops the ball and the backspin
// pulls it back at 2/7 of that, 0.12 m/s. The title fits one line printed 8 cm wide, and the
// run-up leaves the labels room there (from 0.3 m the cue ball's value found none just after
// the impact).
SceneDesc billiardsDraw(const Parameters&) {
  BodyDesc cue = body(text::trc("preset body", "cue ball"), "disk", kBallMassKg, kBallRadiusM,
                      {-0.6, 0.0}, {2.0, 0.0});
  cue.spin = "draw";
  return clothScene("billiards-draw", text::tr("Draw shot: it comes back"), 1.5, std::move(cue));
}

// Two disks meet off-centre (the path passes one radius from the other's centre) with e = 0 in
// stick mode: they join and the pair spins about its centre of mass, keeping the angular momentum
// m1·v·b about it.
SceneDesc stick2d(const Parameters&) {
  SceneDesc scene = presetScene(
      2, "stick-2d", text::tr("Off-centre, e = 0, stick: a spinning pair"), 4.0, 0.0,
      {body(text::trc("preset body", "disk 1"), "disk", 1.0, 0.2, {-1.2, 0.2}, {2.0, 0.0}),
       body(text::trc("preset body", "disk 2"), "disk", 2.0, 0.2, {0.0, 0.0}, {0.0, 0.0})});
  scene.contact.inelastic = InelasticMode::kStick;
  scene.view.center_of_mass = true;
  return scene;
}

}  // namespace collide::scene::detail
