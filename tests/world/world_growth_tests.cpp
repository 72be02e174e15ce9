// Growth (WorldDef::growth_rate; docs/world.md, "Growth"): radii grow at one relative rate,
// contacts come at the closed-form times, growing balls never overlap each other or a wall, the
// grid is re-planned as they outgrow its cells, and a compression reaches the packing fraction
// the growth law gives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

BallDef growth_test_ball(Vec2 position, double radius, Vec2 velocity = {}) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  return def;
}

// n disks of radius `radius` on a square lattice in a periodic square cell of side `side`, with
// velocity components normal of standard deviation 1.
World growth_lattice(int per_row, double side, double radius, double rate, std::uint32_t seed) {
  WorldDef def{Boundary::periodic, {0.0, 0.0}, {side, side}, 1.0};
  def.growth_rate = rate;
  World world(def);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> speed(0.0, 1.0);
  const double spacing = side / per_row;
  for (int i = 0; i < per_row * per_row; ++i) {
    const double vx = speed(random);
    const double vy = speed(random);
    world.add_ball(growth_test_ball({(i % per_row + 0.5) * spacing, (i / per_row + 0.5) * spacing},
                                    radius, {vx, vy}));
  }
  return world;
}

double packing_fraction(const World& world, double area) {
  double covered = 0.0;
  for (const BallId id : world.balls()) {
    covered += std::numbers::pi * world.radius(id) * world.radius(id);
  }
  return covered / area;
}

TEST(WorldGrowth, BallsAtRestMeetWhenTheirRadiiFillTheGapAndPartFasterThanTheyGrow) {
  WorldDef def;
  def.growth_rate = 0.5;  // radii × (1 + t/2)
  World world(def);
  const BallId a = world.add_ball(growth_test_ball({0.0, 0.0}, 1.0));
  const BallId b = world.add_ball(growth_test_ball({10.0, 0.0}, 1.0));
  // The sum of radii 2·(1 + t/2) reaches 10 at t = 8.
  world.run_collisions(1);
  EXPECT_NEAR(world.time(), 8.0, 1e-12);
  EXPECT_NEAR(world.radius(a), 5.0, 1e-12);
  ASSERT_EQ(world.contacts().size(), 1U);
  // The gap closed at the growth speed 2·0.5 = 1; elastic, it opens at 1: each ball leaves at
  // 1/2 + 1/2 of the growth speed.
  EXPECT_NEAR(world.contacts()[0].approach_speed, 1.0, 1e-12);
  EXPECT_NEAR(world.velocity(a).x, -1.0, 1e-12);
  EXPECT_NEAR(world.velocity(b).x, 1.0, 1e-12);
  world.step(10.0);
  EXPECT_FALSE(world.audit()) << *world.audit();
  EXPECT_EQ(world.collision_count(), 1U);  // they part at 2, faster than the radii grow (1)
}

TEST(WorldGrowth, AGrowingBallInABoxNeverReachesIntoItsWalls) {
  WorldDef def{Boundary::box, {0.0, 0.0}, {20.0, 20.0}, 1.0};
  def.growth_rate = 0.2;
  World world(def);
  const BallId ball = world.add_ball(growth_test_ball({10.0, 10.0}, 1.0, {6.0, 2.0}));
  for (int k = 0; k < 40; ++k) {
    world.step(0.25);
    ASSERT_FALSE(world.audit()) << *world.audit() << " at t = " << world.time();
  }
  EXPECT_NEAR(world.radius(ball), 1.0 + 0.2 * 10.0, 1e-12);
  EXPECT_GE(world.collision_count(), 4U);
}

TEST(WorldGrowth, CompressionReachesThePackingTheGrowthLawGivesWithoutAnOverlap) {
  // 400 disks from packing fraction 0.2 at a rate that doubles the radii in 10 time units
  // (η × 4 = 0.8 at t = 10): stopped at t = 9.5 (η ≈ 0.73), audited along the way, after the
  // grid has been re-planned for the larger balls.
  const double side = 40.0;
  const double radius = std::sqrt(0.2 * side * side / (400.0 * std::numbers::pi));
  World world = growth_lattice(20, side, radius, 0.1, 3);
  for (int k = 0; k < 19; ++k) {
    world.step(0.5);
    ASSERT_FALSE(world.audit()) << *world.audit() << " at t = " << world.time();
  }
  const double scale = 1.0 + 0.1 * 9.5;
  EXPECT_NEAR(packing_fraction(world, side * side), 0.2 * scale * scale, 1e-9);
  EXPECT_GT(world.collision_count(), 10'000U);
  // Growth pumps energy in: each contact adds the growth speed to the parting.
  EXPECT_GT(world.kinetic_energy(), 400.0);
}

TEST(WorldGrowth, StoppingGrowthKeepsTheRadiiAndTheWorldRunsOnPlainly) {
  World world = growth_lattice(10, 20.0, 0.5, 0.2, 5);
  world.step(2.0);
  const BallId first = world.balls()[0];
  const double grown = world.radius(first);
  EXPECT_NEAR(grown, 0.5 * 1.4, 1e-12);
  world.set_growth_rate(0.0);
  const double energy = world.kinetic_energy();
  world.step(5.0);
  EXPECT_EQ(world.radius(first), grown);
  EXPECT_NEAR(world.kinetic_energy(), energy, 1e-12 * energy);  // elastic and no growth: kept
  EXPECT_FALSE(world.audit());
  // And started again from the radii of now.
  world.set_growth_rate(0.1);
  world.step(1.0);
  EXPECT_NEAR(world.radius(first), grown * 1.1, 1e-12);
  EXPECT_FALSE(world.audit());
}

TEST(WorldGrowth, SaveAndResumeWhileGrowingIsBitIdentical) {
  World original = growth_lattice(12, 24.0, 0.4, 0.15, 7);
  original.step(1.5);
  std::stringstream bytes;
  original.save(bytes);
  World resumed = World::load(bytes);
  original.step(2.0);
  resumed.step(2.0);
  EXPECT_EQ(resumed.collision_count(), original.collision_count());
  for (const BallId id : original.balls()) {
    EXPECT_EQ(resumed.position(id), original.position(id));
    EXPECT_EQ(resumed.velocity(id), original.velocity(id));
    EXPECT_EQ(resumed.radius(id), original.radius(id));
  }
  EXPECT_EQ(resumed.def().growth_rate, 0.15);
}

TEST(WorldGrowth, RefusesGrowthWithGravityAndBadRates) {
  WorldDef def;
  def.growth_rate = 0.1;
  def.gravity = {0.0, -1.0};
  EXPECT_THROW(World{def}, InvalidArgument);
  def.gravity = {};
  def.growth_rate = -0.1;
  EXPECT_THROW(World{def}, InvalidArgument);
  def.growth_rate = 0.1;
  World world(def);
  EXPECT_THROW(world.set_gravity({0.0, -1.0}), InvalidArgument);
  EXPECT_THROW(world.set_growth_rate(std::nan("")), InvalidArgument);
  World falling(WorldDef{});
  falling.set_gravity({0.0, -1.0});
  EXPECT_THROW(falling.set_growth_rate(0.1), InvalidArgument);
}

TEST(WorldGrowth, BallsGrownPastAThirdOfTheCellAreRefused) {
  // Four disks in a cell of side 10 growing without end: a diameter above 10/3 cannot keep the
  // 3×3 block of cells distinct, and the run says so.
  World world = growth_lattice(2, 10.0, 0.5, 1.0, 1);
  EXPECT_THROW(world.step(10.0), InvalidArgument);
}

TEST(WorldGrowth, SetTemperatureScalesVelocitiesAboutTheCentreOfMass) {
  World world = growth_lattice(8, 20.0, 0.5, 0.0, 9);
  const BallId mover = world.balls()[0];
  world.set_velocity(mover, world.velocity(mover) + Vec2{3.0, -1.0});  // some momentum
  const Vec2 momentum = world.momentum();
  const double before = world.kinetic_energy();
  const double work = world.set_temperature(2.5);
  EXPECT_NEAR(work, world.kinetic_energy() - before, 1e-12 * before);
  EXPECT_NEAR(world.momentum().x, momentum.x, 1e-12 * before);
  EXPECT_NEAR(world.momentum().y, momentum.y, 1e-12 * before);
  // Relative to the centre of mass, K = N·kT: the whole K less ½·M·V².
  const double drift_energy = 0.5 * length_squared(momentum) / 64.0;
  EXPECT_NEAR(world.kinetic_energy() - drift_energy, 64.0 * 2.5, 1e-9);
  world.step(1.0);
  EXPECT_FALSE(world.audit());
  EXPECT_THROW(world.set_temperature(0.0), InvalidArgument);
  EXPECT_THROW(world.set_temperature(std::nan("")), InvalidArgument);
}

// Balls without motion relative to their centre of mass (one ball alone; balls at one velocity)
// have nothing to scale: the rounding of their drift must not become a temperature, nor the
// momentum change (found by the world fuzzer: one ball at speed 100 given kT = 1).
TEST(WorldGrowth, SetTemperatureLeavesBallsWithoutRelativeMotionAndKeepsFastMomentum) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {-50.0, -50.0};
  def.upper = {50.0, 50.0};
  World world(def);
  const BallId alone = world.add_ball({{0.0, 0.0}, {100.0, 0.3}, 0.1, 3.0, {}, 0});
  EXPECT_EQ(world.set_temperature(1.0), 0.0);
  EXPECT_EQ(world.velocity(alone), (Vec2{100.0, 0.3}));
  world.add_ball({{10.0, 0.0}, {100.0, 0.3}, 0.1, 2.0, {}, 0});
  EXPECT_EQ(world.set_temperature(1.0), 0.0);
  // Fast balls moving against each other, cooled a hundred-thousandfold and heated back.
  const BallId third = world.add_ball({{0.0, 10.0}, {-1e6, 0.0}, 0.1, 1.0, {}, 0});
  world.set_velocity(alone, {1e6, 1.0});
  const Vec2 momentum = world.momentum();
  world.set_temperature(1e-6);
  world.set_temperature(1e4);
  EXPECT_LT(length(world.momentum() - momentum), 1e-9 * 2e6);
  EXPECT_TRUE(world.contains(third));
}

TEST(WorldGrowth, AThermostattedCompressionReachesADenseStateAtTheTemperatureAsked) {
  // 256 disks from η = 0.25, growing at 0.02 of their size a time unit, velocities rescaled to
  // kT = 1 every 0.5: at t = 40 the radii are 1.8 times larger, η = 0.81, a dense solid, with
  // no overlap, and each rescaling took out the work growth had put in.
  const double side = 32.0;
  const double radius = std::sqrt(0.25 * side * side / (256.0 * std::numbers::pi));
  World world = growth_lattice(16, side, radius, 0.02, 11);
  world.set_contact_recording(false);
  double taken = 0.0;
  for (int k = 0; k < 80; ++k) {
    world.step(0.5);
    taken -= world.set_temperature(1.0);
    const double drift_energy = 0.5 * length_squared(world.momentum()) / 256.0;
    ASSERT_NEAR(world.kinetic_energy() - drift_energy, 256.0, 1e-9) << "at t = " << world.time();
  }
  ASSERT_FALSE(world.audit()) << *world.audit();
  EXPECT_GT(world.collision_count(), 20'000U);
  EXPECT_NEAR(packing_fraction(world, side * side), 0.25 * 1.8 * 1.8, 1e-9);
  EXPECT_GT(taken, 0.0);
}

}  // namespace
}  // namespace carom
