// The World under gravity (WorldDef::gravity; docs/world.md, "Gravity"): balls on parabolas hit
// floors, pegs and each other at the closed-form times, elastic worlds keep kinetic plus potential
// energy, and gravity is carried by set_gravity, save and load.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "carom/world.hpp"
#include "long_tests.hpp"

namespace carom {
namespace {

WorldDef box_with_gravity(Vec2 lower, Vec2 upper, Vec2 gravity, double restitution = 1.0) {
  WorldDef def{Boundary::box, lower, upper, restitution};
  def.gravity = gravity;
  return def;
}

BallDef falling_ball(Vec2 position, Vec2 velocity, double radius, double mass = 1.0) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  def.mass = mass;
  return def;
}

double total_energy(const World& world) {
  return world.kinetic_energy() + world.potential_energy();
}

// Every ball's place and velocity, bit for bit.
std::vector<std::uint64_t> state_bits(const World& world) {
  std::vector<std::uint64_t> out{std::bit_cast<std::uint64_t>(world.time())};
  for (const BallId id : world.balls()) {
    for (const double x :
         {world.position(id).x, world.position(id).y, world.velocity(id).x, world.velocity(id).y}) {
      out.push_back(std::bit_cast<std::uint64_t>(x));
    }
  }
  return out;
}

// An elastic gas of n balls of radius 0.5 in a box 20 wide and 30 tall under g = (0, −9.81).
World tall_box_gas(int n, std::uint32_t seed, double restitution = 1.0) {
  World world(box_with_gravity({0.0, 0.0}, {20.0, 30.0}, {0.0, -9.81}, restitution));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> speed(-5.0, 5.0);
  for (int i = 0; i < n; ++i) {
    const Vec2 place{1.0 + 2.0 * (i % 9), 1.0 + 2.0 * (i / 9)};
    world.add_ball(falling_ball(place, {speed(random), speed(random)}, 0.5));
  }
  return world;
}

TEST(WorldGravity, DroppedBallMeetsTheFloorAtTheClosedFormTime) {
  // From rest at height h above contact, the floor is met at √(2h/g) with speed √(2gh).
  World world(box_with_gravity({0.0, 0.0}, {10.0, 20.0}, {0.0, -10.0}));
  const BallId ball = world.add_ball(falling_ball({5.0, 11.0}, {}, 1.0));
  ASSERT_EQ(world.run_collisions(1), 1U);
  EXPECT_NEAR(world.time(), std::sqrt(2.0), 4e-16);
  ASSERT_EQ(world.contacts().size(), 1U);
  const ContactEvent& floor = world.contacts()[0];
  EXPECT_EQ(floor.kind, ContactKind::ball_wall);
  EXPECT_EQ(floor.wall, 0U);  // the box's bottom
  EXPECT_NEAR(floor.approach_speed, std::sqrt(200.0), 1e-13);
  EXPECT_NEAR(world.position(ball).y, 1.0, 1e-14);
  EXPECT_NEAR(world.velocity(ball).y, std::sqrt(200.0), 1e-13);
}

TEST(WorldGravity, ThrownBallFollowsItsParabolaBetweenContacts) {
  World world(box_with_gravity({0.0, 0.0}, {100.0, 100.0}, {0.0, -9.81}));
  const BallId ball = world.add_ball(falling_ball({10.0, 10.0}, {3.0, 12.0}, 1.0));
  world.step(1.5);  // the apex comes at 12/9.81 ≈ 1.22, the floor long after
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_NEAR(world.position(ball).x, 14.5, 1e-13);
  EXPECT_NEAR(world.position(ball).y, 10.0 + 12.0 * 1.5 - 0.5 * 9.81 * 2.25, 1e-13);
  EXPECT_NEAR(world.velocity(ball).y, 12.0 - 9.81 * 1.5, 1e-13);
  EXPECT_EQ(world.velocity(ball).x, 3.0);
}

// The proof of exactness under gravity: an elastic ball bouncing on a floor keeps its
// height. Each bounce is one contact; its time is the previous one's plus 2√(2h/g), computed
// anew from the state after the bounce, so the times may drift by a rounding of the clock each
// (at most 2^-52 of the time per event) and the energy by a rounding of the bounce.
TEST(WorldGravity, ElasticBounceKeepsItsHeightOverAMillionBounces) {
  const long bounces = testing::long_tests_enabled() ? 1'000'000 : 100'000;
  // A box no wider than a cell: the ball meets nothing but the floor, and crosses no cell.
  World world(box_with_gravity({0.0, 0.0}, {2.5, 6.0}, {0.0, -10.0}));
  const BallId ball = world.add_ball(falling_ball({1.25, 5.0}, {}, 1.0));  // 4 above the floor
  const double start_energy = total_energy(world);
  const double period = 2.0 * std::sqrt(0.8);  // up and down: 2·√(2h/g)
  ASSERT_EQ(world.run_collisions(1), 1U);
  const double first = world.time();
  EXPECT_NEAR(first, std::sqrt(0.8), 4e-16);
  double highest_drift = 0.0;
  for (long done = 1; done < bounces;) {
    const auto batch = static_cast<std::uint64_t>(std::min(10'000L, bounces - done));
    ASSERT_EQ(world.run_collisions(batch), batch);
    done += static_cast<long>(batch);
    highest_drift = std::max(highest_drift, std::abs(total_energy(world) - start_energy));
    const double expected = first + static_cast<double>(done - 1) * period;
    ASSERT_NEAR(world.time(), expected, 4.0 * static_cast<double>(done) * expected * 0x1p-52)
        << "after " << done << " bounces";
  }
  EXPECT_LE(highest_drift / start_energy, 1e-12);
  EXPECT_NEAR(world.position(ball).y, 1.0, 1e-9);
  EXPECT_FALSE(world.audit());
}

TEST(WorldGravity, ElasticGasInATallBoxKeepsItsTotalEnergy) {
  World world = tall_box_gas(60, 7);
  const double start = total_energy(world);
  for (int k = 0; k < 20; ++k) {
    world.run_collisions(2'000);
    ASSERT_FALSE(world.audit()) << *world.audit();
    // Each contact rounds the energy by a few units of 2^-53; 40 000 of them stay far below.
    ASSERT_NEAR(total_energy(world), start, 1e-10 * start);
  }
}

TEST(WorldGravity, BallOnAParabolaMeetsAPegWhenTheCoreQuerySaysSo) {
  World world(box_with_gravity({-20.0, -20.0}, {20.0, 20.0}, {0.0, -10.0}));
  const BallId peg = world.add_ball(falling_ball({2.0, 5.0}, {}, 0.5, kImmovable));
  const BallId ball = world.add_ball(falling_ball({0.0, 10.0}, {2.0, 0.0}, 1.0));
  const Impact expected =
      time_of_impact_ball_ball({{0.0, 10.0}, 1.0}, Motion{{2.0, 0.0}, {0.0, -10.0}},
                               {{2.0, 5.0}, 0.5}, Motion{{0.0, 0.0}, {0.0, 0.0}}, 10.0);
  ASSERT_TRUE(expected.hit);
  ASSERT_EQ(world.run_collisions(1), 1U);
  EXPECT_EQ(world.time(), expected.t);
  const ContactEvent& contact = world.contacts()[0];
  EXPECT_EQ(contact.kind, ContactKind::ball_ball);
  EXPECT_EQ(world.position(peg), (Vec2{2.0, 5.0}));  // immovable balls do not fall
  EXPECT_NEAR(length(world.position(ball) - Vec2{2.0, 5.0}), 1.5, 1e-12);
}

TEST(WorldGravity, BallsFallingSideBySideNeverMeet) {
  World world(box_with_gravity({0.0, 0.0}, {10.0, 100.0}, {0.0, -10.0}));
  world.add_ball(falling_ball({4.0, 90.0}, {}, 0.99));
  world.add_ball(falling_ball({6.0, 90.0}, {}, 0.99));
  world.step(4.0);  // the floor comes at √(2·89/10) ≈ 4.2
  EXPECT_TRUE(world.contacts().empty());
}

TEST(WorldGravity, SetGravityBetweenStepsKeepsPlaceAndVelocity) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {50.0, 50.0}});
  const BallId ball = world.add_ball(falling_ball({25.0, 25.0}, {1.0, 0.0}, 1.0));
  world.step(1.0);
  world.set_gravity({0.0, -2.0});
  EXPECT_EQ(world.def().gravity, (Vec2{0.0, -2.0}));
  EXPECT_EQ(world.position(ball), (Vec2{26.0, 25.0}));
  EXPECT_EQ(world.velocity(ball), (Vec2{1.0, 0.0}));
  world.step(2.0);
  EXPECT_NEAR(world.position(ball).y, 25.0 - 4.0, 1e-13);
  EXPECT_NEAR(world.velocity(ball).y, -4.0, 1e-13);
  world.set_gravity({});
  world.step(1.0);
  EXPECT_NEAR(world.velocity(ball).y, -4.0, 1e-13);
  EXPECT_NEAR(world.position(ball).y, 17.0, 1e-13);
  EXPECT_EQ(world.potential_energy(), 0.0);
  EXPECT_THROW(world.set_gravity({0.0, std::numeric_limits<double>::infinity()}), InvalidArgument);
  EXPECT_THROW(World(box_with_gravity({0.0, 0.0}, {1.0, 1.0}, {std::nan(""), 0.0})),
               InvalidArgument);
}

TEST(WorldGravity, PotentialEnergyIsMinusMassTimesGravityDotPlace) {
  World world(box_with_gravity({0.0, 0.0}, {10.0, 10.0}, {1.0, -2.0}));
  world.add_ball(falling_ball({3.0, 4.0}, {}, 1.0, 2.0));
  world.add_ball(falling_ball({7.0, 7.0}, {}, 1.0, kImmovable));  // immovable: no energy of its own
  EXPECT_EQ(world.potential_energy(), -2.0 * (3.0 - 8.0));
}

TEST(WorldGravity, SameCallsGiveBitIdenticalRuns) {
  World first = tall_box_gas(40, 11);
  World second = tall_box_gas(40, 11);
  first.step(3.0);
  second.step(1.0);
  second.step(2.0);
  EXPECT_EQ(state_bits(first), state_bits(second));
}

TEST(WorldGravity, SavedAndResumedRunIsBitIdentical) {
  World original = tall_box_gas(40, 13);
  original.step(1.0);
  std::stringstream bytes;
  original.save(bytes);
  World resumed = World::load(bytes);
  EXPECT_EQ(resumed.def().gravity, original.def().gravity);
  original.run_collisions(3'000);
  resumed.run_collisions(3'000);
  EXPECT_EQ(state_bits(resumed), state_bits(original));
}

TEST(WorldGravity, WorldWithoutGravitySavesAsItAlwaysDid) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  world.add_ball(falling_ball({5.0, 5.0}, {1.0, 0.5}, 1.0));
  std::stringstream bytes;
  world.save(bytes);
  const std::string text = bytes.str();
  EXPECT_EQ(static_cast<unsigned char>(text[8]), 2U);  // version 2: no gravity section
  World with(box_with_gravity({0.0, 0.0}, {10.0, 10.0}, {0.0, -1.0}));
  std::stringstream gravity_bytes;
  with.save(gravity_bytes);
  EXPECT_EQ(static_cast<unsigned char>(gravity_bytes.str()[8]), 3U);
}

}  // namespace
}  // namespace carom
