// Resting and sliding under gravity (WorldDef::rest_height; docs/world.md, "Resting and
// sliding"): inelastic balls come to rest on floors, in corners and in piles, slide down slopes
// at the closed-form rate, cost no events once settled, wake when disturbed, and never gain
// energy.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "carom/world.hpp"

namespace carom {
namespace {

BallDef resting_test_ball(Vec2 position, double radius, Vec2 velocity = {}, double mass = 1.0) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  def.mass = mass;
  return def;
}

WorldDef box_under_gravity(Vec2 upper, double restitution) {
  WorldDef def{Boundary::box, {0.0, 0.0}, upper, restitution};
  def.gravity = {0.0, -9.81};
  return def;
}

double resting_total_energy(const World& world) {
  return world.kinetic_energy() + world.potential_energy();
}

// A box 20 wide and 60 tall with n balls of radii 0.5 to 0.7 thrown about in rows above the
// floor: the pour of the proofs.
World poured_box(int n, double restitution, std::uint32_t seed) {
  World world(box_under_gravity({20.0, 60.0}, restitution));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> speed(-3.0, 3.0);
  for (int i = 0; i < n; ++i) {
    const Vec2 place{1.0 + 2.0 * (i % 9) + 0.3 * (i / 9 % 2), 1.5 + 2.0 * (i / 9)};
    world.add_ball(resting_test_ball(place, 0.5 + 0.1 * (i % 3), {speed(random), speed(random)}));
  }
  return world;
}

// Runs `world` for `duration` in steps of 0.05, failing if the total energy ever rises by more
// than the rounding of a sum of its terms (10⁻¹² of the largest) or an audit fails.
void run_never_gaining(World& world, double duration) {
  double before = resting_total_energy(world);
  const double scale = std::abs(before) + world.kinetic_energy() + 1.0;
  for (double t = 0.0; t < duration; t += 0.05) {
    world.step(0.05);
    const double now = resting_total_energy(world);
    ASSERT_LE(now, before + 1e-12 * scale) << "at t = " << world.time();
    ASSERT_FALSE(world.audit()) << *world.audit() << " at t = " << world.time();
    before = now;
  }
}

TEST(WorldResting, InelasticBallOnAFloorComesToRest) {
  World world(box_under_gravity({10.0, 20.0}, 0.5));
  const BallId ball = world.add_ball(resting_test_ball({5.0, 10.0}, 1.0));
  run_never_gaining(world, 5.0);
  // Bounces lose 3/4 of their energy each: from a drop of 9 radii, within a dozen bounces the
  // bounce is below the rest height (10⁻³ radii) and the ball rests.
  EXPECT_LT(world.collision_count(), 20U);
  EXPECT_EQ(world.velocity(ball), (Vec2{}));
  EXPECT_NEAR(world.position(ball).y, 1.0, 1e-12);
  const std::uint64_t settled = world.collision_count();
  world.step(100.0);
  EXPECT_EQ(world.collision_count(), settled);
  EXPECT_EQ(world.velocity(ball), (Vec2{}));
}

TEST(WorldResting, ElasticBallPlacedOnAFloorStaysAtNoCost) {
  World world(box_under_gravity({10.0, 20.0}, 1.0));
  const BallId ball = world.add_ball(resting_test_ball({5.0, 1.0}, 1.0));
  world.step(50.0);
  EXPECT_EQ(world.collision_count(), 0U);
  EXPECT_EQ(world.position(ball), (Vec2{5.0, 1.0}));
  EXPECT_EQ(world.velocity(ball), (Vec2{}));
}

TEST(WorldResting, BallSlidesDownASlopeAtGravitysPartAlongItThenFalls) {
  // A segment 8 long sloping down at 30° from (0, 10); a ball placed on it at rest.
  WorldDef def;
  def.gravity = {0.0, -10.0};
  def.restitution = 0.5;
  World world(def);
  const double angle = std::numbers::pi / 6.0;
  const Vec2 down{std::cos(angle), -std::sin(angle)};
  const Vec2 top{0.0, 10.0};
  const Vec2 bottom = top + down * 8.0;
  world.add_segment({top, bottom});
  const Vec2 up_normal{std::sin(angle), std::cos(angle)};
  // (A hair above it: a ball placed exactly touching is refused for the rounding of its place.)
  const Vec2 start = top + down * 1.0 + up_normal * (0.5 + 1e-12);
  const BallId ball = world.add_ball(resting_test_ball(start, 0.5));
  // Along the slope the ball accelerates at g·sin 30° = 5, so after t it has slid 2.5·t².
  world.step(1.0);
  EXPECT_LE(world.collision_count(), 1U);  // the landing from a hair above, then sliding
  const Vec2 slid = world.position(ball) - start;
  EXPECT_NEAR(dot(slid, down), 2.5, 1e-5);
  EXPECT_NEAR(dot(slid, up_normal), 0.0, 1e-11);
  EXPECT_NEAR(length(world.velocity(ball)), 5.0, 1e-5);
  // Past the end (7 along, at t = √(14/5)) it falls free: beyond the slope, falling faster
  // than the slide alone would take it.
  world.step(1.0);
  EXPECT_GT(world.position(ball).x, bottom.x);
  EXPECT_LT(world.velocity(ball).y, -5.0 * std::sqrt(2.8) * std::sin(angle) - 1.0);
}

TEST(WorldResting, BallRollsIntoAValleyAndRestsBetweenItsSides) {
  World world(box_under_gravity({20.0, 20.0}, 0.3));
  world.add_polyline(std::vector<Vec2>{{2.0, 10.0}, {10.0, 4.0}, {18.0, 10.0}});
  const BallId ball = world.add_ball(resting_test_ball({4.0, 12.0}, 0.5));
  run_never_gaining(world, 30.0);
  EXPECT_EQ(world.velocity(ball), (Vec2{}));
  // At rest touching both sides: straight above the valley's bottom.
  EXPECT_NEAR(world.position(ball).x, 10.0, 1e-9);
  const std::uint64_t settled = world.collision_count();
  world.step(10.0);
  EXPECT_EQ(world.collision_count(), settled);
}

TEST(WorldResting, BallOnTopOfAPegRestsAndOneOffCentreRollsOff) {
  World world(box_under_gravity({20.0, 20.0}, 0.5));
  world.add_ball(resting_test_ball({5.0, 5.0}, 1.0, {}, kImmovable));
  world.add_ball(resting_test_ball({15.0, 5.0}, 1.0, {}, kImmovable));
  const BallId centred = world.add_ball(resting_test_ball({5.0, 8.0}, 1.0));
  const BallId off = world.add_ball(resting_test_ball({15.1, 8.0}, 1.0));
  run_never_gaining(world, 10.0);
  EXPECT_EQ(world.velocity(centred), (Vec2{}));
  EXPECT_NEAR(world.position(centred).y, 7.0, 1e-9);  // on top of its peg
  EXPECT_NEAR(world.position(off).y, 1.0, 1e-9);      // rolled off, on the floor
}

TEST(WorldResting, PouredBallsSettleNeverGainEnergyAndStayInTheBox) {
  for (const double restitution : {0.0, 0.5, 0.9}) {
    SCOPED_TRACE(restitution);
    World world = poured_box(80, restitution, 3);
    run_never_gaining(world, 12.0);
    // Settled: no event at all over the next 20 time units, every ball still.
    const std::uint64_t settled = world.collision_count();
    world.step(20.0);
    EXPECT_EQ(world.collision_count(), settled);
    EXPECT_EQ(world.kinetic_energy(), 0.0);
    for (const BallId id : world.balls()) {
      const Vec2 p = world.position(id);
      EXPECT_TRUE(p.x > 0.0 && p.x < 20.0 && p.y > 0.0 && p.y < 60.0);
    }
  }
}

TEST(WorldResting, BallDroppedOnAPileWakesItLocallyAndItSettlesAgain) {
  World world = poured_box(120, 0.5, 5);
  run_never_gaining(world, 12.0);
  std::vector<Vec2> before;
  for (const BallId id : world.balls()) before.push_back(world.position(id));
  // Dropped from a few diameters above the pile's top (near y = 11).
  const BallId dropped = world.add_ball(resting_test_ball({3.0, 16.0}, 0.6));
  run_never_gaining(world, 12.0);
  const std::uint64_t settled = world.collision_count();
  world.step(20.0);
  EXPECT_EQ(world.collision_count(), settled);
  // Woken balls are those it touched and those they carried, and what those carried: a cone
  // over the landing place, never the whole pile. (Balls that stopped against each other in a
  // jam carry each other sideways, so the cone is a wide one.)
  std::size_t moved = 0;
  const std::vector<BallId> ids = world.balls();
  for (std::size_t k = 0; k < before.size(); ++k) {
    // (A woken ball settles again within a rounding or a rest height of where it was.)
    if (length(world.position(ids[k]) - before[k]) > 1e-3) ++moved;
  }
  EXPECT_GT(moved, 0U);
  EXPECT_LT(moved, before.size() / 4);
  EXPECT_LT(world.position(dropped).y, 16.0);
}

TEST(WorldResting, RemovingASupportLetsWhatRestedOnItFall) {
  World world(box_under_gravity({20.0, 20.0}, 0.5));
  const BallId lower = world.add_ball(resting_test_ball({10.0, 1.0}, 1.0));
  const BallId upper = world.add_ball(resting_test_ball({10.0, 3.0}, 1.0));
  world.step(1.0);
  EXPECT_EQ(world.velocity(upper), (Vec2{}));
  const std::uint64_t settled = world.collision_count();
  world.step(1.0);
  EXPECT_EQ(world.collision_count(), settled);
  world.remove_ball(lower);
  world.step(10.0);
  EXPECT_NEAR(world.position(upper).y, 1.0, 1e-9);  // fell onto the floor
  EXPECT_EQ(world.velocity(upper), (Vec2{}));
}

TEST(WorldResting, TurningGravityWakesRestingBalls) {
  World world(box_under_gravity({20.0, 20.0}, 0.5));
  const BallId ball = world.add_ball(resting_test_ball({10.0, 1.0}, 1.0));
  world.step(1.0);
  world.set_gravity({-9.81, 0.0});
  world.step(20.0);
  EXPECT_NEAR(world.position(ball).x, 1.0, 1e-9);  // now against the left wall
  EXPECT_EQ(world.velocity(ball), (Vec2{}));
}

TEST(WorldResting, BallGrazedWhileSlidingDownASlopeSlidesOn) {
  // A ball sliding down a frictionless slope (1 in 2) at 4.5 is grazed from above by a faster
  // ball (approach 0.064, below the rest speed ≈ 0.094): the graze presses it into the slope,
  // a second slow contact at one instant. No ball can rest on a frictionless slope: both slide
  // or fall on, never gaining energy, and end on the floor below.
  World world(box_under_gravity({20.0, 30.0}, 0.6));
  world.add_segment({{20.0, 14.0}, {12.0, 10.0}});
  const Vec2 up_normal = normalized(Vec2{-1.0, 2.0});
  const Vec2 start = Vec2{16.0, 12.0} + up_normal * (0.45 + 1e-9);
  const BallId slider = world.add_ball(resting_test_ball(start, 0.45, {-4.0, -2.0}));
  const BallId grazer =
      world.add_ball(resting_test_ball(start + Vec2{-0.7903895147049271, 0.43045379720529203}, 0.45,
                                       {-4.956411782090224, -3.8890548140545436}));
  run_never_gaining(world, 0.2);
  // Still on the slope, faster down it than it started (gravity's part along it is g/√5).
  EXPECT_GT(dot(world.velocity(slider), Vec2{-2.0, -1.0}), 4.0 * std::sqrt(5.0));
  EXPECT_GT(length(world.position(slider) - start), 0.5);
  run_never_gaining(world, 10.0);
  for (const BallId id : {slider, grazer}) {
    EXPECT_LT(world.position(id).y, 2.0) << "ball " << id.index;
  }
}

TEST(WorldResting, BallsSlidingDownASlopeMeetSlowlyAndSlideOnTogether) {
  // Two balls sliding down a slope (1 in 2), the upper one 0.05 faster, 0.005 apart: they meet
  // below the rest speed (≈ 0.099), the contact presses each onto the slope at that instant, a
  // jam. Neither can rest on a frictionless slope: they slide on at one speed, the mean.
  World world(box_under_gravity({30.0, 30.0}, 0.5));
  world.add_segment({{2.0, 20.0}, {26.0, 8.0}});
  const Vec2 down = normalized(Vec2{2.0, -1.0});
  const Vec2 up_normal = normalized(Vec2{1.0, 2.0});
  const Vec2 start = Vec2{6.0, 18.0} + up_normal * (0.5 + 1e-9);
  const BallId upper = world.add_ball(resting_test_ball(start, 0.5, down * 1.0));
  const BallId lower = world.add_ball(resting_test_ball(start + down * 1.005, 0.5, down * 0.95));
  run_never_gaining(world, 0.5);
  const double speed = 0.975 + 9.81 / std::sqrt(5.0) * world.time();
  for (const BallId id : {upper, lower}) {
    EXPECT_NEAR(dot(world.velocity(id), down), speed, 1e-9) << "ball " << id.index;
    EXPECT_NEAR(dot(world.velocity(id), up_normal), 0.0, 1e-12) << "ball " << id.index;
  }
}

// Three balls touching in a row in the air, the outer two thrown at each other at `speed`.
World row_in_flight(double restitution, double speed) {
  World world(box_under_gravity({20.0, 10.0}, restitution));
  world.add_ball(resting_test_ball({3.0, 5.0}, 1.0, {speed, 0.0}));
  world.add_ball(resting_test_ball({5.0, 5.0}, 1.0));
  world.add_ball(resting_test_ball({7.0, 5.0}, 1.0, {-speed, 0.0}));
  return world;
}

TEST(WorldResting, SlowInelasticPressInFlightMovesTheBallsOnTogether) {
  // Below the rest speed (√(2·g·10⁻³·r) ≈ 0.14) the middle ball would pass the press back and
  // forth, each time half as fast, until the approach is lost to rounding: a ball in a second
  // slow contact at one instant makes a jam, and in flight the touching balls move on at their
  // centre of mass's velocity (they neither hang in the air nor gain energy).
  World world = row_in_flight(0.5, 0.1);
  const double before = resting_total_energy(world);
  world.step(0.5);
  EXPECT_LE(world.collision_count(), 3U);
  EXPECT_LE(resting_total_energy(world), before);
  const std::vector<BallId> ids = world.balls();
  for (const BallId id : ids) {
    EXPECT_EQ(world.velocity(id), world.velocity(ids[0]));
    EXPECT_LT(world.position(id).y, 4.0);  // fallen ½·g·t² ≈ 1.23
  }
  EXPECT_EQ(world.velocity(ids[0]).x, 0.0);  // the row's momentum
  EXPECT_FALSE(world.audit());
}

TEST(WorldResting, SlowElasticHitsInFlightBounceAsEver) {
  // Elastic contacts are no jam: the hits pass through the row and out, energy kept.
  World world = row_in_flight(1.0, 0.1);
  const double before = resting_total_energy(world);
  world.step(0.5);
  EXPECT_EQ(world.collision_count(), 3U);
  const std::vector<BallId> ids = world.balls();
  EXPECT_DOUBLE_EQ(world.velocity(ids[0]).x, -0.1);
  EXPECT_EQ(world.velocity(ids[1]).x, 0.0);
  EXPECT_DOUBLE_EQ(world.velocity(ids[2]).x, 0.1);
  EXPECT_NEAR(resting_total_energy(world), before, 1e-12 * std::abs(before));
}

std::vector<std::uint64_t> state_of(const World& world) {
  std::vector<std::uint64_t> out{std::bit_cast<std::uint64_t>(world.time()),
                                 world.collision_count()};
  for (const BallId id : world.balls()) {
    for (const double x :
         {world.position(id).x, world.position(id).y, world.velocity(id).x, world.velocity(id).y}) {
      out.push_back(std::bit_cast<std::uint64_t>(x));
    }
  }
  return out;
}

TEST(WorldResting, SaveAndResumeWithRestingAndSlidingBallsIsBitIdentical) {
  World original = poured_box(80, 0.5, 7);
  original.step(2.0);  // some balls resting, some sliding, some flying
  std::stringstream bytes;
  original.save(bytes);
  World resumed = World::load(bytes);
  original.step(3.0);
  resumed.step(3.0);
  EXPECT_EQ(state_of(resumed), state_of(original));
  World again = poured_box(80, 0.5, 7);
  again.step(5.0);
  EXPECT_EQ(state_of(again), state_of(original));
}

}  // namespace
}  // namespace carom
