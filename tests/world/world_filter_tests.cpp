// Collision filters: pairs whose filters do not meet pass through each other (no contact, no
// response, no overlap complaint), groups override the bits, walls filter too, a filter changed
// between steps takes effect at once, filters that meet everything change no bit, and filters
// travel through save and load.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <vector>

#include "ball_def.hpp"
#include "carom/error.hpp"
#include "carom/filter.hpp"
#include "carom/world.hpp"

namespace carom::filter_tests {
namespace {

CollisionFilter only(std::uint64_t category) { return {category, category, 0}; }

using testing::ball_def;

// A box gas of two kinds, even and odd, with the given filter for each kind.
World two_kinds(const CollisionFilter& even, const CollisionFilter& odd, bool with_odd = true) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {40.0, 40.0}});
  std::mt19937_64 engine(5);
  std::normal_distribution<double> speed(0.0, 1.0);
  int k = 0;
  for (int row = 0; row < 14; ++row) {
    for (int column = 0; column < 14; ++column, ++k) {
      const BallDef def =
          ball_def({1.5 + column * 2.7, 1.5 + row * 2.7}, {speed(engine), speed(engine)});
      if (k % 2 == 0) {
        world.add_ball(def, even);
      } else if (with_odd) {
        world.add_ball(def, odd);
      }
    }
  }
  world.set_contact_recording(true);
  return world;
}

TEST(WorldFilter, KindsThatDoNotMeetPassThroughEachOtherAndMoveAsIfAlone) {
  World both = two_kinds(only(1), only(2));
  World alone = two_kinds(only(1), only(2), false);
  std::uint64_t between = 0;
  std::uint64_t within = 0;
  for (int step = 0; step < 40; ++step) {
    both.step(0.5);
    alone.step(0.5);
    for (const ContactEvent& c : both.contacts()) {
      if (c.kind != ContactKind::ball_ball) continue;
      (both.filter(c.a).category == both.filter(c.b).category ? within : between) += 1;
    }
    ASSERT_EQ(both.audit(), std::nullopt);  // overlaps between the kinds break no promise
  }
  EXPECT_EQ(between, 0u);
  EXPECT_GT(within, 200u);
  // The even balls, with the odd ones passing through, move as in a world without them (to the
  // rounding of re-planned grids and re-based positions).
  const std::vector<BallId> ids = alone.balls();
  std::size_t checked = 0;
  for (const BallId id : both.balls()) {
    if (both.filter(id).category != 1) continue;
    const BallId twin = ids[checked++];
    EXPECT_NEAR(both.position(id).x, alone.position(twin).x, 1e-6);
    EXPECT_NEAR(both.position(id).y, alone.position(twin).y, 1e-6);
  }
  EXPECT_EQ(checked, ids.size());
}

TEST(WorldFilter, FiltersThatMeetEverythingChangeNoBit) {
  // Category 3, every mask bit: a filter of its own, which still meets every other ball.
  World plain = two_kinds({}, {});
  World filtered = two_kinds({}, {3, ~0ULL, 0});
  for (int step = 0; step < 20; ++step) {
    plain.step(0.5);
    filtered.step(0.5);
  }
  ASSERT_EQ(plain.collision_count(), filtered.collision_count());
  const std::vector<BallId> a = plain.balls();
  const std::vector<BallId> b = filtered.balls();
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(plain.position(a[i]), filtered.position(b[i]));
    ASSERT_EQ(plain.velocity(a[i]), filtered.velocity(b[i]));
  }
}

TEST(WorldFilter, GroupsOverrideTheBits) {
  EXPECT_FALSE(should_collide({1, ~0ULL, -3}, {1, ~0ULL, -3}));  // a negative group never meets
  EXPECT_TRUE(should_collide({1, 0, 4}, {2, 0, 4}));             // a positive one always does
  EXPECT_TRUE(should_collide({1, ~0ULL, -3}, {1, ~0ULL, -2}));   // other groups: the bits
  EXPECT_FALSE(should_collide({1, 2, 0}, {1, ~0ULL, 0}));        // a's mask misses b
  // In a world: two balls of one negative group head-on pass through each other.
  World world;
  const BallId a = world.add_ball(ball_def({0.0, 0.0}, {1.0, 0.0}), {1, ~0ULL, -1});
  const BallId b = world.add_ball(ball_def({5.0, 0.0}, {-1.0, 0.0}), {1, ~0ULL, -1});
  world.run_until(10.0);
  EXPECT_EQ(world.collision_count(), 0u);
  EXPECT_EQ(world.position(a), (Vec2{10.0, 0.0}));
  EXPECT_EQ(world.position(b), (Vec2{-5.0, 0.0}));
}

TEST(WorldFilter, ABallPlacedOverlappingWhatItPassesThroughIsAccepted) {
  World world;
  world.add_ball(ball_def({0.0, 0.0}, {}), only(1));
  EXPECT_NO_THROW(world.add_ball(ball_def({0.3, 0.0}, {}), only(2)));
  EXPECT_THROW(world.add_ball(ball_def({0.0, 0.3}, {}), only(1)), InvalidArgument);
  EXPECT_EQ(world.audit(), std::nullopt);
}

TEST(WorldFilter, AWallLetsThroughWhatItsFilterDoesNotMeet) {
  World world;
  const WallId gate = world.add_segment({{5.0, -10.0}, {5.0, 10.0}});
  world.set_wall_filter(gate, only(2));
  const BallId ghost = world.add_ball(ball_def({0.0, 0.0}, {1.0, 0.0}), only(1));
  const BallId solid = world.add_ball(ball_def({0.0, 3.0}, {1.0, 0.0}), {1 | 2, ~0ULL, 0});
  world.run_until(10.0);
  EXPECT_EQ(world.position(ghost), (Vec2{10.0, 0.0}));  // straight through
  EXPECT_LT(world.position(solid).x, 5.0);              // bounced back
  EXPECT_EQ(world.wall_filter(gate), only(2));
  // A box's own sides keep every ball in: no filter for them.
  World box(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  EXPECT_THROW(box.set_wall_filter(0, only(2)), InvalidArgument);
  EXPECT_THROW(box.set_wall_filter(9, only(2)), InvalidArgument);
}

TEST(WorldFilter, AFilterChangedBetweenStepsTakesEffectAtOnce) {
  // b owns the pending contact of the pair (or a does): after a's filter changes, neither may
  // meet the other, whichever predicted it.
  for (const bool change_a : {true, false}) {
    World world;
    const BallId a = world.add_ball(ball_def({0.0, 0.0}, {1.0, 0.0}));
    const BallId b = world.add_ball(ball_def({4.0, 0.0}, {-1.0, 0.0}));
    world.step(0.5);  // predicted: they meet at t = 1.5
    world.set_filter(change_a ? a : b, only(2));
    world.run_until(5.0);
    EXPECT_EQ(world.collision_count(), 0u);
    // Back to the default: they meet again the next time they approach (never: they separate);
    // send them back at each other.
    world.set_filter(change_a ? a : b, {});
    world.set_velocity(a, {-1.0, 0.0});
    world.set_velocity(b, {1.0, 0.0});
    world.run_until(10.0);
    EXPECT_EQ(world.collision_count(), 1u);
    EXPECT_EQ(world.audit(), std::nullopt);
  }
}

TEST(WorldFilter, FiltersSurviveSaveAndLoadAndAWorldWithoutThemSavesAsBefore) {
  World world = two_kinds(only(1), {2, 3, -4});
  world.set_wall_filter(world.add_segment({{10.0, 10.0}, {30.0, 12.0}}), only(2));
  world.step(2.0);
  std::stringstream file(std::ios::in | std::ios::out | std::ios::binary);
  world.save(file);
  World loaded = World::load(file);
  for (const BallId id : world.balls()) ASSERT_EQ(world.filter(id), loaded.filter(id));
  EXPECT_EQ(loaded.wall_filter(4), only(2));
  world.step(3.0);
  loaded.step(3.0);
  for (const BallId id : world.balls()) ASSERT_EQ(world.position(id), loaded.position(id));
  // Default filters leave the bytes of a save as they were: the version without the flag.
  World plain = two_kinds({}, {});
  std::stringstream bytes(std::ios::in | std::ios::out | std::ios::binary);
  plain.save(bytes);
  const std::string text = bytes.str();
  EXPECT_EQ(static_cast<unsigned char>(text[8]), 2);  // version 2, no filter flag
  EXPECT_EQ(static_cast<unsigned char>(text[9]), 0);
}

TEST(WorldFilter, UnderGravityABallFallsThroughWhatItDoesNotMeetAndRestsOnWhatItDoes) {
  WorldDef def{Boundary::box, {0.0, 0.0}, {10.0, 20.0}};
  def.restitution = 0.5;
  def.gravity = {0.0, -9.81};
  World world(def);
  world.set_wall_filter(world.add_segment({{0.0, 10.0}, {10.0, 10.0}}), only(2));  // a shelf
  const BallId below =
      world.add_ball(ball_def({5.0, 0.5}, {}), {1, 1, -1});  // its group: never meet
  const BallId ghost =
      world.add_ball(ball_def({5.0, 15.0}, {}), {1, 1, -1});  // meets the floor only
  const BallId solid = world.add_ball(ball_def({2.0, 15.0}, {}), {2, ~0ULL, 0});
  world.run_until(20.0);
  EXPECT_EQ(world.audit(), std::nullopt);
  EXPECT_NEAR(world.position(solid).y, 10.5, 1e-3);  // on the shelf
  EXPECT_NEAR(world.position(ghost).y, 0.5, 1e-3);   // through the shelf and the ball below
  EXPECT_NEAR(world.position(below).y, 0.5, 1e-3);
  EXPECT_EQ(world.velocity(ghost), (Vec2{0.0, 0.0}));
}

TEST(WorldFilter, QueriesSeeTheCategoriesOfTheirMask) {
  World world;
  const BallId one = world.add_ball(ball_def({5.0, 0.0}, {}), only(1));
  const BallId two = world.add_ball(ball_def({10.0, 0.0}, {}), only(2));
  QueryFilter twos;
  twos.mask = 2;
  EXPECT_EQ(world.cast_ray({0.0, 0.0}, {20.0, 0.0}).ball, one);
  EXPECT_EQ(world.cast_ray({0.0, 0.0}, {20.0, 0.0}, twos).ball, two);
  EXPECT_EQ(world.balls_in_box({0.0, -1.0}, {20.0, 1.0}, twos), std::vector<BallId>{two});
}

}  // namespace
}  // namespace carom::filter_tests
