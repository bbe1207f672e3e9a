// Determinism: fixed scenes give a bit-identical event log on every run and every build made
// with -ffp-contract=off. The constants below are the hashes of the current algorithm; if the
// algorithm changes on purpose, run this test, check the new values are stable over two runs,
// and paste them here (the failure message prints them).
//
// The recorded hashes are a change detector, not a check of correctness: they were produced by
// this program, so they say only that nothing changed. Correctness lives in the closed-form,
// conservation and property tests.
#include <gtest/gtest.h>

#include <cstdio>

#include "physics/event_hash.hpp"
#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "random_scenes.hpp"

namespace collide::physics {
namespace {

WorldDef fixedScene(int kind) {
  switch (kind) {
    case 0:
      return piBlocksWorld(5);
    case 1: {
      testing::Dice dice(7);
      testing::SceneTraits traits;
      WorldDef world;
      for (int k = 0; k < 40; ++k) world = testing::randomLine(dice, traits);  // walls and merges
      world.gravity_mps2 = {-3.0, 0.0};
      return world;
    }
    case 2: {
      testing::Dice dice(11);
      testing::SceneTraits traits;
      WorldDef world;
      for (int k = 0; k < 5; ++k) world = testing::randomPlane(dice, traits);
      world.inelastic_mode = InelasticMode::kStick;
      world.walls = testing::boxWalls(2.0, 0.9);
      world.restitution = 0.0;
      world.gravity_mps2 = {0.0, 0.0};
      return world;
    }
    default: {
      testing::Dice dice(13);
      testing::SceneTraits traits;
      WorldDef world = testing::randomPlane(dice, traits);
      world.contact_model = ContactModel::kSpringDamper;
      world.gravity_mps2 = {0.0, 0.0};
      world.restitution = 0.8;
      return world;
    }
  }
}

constexpr std::uint64_t kExpected[4] = {0x01a0a31661047c90ull, 0xf6c292b511b8330bull,
                                        0x45b4a623c6ea4fbdull, 0x1c051b105ea49ea4ull};

TEST(DeterminismTest, EventLogIsIdenticalOnTwoRunsAndUnchangedSinceRecorded) {
  for (int kind = 0; kind < 4; ++kind) {
    const WorldDef world = fixedScene(kind);
    const Timeline first = simulate(world), second = simulate(world);
    EXPECT_GT(first.collisionCount(), 0) << kind;
    const std::uint64_t hash = hashEventLog(first);
    EXPECT_EQ(hash, hashEventLog(second)) << "scene " << kind << " differs between runs";
    EXPECT_EQ(hash, kExpected[kind]) << "scene " << kind << ": 0x" << std::hex << hash;
  }
}

}  // namespace
}  // namespace collide::physics
