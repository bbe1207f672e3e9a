// Extreme but valid values: masses 1e-6 and 1e9 kg, speeds 1e-6 and 1e4 m/s, in every pairing, 1D
// and 2D, with and without walls and gravity, e in {0, 0.5, 1}. Each run must end, stay finite,
// never overlap, and obey the definition of e and the conservation laws to rounding.
//
// How a run may end (everything else completes):
// - Rate cap: with e = 1 between walls, a light body trapped by a heavy one is pumped ever
//   faster (the heavy one falls onto it under gravity and is held up by its bounces, like a gas
//   spring, or drives it as a piston at 1e4 m/s); collisions come ever closer, without end. The run
//   stops at max_collisions_per_second with its warning. Only a mass ratio other than 1 does this.
// - Stall: in 2D with e = 0 under gravity a disk can come to rest on another disk, which the
//   event-driven model does not follow (documented); the run stops there with its warning.
//
// Tolerances, from floating-point analysis (unit roundoff 2^-53 = 1.1e-16):
// - A velocity update v' = v + J / m rounds v' to half an ulp; with a mass ratio of 1e15 the
//   heavy body's change can vanish in that rounding. So the normal relative velocity after an
//   impact, and the total momentum, are exact to a few ulps of the largest velocity (momentum)
//   involved: 1e-14 of that scale (about 45 ulps) bounds them.
// - Mechanical energy sums kinetic terms 1/2 m v^2 and potential terms -m g.x of both signs, each
//   rounded (the state itself holds x to half an ulp of |x|). Its error is a few ulps of the
//   largest terms, not of the total: a 1e9 kg disk 1 m below the origin carries -1e10 J of
//   potential energy, whose ulp (2e-6 J) is far above a total of 5e-4 J. Energy never grows, so
//   kinetic energy stays below KE0 + PE0 - PE(x), and every term is bounded by
//   KE0 + 3 sum m |g| R, with R the largest |x| inside the walls: 1e-14 of that.
// - These errors add up over collisions (thousands of wall bounces at 1e4 m/s), at most linearly:
//   energy and momentum are held to 1e-14 of their scale per collision so far.
// - Positions: a time of impact is exact to half an ulp of t, so a body at speed v can stand
//   v ulp(t) / 2 past a contact at the impact instant (and at the last sample of a stopped run,
//   which falls on one). Regular motion, 1e4 m/s at t < 2 s: 2e-12 m. The pumped bodies of the
//   rate-cap runs are the fastest: 1e9 m/s in 1D, reached by t = 5.5e-4 s (ulp 1.1e-19 s:
//   1e-10 m) or 1e6 m/s by t = 1.06 s (ulp 2.2e-16 s: 1.1e-10 m), 6e6 m/s in 2D by t = 0.17 s
//   (ulp 2.8e-17 s: 2e-10 m). Conservative advancement in 2D may pass a contact by 1e-10 m.
//   Overlap beyond 1e-9 m is therefore a defect.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;
using testing::disk;
using testing::wall;

constexpr double kMasses_kg[] = {1e-6, 1.0, 1e9};
constexpr double kSpeeds_mps[] = {1e-6, 1.0, 1e4};
constexpr double kRestitutions[] = {0.0, 0.5, 1.0};
constexpr double kRelative = 1e-14;
constexpr double kOverlap_m = 1e-9;
// Collisions per simulated second that stop a pumping cascade. The fastest regular motion here is
// a body at 1e4 m/s between walls 4 m apart, 2,500 wall hits per second per axis: 1e5 is 20 times
// that. The default (1e8) would stop the same cascades after 1,000 times the work (minutes in 2D);
// the guard itself is tested in rate_cap_test.cpp.
constexpr std::int64_t kRateCap = 100'000;

struct Case {
  int mass_a, mass_b, speed_a, speed_b, e;  // indices into the tables above
  bool walls_and_gravity;
};

Case caseOf(const std::tuple<int, int, int, int, int, bool>& p) {
  return {std::get<0>(p), std::get<1>(p), std::get<2>(p),
          std::get<3>(p), std::get<4>(p), std::get<5>(p)};
}

bool finite(const core::Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

// |x| + |y|: a speed scale that, unlike the Euclidean norm, does not underflow at 1e-170.
double size(const core::Vec2& v) {
  return std::abs(v.x()) + std::abs(v.y());
}

void checkEvents(const Timeline& timeline) {
  for (const CollisionEvent& event : timeline.collisions()) {
    ASSERT_TRUE(std::isfinite(event.time_s) && finite(event.velocity_a_after_mps) &&
                finite(event.velocity_b_after_mps))
        << "collision " << event.index;
    const double before =
        (event.velocity_a_before_mps - event.velocity_b_before_mps).dot(event.normal);
    const double after =
        (event.velocity_a_after_mps - event.velocity_b_after_mps).dot(event.normal);
    const double scale = size(event.velocity_a_before_mps) + size(event.velocity_b_before_mps) +
                         size(event.velocity_a_after_mps) + size(event.velocity_b_after_mps);
    ASSERT_NEAR(after, -event.restitution * before, kRelative * scale)
        << "collision " << event.index;
  }
}

// Bound on every kinetic and potential term of the mechanical energy (see the header); R is the
// largest |x| inside the walls (1D: 10 m; 2D: the corner of the 4 m box, 2 sqrt 2 m).
double energyScale(const Timeline& timeline) {
  const WorldDef& world = timeline.world();
  const double reach_m = world.dimensions == 1 ? 10.0 : 2.0 * std::sqrt(2.0);
  double potential = 0.0;
  for (const BodyDef& body : world.bodies) {
    potential += body.mass_kg * world.gravity_mps2.norm() * reach_m;
  }
  return timeline.initialKineticEnergy() + 3.0 * potential;
}

// Energy never grows (mechanical energy with gravity), momentum is kept without walls and gravity,
// and nothing overlaps, at 200 sampled times.
void checkSamples(const Timeline& timeline, bool walls_and_gravity) {
  const WorldDef& world = timeline.world();
  const Snapshot first = timeline.sample(0.0);
  double momentum_scale = 0.0;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    momentum_scale += world.bodies[i].mass_kg * size(first.bodies[i].velocity_mps);
  }
  const double energy_scale = energyScale(timeline);
  const double start_energy = timeline.mechanicalEnergy(first);
  const double collisions = 1.0 + static_cast<double>(timeline.collisionCount());
  for (int k = 0; k <= 200; ++k) {
    const Snapshot s = timeline.sample(timeline.simulatedUntil_s() * k / 200.0);
    for (const BodyState& body : s.bodies) {
      ASSERT_TRUE(finite(body.position_m) && finite(body.velocity_mps)) << "sample " << k;
    }
    ASSERT_LE(timeline.mechanicalEnergy(s), start_energy + kRelative * collisions * energy_scale)
        << "sample " << k;
    if (!walls_and_gravity) {
      ASSERT_LE((timeline.momentum(s) - timeline.momentum(first)).norm(),
                kRelative * collisions * momentum_scale)
          << "sample " << k;
    }
    for (std::size_t a = 0; a < s.bodies.size(); ++a) {
      const double half =
          world.dimensions == 1 ? 0.5 * world.bodies[a].size_m : world.bodies[a].size_m;
      for (const WallDef& w : world.walls) {
        const double clearance = world.dimensions == 1
                                     ? (s.bodies[a].position_m.x() - w.point_m.x()) * w.normal.x()
                                     : (s.bodies[a].position_m - w.point_m).dot(w.normal);
        ASSERT_GE(clearance - half, -kOverlap_m) << "sample " << k << " wall " << w.name;
      }
    }
    const double gap = world.dimensions == 1
                           ? s.bodies[1].position_m.x() - s.bodies[0].position_m.x() -
                                 0.5 * (world.bodies[0].size_m + world.bodies[1].size_m)
                           : (s.bodies[1].position_m - s.bodies[0].position_m).norm() -
                                 world.bodies[0].size_m - world.bodies[1].size_m;
    ASSERT_GE(gap, -kOverlap_m) << "sample " << k;
  }
}

// Besides the one that says why a run stopped, the only warning allowed is the collapse guard's
// note (e = 0.5 under gravity: the bounces of a resting body are ended by it).
const Warning& stopWarning(const Timeline& timeline) {
  const std::vector<Warning>& warnings = timeline.warnings();
  for (std::size_t k = 0; k + 1 < warnings.size(); ++k) {
    EXPECT_EQ(warnings[k].kind, WarningKind::kCollapseRule) << warnings[k].message;
  }
  return warnings.back();
}

// A warning the user can read: one sentence, saying when the run stopped and that nothing later
// was simulated.
void expectOneSentenceAboutTheStop(const Warning& warning) {
  const std::string& text = warning.message;
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_EQ(text.find(". "), std::string::npos) << text;
  EXPECT_EQ(text.rfind("stopped at t = ", 0), 0u) << text;
  const std::string ending = "; later states are not simulated";
  EXPECT_TRUE(text.size() > ending.size() &&
              text.compare(text.size() - ending.size(), ending.size(), ending) == 0)
      << text;
}

// The rate cap's claim, checked on the event log: more than kRateCap collisions fell within the
// last simulated second.
void expectRateCapStop(const Timeline& timeline, const Case& c) {
  EXPECT_EQ(kRestitutions[c.e], 1.0);
  EXPECT_TRUE(c.walls_and_gravity);
  EXPECT_NE(c.mass_a, c.mass_b);
  ASSERT_FALSE(timeline.warnings().empty());
  EXPECT_EQ(stopWarning(timeline).kind, WarningKind::kCollisionRateCap);
  expectOneSentenceAboutTheStop(stopWarning(timeline));
  std::int64_t last_second = 0, seen = 0;
  timeline.replayCollisions([&](const CollisionEvent& event) {
    ++seen;
    last_second += event.time_s > timeline.simulatedUntil_s() - 1.0 ? 1 : 0;
  });
  EXPECT_EQ(seen, timeline.collisionCount());
  EXPECT_GE(last_second, kRateCap);
}

// The stall's claim: the last collision was an inelastic disk-disk impact that left the two with
// no normal relative velocity while gravity pressed them together.
void expectRestingStackStop(const Timeline& timeline, const Case& c) {
  const WorldDef& world = timeline.world();
  EXPECT_EQ(world.dimensions, 2);
  EXPECT_EQ(kRestitutions[c.e], 0.0);
  EXPECT_TRUE(c.walls_and_gravity);
  ASSERT_FALSE(timeline.warnings().empty());
  const Warning& warning = stopWarning(timeline);
  EXPECT_EQ(warning.kind, WarningKind::kStalled);
  expectOneSentenceAboutTheStop(warning);
  const CollisionEvent& last = timeline.collisions().back();
  ASSERT_FALSE(last.hitsWall());
  EXPECT_EQ(last.restitution, 0.0);
  EXPECT_EQ(warning.time_s, last.time_s);
  const double normal_after =
      (last.velocity_a_after_mps - last.velocity_b_after_mps).dot(last.normal);
  EXPECT_NEAR(normal_after, 0.0,
              kRelative * (size(last.velocity_a_before_mps) + size(last.velocity_b_before_mps)));
  EXPECT_NE(last.normal.dot(world.gravity_mps2), 0.0);
  const Snapshot at = timeline.sample(last.time_s);
  const bool b_above = (at.bodies[last.body_b].position_m - at.bodies[last.body_a].position_m)
                           .dot(world.gravity_mps2) < 0.0;
  const std::string& upper = world.bodies[b_above ? last.body_b : last.body_a].name;
  const std::string& lower = world.bodies[b_above ? last.body_a : last.body_b].name;
  EXPECT_NE(warning.message.find("disk \"" + upper + "\" came to rest on disk \"" + lower + "\""),
            std::string::npos)
      << warning.message;
}

void expectEnds(const Timeline& timeline, const Case& c) {
  switch (timeline.status()) {
    case SimulationStatus::kComplete:
      for (const Warning& warning : timeline.warnings()) {
        EXPECT_EQ(warning.kind, WarningKind::kCollapseRule) << warning.message;
      }
      return;
    case SimulationStatus::kCollisionRateCapReached:
      expectRateCapStop(timeline, c);
      return;
    case SimulationStatus::kStalled:
      expectRestingStackStop(timeline, c);
      return;
    case SimulationStatus::kCollisionCapReached:
      ADD_FAILURE() << "the collision cap is a backstop; the rate cap must come first";
      return;
  }
}

WorldDef lineWorld(const Case& c) {
  WorldDef world;
  world.dimensions = 1;
  world.duration_s = 2.0;
  world.restitution = kRestitutions[c.e];
  world.max_collisions = 2'000'000;
  world.max_collisions_per_second = kRateCap;
  world.bodies = {block("a", kMasses_kg[c.mass_a], 1.0, 3.0, kSpeeds_mps[c.speed_a]),
                  block("b", kMasses_kg[c.mass_b], 1.0, 7.0, -kSpeeds_mps[c.speed_b])};
  if (c.walls_and_gravity) {
    world.walls = {wall("left", {0.0, 0.0}, {1.0, 0.0}, world.restitution),
                   wall("right", {10.0, 0.0}, {-1.0, 0.0}, world.restitution)};
    world.gravity_mps2 = {-9.81, 0.0};
  }
  return world;
}

WorldDef planeWorld(const Case& c) {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 2.0;
  world.restitution = kRestitutions[c.e];
  world.max_collisions = 2'000'000;
  world.max_collisions_per_second = kRateCap;
  world.bodies = {
      disk("a", kMasses_kg[c.mass_a], 0.3, {-1.0, 0.0}, {kSpeeds_mps[c.speed_a], 0.0}),
      disk("b", kMasses_kg[c.mass_b], 0.2, {1.0, 0.25}, {-kSpeeds_mps[c.speed_b], 0.0})};
  if (c.walls_and_gravity) {
    world.walls = testing::boxWalls(2.0, world.restitution);
    world.gravity_mps2 = {0.0, -9.81};
  }
  return world;
}

// The event checks above loop over the collisions, so a case without any checks nothing there:
// say which cases must collide and check the others' free flight instead. Walls and gravity
// always bring a collision within the 2 s; in free space the bodies meet only if their closing
// speed covers the gap (`gap_m`) in time (the 1e-6 m/s pairs do not: 12 cases of each matrix).
void expectCollisionsWherePredicted(const Timeline& timeline, const Case& c, double gap_m) {
  const WorldDef& world = timeline.world();
  const double closing_mps = kSpeeds_mps[c.speed_a] + kSpeeds_mps[c.speed_b];
  if (c.walls_and_gravity || closing_mps * world.duration_s > gap_m) {
    EXPECT_GT(timeline.collisionCount(), 0) << "closing at " << closing_mps << " m/s";
    return;
  }
  EXPECT_EQ(timeline.collisionCount(), 0);
  const double t = world.duration_s;
  const Snapshot end = timeline.sample(t);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const core::Vec2 expected = world.bodies[i].position_m + world.bodies[i].velocity_mps * t;
    EXPECT_NEAR(end.bodies[i].position_m.x(), expected.x(), 1e-15 * (1.0 + std::abs(expected.x())))
        << world.bodies[i].name;
    if (world.dimensions == 2) {
      EXPECT_EQ(end.bodies[i].position_m.y(), expected.y()) << world.bodies[i].name;
    }
    EXPECT_EQ(end.bodies[i].velocity_mps.x(), world.bodies[i].velocity_mps.x());
  }
}

// Every check above on one case's run; `gap_m`: the distance the bodies close to meet.
void expectSoundRun(const Timeline& timeline, const Case& c, double gap_m) {
  expectCollisionsWherePredicted(timeline, c, gap_m);
  expectEnds(timeline, c);
  checkEvents(timeline);
  checkSamples(timeline, c.walls_and_gravity);
}

// Every mass, speed and restitution pairing, with and without walls and gravity.
const auto kCaseMatrix =
    ::testing::Combine(::testing::Values(0, 2), ::testing::Values(0, 2), ::testing::Values(0, 2),
                       ::testing::Values(0, 2), ::testing::Range(0, 3), ::testing::Bool());

class ExtremeLineTest : public ::testing::TestWithParam<std::tuple<int, int, int, int, int, bool>> {
};

// Block a (1 m wide, centred at 3 m) moves right, block b (centred at 7 m) moves left, between
// walls at 0 and 10 m; gravity pulls towards the left wall.
TEST_P(ExtremeLineTest, EndsFiniteWithoutOverlapObeyingConservationAndE) {
  const Case c = caseOf(GetParam());
  expectSoundRun(simulate(lineWorld(c)), c, 7.0 - 3.0 - 1.0);
}

INSTANTIATE_TEST_SUITE_P(Matrix, ExtremeLineTest, kCaseMatrix);

class ExtremePlaneTest
    : public ::testing::TestWithParam<std::tuple<int, int, int, int, int, bool>> {};

// Disk a (radius 0.3 m) at (-1, 0) and disk b (0.2 m) at (1, 0.25) head for each other off-centre
// in a 4 m box; gravity pulls down.
TEST_P(ExtremePlaneTest, EndsFiniteWithoutOverlapObeyingConservationAndE) {
  const Case c = caseOf(GetParam());
  // The disks touch when their centres are 0.5 m apart, 0.25 m of it across the x axis.
  expectSoundRun(simulate(planeWorld(c)), c, 2.0 - std::sqrt(0.5 * 0.5 - 0.25 * 0.25));
}

INSTANTIATE_TEST_SUITE_P(Matrix, ExtremePlaneTest, kCaseMatrix);

// The heavy case behind the energy tolerance: a 1e9 kg disk drifting at 1e-6 m/s falls freely
// until it lands on the floor at y = -2 m (its centre at -1.7 m, after sqrt(2 * 1.7 / 9.81) s).
// Its mechanical energy is 5e-4 J, a sum of terms that reach 1.7e10 J, so checking it to 1e-14 of
// itself is beyond double precision; the trajectory, though, must be exact to a few ulps of its
// terms, x0 + v0 t + g t^2 / 2, computed here in long double.
TEST(ExtremeFallTest, HeavyDiskFallsExactlyAsComputedInLongDouble) {
  const Case c{2, 0, 0, 0, 0, true};
  const Timeline timeline = simulate(planeWorld(c));
  const long double g = 9.81L, vx = 1e-6L;
  const double landing_s = std::sqrt(2.0 * 1.7 / 9.81);
  for (int k = 0; k < 100; ++k) {
    const double t = landing_s * k / 100.0;
    const BodyState body = timeline.sample(t).bodies[0];
    const long double x = -1.0L + vx * t, y = -0.5L * g * t * t;
    const double ulp = 0x1.0p-52;
    EXPECT_NEAR(body.position_m.x(), static_cast<double>(x), 4 * ulp * (1.0 + 1e-6 * t)) << t;
    EXPECT_NEAR(body.position_m.y(), static_cast<double>(y), 4 * ulp * std::abs(y)) << t;
    EXPECT_NEAR(body.velocity_mps.x(), 1e-6, 4 * ulp * 1e-6) << t;
    EXPECT_NEAR(body.velocity_mps.y(), static_cast<double>(-g * t), 4 * ulp * g * t) << t;
  }
}

}  // namespace
}  // namespace collide::physics
