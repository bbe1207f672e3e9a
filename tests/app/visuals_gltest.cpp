// Teaching visuals end to end (scene -> physics -> FrameModel -> pixels), compared with reviewed
// goldens: 2D glancing collision, Newton's cradle, the bouncing-ball strobe, comparison panels, a
// chart and each theme. Plus the numbers behind the pictures: centre-of-momentum frame, slow
// motion keeping simulated time.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "compose/slow_motion.hpp"
#include "golden.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

constexpr int kWidth = 480, kHeight = 270;

::testing::AssertionResult matchesGolden(const frame::FrameModel& frame, const std::string& name,
                                         int width = kWidth, int height = kHeight) {
  render::Renderer renderer(width, height);
  test::GoldenOptions options;
  options.renderer = renderer.glRendererName();
  return test::compareWithGolden(renderer.render(frame), "app/" + name + ".png", options);
}

// A 1 kg disk of radius 0.2 m, everything else as a scene file leaves it.
scene::BodyDesc disk(const std::string& name, core::Vec2 position_m, core::Vec2 velocity_mps) {
  scene::BodyDesc body;
  body.name = name;
  body.shape = "disk";
  body.mass_kg = 1.0;
  body.size_m = 0.2;
  body.position_m = position_m;
  body.velocity_mps = velocity_mps;
  return body;
}

// Two equal disks, large enough to see at 480x270: the cue ball's path passes 0.2 m (one radius)
// from the object ball's centre, so they leave 90 degrees apart.
scene::SceneDesc glancing() {
  scene::SceneDesc scene;
  scene.name = "glancing-test";
  scene.title = "Glancing elastic collision";
  scene.dimensions = 2;
  scene.duration_s = 1.6;
  scene.restitution = 1.0;
  scene.bodies.push_back(disk("cue", {-1.0, 0.2}, {1.5, 0.0}));
  scene.bodies.push_back(disk("object", {0.0, 0.0}, {0.0, 0.0}));
  scene.view.momentum_diagram = true;
  scene.view.center_of_mass = true;
  scene.view.trail_s = 0.6;
  return scene;
}

TEST(VisualsGLTest, GlancingCollision2D) {
  const compose::FrameSource source = app::animate(glancing(), {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(1.1), "glancing_2d"));
}

TEST(VisualsGLTest, NewtonsCradle) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("newtons-cradle"), {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(1.5), "newtons_cradle"));
}

// The swinging cradle at three instants: the pulled ball coming down (0.2 s), just after it hits
// the row (the quarter period sqrt(L/g) K(sin 15 degrees) = 0.3606 s), and at the top of the
// far ball's swing (half a period).
TEST(VisualsGLTest, NewtonsCradleSwings) {
  const double quarter =
      std::sqrt(0.5 / 9.81) * std::comp_ellint_1(std::sin(std::numbers::pi / 12));
  const compose::FrameSource source =
      app::animate(scene::loadPreset("newtons-cradle"), {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(0.2), "newtons_cradle_before"));
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(quarter + 0.02), "newtons_cradle_after"));
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(2.0 * quarter), "newtons_cradle_top"));
}

// The ballistic pendulum: the bullet on its way (1 ms), just after it stopped inside the block,
// and past the top of the swing, with the rise h and the speed it gives back.
TEST(VisualsGLTest, BallisticPendulumRise) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("ballistic-pendulum"), {kWidth, kHeight}).frames;
  // Hit after (0.5 - 0.125) m / 200 m/s; top a quarter period of the 1 m string later at the
  // amplitude acos(1 - h / L), h = (2 / 1.01)^2 / (2 g).
  const double hit = (0.5 - 0.125) / 200.0;
  const double v = 2.0 / 1.01, h = v * v / (2.0 * 9.81);
  const double top =
      hit + std::sqrt(1.0 / 9.81) * std::comp_ellint_1(std::sin(0.5 * std::acos(1.0 - h / 1.0)));
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(0.001), "ballistic_pendulum_before"));
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(hit + 0.02), "ballistic_pendulum_after"));
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(top + 0.01), "ballistic_pendulum_top"));
}

TEST(VisualsGLTest, BouncingBallStrobe) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("bouncing-ball"), {kWidth, kHeight}).frames;
  // The rate is chosen so no image overlaps the next. The ball (radius 0.12 m) keeps its
  // sideways 0.6 m/s throughout (the floor is smooth), so images 1/rate apart are at least
  // 0.6 m/s / rate apart sideways: they clear one diameter (0.24 m) from 2.5 images per second
  // down. At any faster round rate the images at the top of the last, tiny hops would overlap.
  const double rate_hz = source.strobeRate_hz();
  EXPECT_EQ(rate_hz, 2.5);
  const frame::FrameModel frame = source.strobeFrame(0.0);
  // 4 s at 2.5 per second: 11 images, the last one solid. No flash catches a bounce, so the ball
  // is also drawn touching the floor at each bounce whose image clears every flash's and every
  // earlier bounce's (the first always). Where it was: from the simulation, bounces from its
  // event log.
  const physics::Timeline& timeline = source.timeline();
  const auto at = [&](double t_s) { return timeline.sample(t_s).bodies.front().position_m; };
  constexpr double kDiameter_m = 0.24;
  std::vector<core::Vec2> kept;
  for (int k = 0; k <= 10; ++k) kept.push_back(at(k / rate_hz));
  std::size_t bounces = 0;
  for (const physics::CollisionEvent& bounce : timeline.collisions()) {
    ASSERT_TRUE(bounce.hitsWall());
    if (bounce.time_s >= 4.0) continue;
    const core::Vec2 there = at(bounce.time_s);
    EXPECT_NEAR(there.y(), 0.5 * kDiameter_m, 1e-9) << "on the floor at " << bounce.time_s;
    bool clear = true;
    for (const core::Vec2& image : kept) clear = clear && (image - there).norm() >= kDiameter_m;
    if (bounces > 0 && !clear) continue;
    kept.push_back(there);
    ++bounces;
  }
  EXPECT_GE(bounces, 1u);
  EXPECT_EQ(frame.panels.front().ghosts.size(), 10u + bounces);
  EXPECT_TRUE(matchesGolden(frame, "bouncing_ball_strobe"));
}

TEST(VisualsGLTest, ComparisonPanels) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("compare-restitution"), {640, 360}).frames;
  const frame::FrameModel frame = source.frameAtSimulated(2.5);
  ASSERT_EQ(frame.panels.size(), 3u);
  EXPECT_EQ(frame.panels[0].heading, "e = 1");
  EXPECT_EQ(frame.panels[2].heading, "e = 0");
  EXPECT_TRUE(matchesGolden(frame, "compare_restitution", 640, 360));
}

TEST(VisualsGLTest, EnergyChartAlone) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("worked-example"), {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.chartFrame(), "worked_example_chart"));
}

TEST(VisualsGLTest, DarkThemeWithChart) {
  scene::SceneDesc scene = scene::loadPreset("worked-example");
  scene.view.theme = "dark";
  scene.view.chart = true;
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(2.5), "theme_dark"));
}

TEST(VisualsGLTest, HighContrastTheme) {
  scene::SceneDesc scene = scene::loadPreset("worked-example");
  scene.view.theme = "high-contrast";
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(2.5), "theme_high_contrast"));
}

// Issue 18's numbers and springs: a soft contact half-way through (spring drawn, its energy on
// the bar, the loss so far) and after it; the air track's bumpers squeezed in its first contact;
// the car crash's energies in kJ and momentum grouped in thousands.
double midContact_s(const compose::FrameSource& source, const scene::SceneDesc& scene) {
  return source.timeline().collisions().at(0).time_s + 0.5 * scene.contact.duration_s;
}

TEST(VisualsGLTest, SoftContactHalfWayAndAfter) {
  const scene::SceneDesc scene = scene::loadPreset("soft-contact");
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  EXPECT_TRUE(
      matchesGolden(source.frameAtSimulated(midContact_s(source, scene)), "soft_contact_mid"));
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(2.0), "soft_contact_after"));
}

TEST(VisualsGLTest, AirTrackBumpersInContact) {
  const scene::SceneDesc scene = scene::loadPreset("air-track");
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(midContact_s(source, scene)), "air_track_mid"));
}

TEST(VisualsGLTest, CarCrashAfterTheImpact) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset("car-crash"), {kWidth, kHeight}).frames;
  EXPECT_TRUE(matchesGolden(source.frameAtSimulated(1.8), "car_crash"));
}

TEST(VisualsTest, CentreOfMomentumFrameHasZeroTotalMomentum) {
  scene::SceneDesc scene = scene::loadPreset("worked-example");
  scene.view.center_of_momentum_frame = true;
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  for (double t : {0.0, 1.0, 2.5}) {
    const frame::PanelModel panel = source.frameAtSimulated(t).panels.front();
    double p = 0.0;
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      p += scene.bodies[i].mass_kg * panel.bodies[i].velocity_mps.x();
    }
    EXPECT_NEAR(p, 0.0, 1e-12) << t;
  }
  // Before the collision the carts close at 3 m/s, symmetric about the frame: +1.5 and -1.5 m/s.
  const frame::PanelModel start = source.frameAtSimulated(0.0).panels.front();
  EXPECT_NEAR(start.bodies[0].velocity_mps.x(), 1.5, 1e-12);
  EXPECT_NEAR(start.bodies[1].velocity_mps.x(), -1.5, 1e-12);
}

TEST(VisualsTest, SlowMotionStretchesPlaybackButReadoutsKeepSimulatedTime) {
  scene::SceneDesc scene = scene::loadPreset("worked-example");
  scene.view.slow_motion_factor = 4.0;
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  EXPECT_GT(source.duration_s(), scene.duration_s + 0.5);
  EXPECT_EQ(source.frameAt(source.duration_s()).time_readout, "t = 4.000 s");
  // At the collision (t = 7/6 s) playback runs 4 times slower, and the frame says so.
  const double t_c = 7.0 / 6.0;
  double lo = 0.0, hi = source.duration_s();
  for (int i = 0; i < 60; ++i) {  // playback time showing t_c, by bisection
    const double mid = 0.5 * (lo + hi);
    (source.simulatedAt(mid) < t_c ? lo : hi) = mid;
  }
  const double dp = 1e-3;
  EXPECT_NEAR((source.simulatedAt(lo + dp) - source.simulatedAt(lo - dp)) / (2 * dp), 0.25, 1e-3);
  EXPECT_EQ(source.frameAt(lo).subtitle, "slow motion ×4");
}

TEST(VisualsTest, TimeMapIsMonotoneAndIdentityWithoutSlowMotion) {
  const compose::TimeMap identity(4.0, {1.0, 2.0}, 1.0);
  EXPECT_DOUBLE_EQ(identity.playbackDuration_s(), 4.0);
  EXPECT_DOUBLE_EQ(identity.simulatedAt(1.7), 1.7);
  const compose::TimeMap slow(4.0, {1.0, 2.0}, 3.0);
  double previous = -1.0;
  for (double p = 0.0; p <= slow.playbackDuration_s(); p += 0.01) {
    const double t = slow.simulatedAt(p);
    EXPECT_GT(t, previous);
    previous = t;
  }
  EXPECT_DOUBLE_EQ(slow.simulatedAt(slow.playbackDuration_s()), 4.0);
}

}  // namespace
}  // namespace collide
