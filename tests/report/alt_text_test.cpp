// Alt text and parameter lines say what the physics says.
#include "report/alt_text.hpp"

#include <gtest/gtest.h>

#include "report/plain_numbers.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

using test::contains;

TEST(AltTextTest, PlainNumbersHaveThreeSignificantDigits) {
  EXPECT_EQ(plainNumber(2.0), "2");
  EXPECT_EQ(plainNumber(0.5), "0.5");
  EXPECT_EQ(plainNumber(2.0 / 3.0), "0.667");
  EXPECT_EQ(plainNumber(7.0 / 6.0), "1.17");
  EXPECT_EQ(plainNumber(1234.6), "1230");                // three figures, never an exponent
  EXPECT_EQ(plainNumber(-0.0001234), "\u22120.000123");  // a true minus sign
  EXPECT_EQ(plainNumber(-1e-20 * 0.0), "0");
  EXPECT_EQ(percentOf(1.0, 3.0), "33.3%");
  EXPECT_EQ(percentOf(1.0, 4.0), "25.0%");  // a computed share keeps its three figures
  EXPECT_EQ(motionInWords({0.0, 2.0}, 2), "moving at 2.00 m/s towards 90°");
}

TEST(AltTextTest, StillAfterTheCollisionDescribesPositionsAndEnergy) {
  // After the impact at 0.5 s: left at 1.5 m/s from x = 0.5 m, right at 3 m/s from x = 1 m.
  // At t = 1 s: left at 0.5 + 0.75 = 1.25 m, right at 1 + 1.5 = 2.5 m. 2.25 J of 9 J lost.
  const physics::Timeline timeline = physics::simulate(test::twoBlocks(0.5));
  const std::string text = describeStill(timeline, "Two blocks", 1.0);
  EXPECT_TRUE(
      contains(text, "Still image at t = 1.000 s of a collision simulation (\"Two blocks\")"))
      << text;
  EXPECT_TRUE(contains(text, "2 blocks slide on a horizontal track")) << text;
  EXPECT_TRUE(contains(text, "Left (2 kg) is at x = 1.25 m, moving right at 1.50 m/s.")) << text;
  EXPECT_TRUE(contains(text, "Right (1 kg) is at x = 2.50 m, moving right at 3.00 m/s.")) << text;
  EXPECT_TRUE(contains(text, "1 collision has happened so far.")) << text;
  EXPECT_TRUE(contains(text, "shows 6.75 J of kinetic energy and 2.25 J (25.0%) turned into heat"))
      << text;
  const std::string before = describeStill(timeline, "", 0.25);
  EXPECT_TRUE(contains(before, "No collision has happened yet.")) << before;
  EXPECT_TRUE(contains(before, "and no energy lost.")) << before;
}

TEST(AltTextTest, PanelsAreEachDescribedUnderTheirOwnHeading) {
  // e = 1 keeps all 9 J; e = 0.5 loses 1/2 mu (1 - e^2) u^2 = 1/2 (2/3) (3/4) 9 = 2.25 J (25%).
  const physics::Timeline elastic = physics::simulate(test::twoBlocks(1.0));
  const physics::Timeline half = physics::simulate(test::twoBlocks(0.5));
  const std::string text = describePanels({{"e = 1", &elastic}, {"e = 0.5", &half}}, "", 1.0);
  EXPECT_TRUE(contains(text, "2 panels compare e = 1 and e = 0.5.")) << text;
  EXPECT_TRUE(contains(text, "Panel e = 1: 2 blocks slide")) << text;
  EXPECT_TRUE(contains(text, "Panel e = 0.5: 2 blocks slide")) << text;
  const std::size_t second = text.find("Panel e = 0.5:");
  EXPECT_TRUE(contains(text.substr(0, second), "and no energy lost.")) << text;
  EXPECT_TRUE(contains(text.substr(second), "2.25 J (25.0%) turned into heat")) << text;
}

TEST(AltTextTest, OneBodyIsSingular) {
  physics::WorldDef world = test::twoBlocks(0.5);
  world.bodies.pop_back();
  const std::string text = describeStill(physics::simulate(world), "", 0.5);
  EXPECT_TRUE(contains(text, "1 block slides on a horizontal track.")) << text;
}

// Gliders on an air track are gliders in words too, not blocks.
TEST(AltTextTest, GlidersRideOnAnAirTrack) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocks(0.5));
  const std::string text = describeStill(timeline, "", 0.25, true);
  EXPECT_TRUE(contains(text, "2 gliders ride on an air track.")) << text;
  EXPECT_FALSE(contains(text, "block")) << text;
}

TEST(AltTextTest, ParametersListEveryBodyAndWall) {
  const std::string text = describeParameters(physics::simulate(test::twoBlocksAndWall(0.5)));
  EXPECT_EQ(text,
            "1D; e = 0.5; duration 4 s; left: 2 kg, 0.5 m wide, x = \u22121 m, v = 3 m/s; "
            "right: 1 kg, 0.5 m wide, x = 1 m, v = 0 m/s; wall far: at x = 3 m, e = 1");
}

}  // namespace
}  // namespace collide::report
