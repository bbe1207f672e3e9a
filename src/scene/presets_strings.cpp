// Presets with bodies on strings: the swinging Newton's cradle and the ballistic pendulum.
// The numbers are chosen so that the expected results follow by hand from conservation of
// momentum and of energy; each comment gives them.
#include <cmath>
#include <numbers>

#include "scene/preset_builders.hpp"
#include "text/translate.hpp"

namespace collide::scene::detail {
namespace {

constexpr double kGravity = 9.81;  // m/s^2, pulling down

// A body of `shape` hanging from `pivot` on a string of `length`, pulled `angle_deg` from
// straight down (counter-clockwise positive), at rest.
BodyDesc hangingBody(const std::string& name, double mass_kg, double radius_m, core::Vec2 pivot,
                     double length_m, double angle_deg) {
  BodyDesc b =
      body(name, "disk", mass_kg, radius_m, pivot + hangingOffset(length_m, angle_deg), {0.0, 0.0});
  b.pivot_m = pivot;
  b.string_length_m = length_m;
  b.string_angle_deg = angle_deg;
  return b;
}

SceneDesc hangingScene(const std::string& name, const std::string& title, double duration_s,
                       double e) {
  SceneDesc scene = presetScene(2, name, title, duration_s, e);
  scene.gravity_mps2 = {0.0, -kGravity};
  return scene;
}

}  // namespace

// Five equal 0.2 kg balls of radius 1/16 m hang on 0.5 m strings from pivots 1/8 m apart (exact
// in binary: the balls at rest touch exactly). `moving` balls on the left are pulled 30 degrees
// aside and let go: they reach the row at sqrt(2 g L (1 - cos 30)) = 1.146 m/s after a quarter
// period, T / 4 = sqrt(L / g) K(sin 15) = 0.361 s, and as many balls swing out on the right,
// back and forth; with e < 1 the swing dies away into the whole row swinging together.
SceneDesc newtonsCradle(const Parameters& parameters) {
  const int moving = static_cast<int>(parameters.at("moving"));
  SceneDesc scene = hangingScene("newtons-cradle",
                                 text::fill(text::tr("Newton's cradle: {moving} in, {moving} out"),
                                            {{"moving", std::to_string(moving)}}),
                                 4.0, 1.0);
  constexpr double kRadius = 0.0625, kSpacing = 0.125, kLength = 0.5;  // m
  for (int k = 0; k < 5; ++k) {
    const core::Vec2 pivot{kSpacing * (k - 2), 0.0};
    const std::string name =
        text::fill(text::trc("preset body", "ball {number}"), {{"number", std::to_string(k + 1)}});
    scene.bodies.push_back(
        hangingBody(name, 0.2, kRadius, pivot, kLength, k < moving ? -30.0 : 0.0));
  }
  return scene;
}

// A 10 g bullet at 200 m/s into a 1 kg block hanging on a 1 m string (e = 0: it stays in).
// Momentum 2 kg m/s shared by 1.01 kg: 1.980 m/s, kinetic energy 1.980 J of 200 J. The block
// then rises h = v^2 / (2 g) = 0.1998 m (36.9 degrees), and (m + M) / m sqrt(2 g h) gives back
// the bullet's 200 m/s: the ballistic pendulum's measurement.
SceneDesc ballisticPendulum(const Parameters&) {
  SceneDesc scene =
      hangingScene("ballistic-pendulum",
                   text::tr("Ballistic pendulum: the rise gives the bullet's speed"), 2.5, 0.0);
  scene.bodies.push_back(
      hangingBody(text::trc("preset body", "block"), 1.0, 0.1, {0.0, 0.0}, 1.0, 0.0));
  scene.bodies.push_back(
      body(text::trc("preset body", "bullet"), "disk", 0.01, 0.025, {-0.5, -1.0}, {200.0, 0.0}));
  scene.view.slow_motion_factor = 10.0;
  return scene;
}

}  // namespace collide::scene::detail
