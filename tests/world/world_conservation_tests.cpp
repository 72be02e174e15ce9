// Conservation over many contacts: an elastic periodic gas keeps its energy and momentum to
// rounding; an inelastic gas with the collapse guard keeps advancing and cools.
#include <gtest/gtest.h>
#include <unistd.h>  // alarm: a watchdog for a run that might never return

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>

#include "carom/world.hpp"
#include "long_tests.hpp"

namespace carom {
namespace {

using testing::long_tests_enabled;

// Balls on a jittered grid in the world's [lower, upper] square, per_row × per_row of them.
// Radii lie in [smallest, largest] and centres within ±jitter of their site (all as fractions of
// the grid's pitch); 2·(largest + jitter) < 1 keeps neighbours apart.
struct GasShape {
  int per_row = 20;
  double smallest = 0.2;
  double largest = 0.3;
  double jitter = 0.1;
  double speed = 5.0;  // each ball gets a speed in [0, speed] in a random direction
};

World gas(const WorldDef& def, const GasShape& shape, std::uint64_t seed) {
  World world(def);
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pitch = (def.upper.x - def.lower.x) / shape.per_row;
  for (int i = 0; i < shape.per_row; ++i) {
    for (int j = 0; j < shape.per_row; ++j) {
      BallDef ball;
      ball.radius = pitch * (shape.smallest + (shape.largest - shape.smallest) * unit(engine));
      ball.position =
          def.lower + Vec2{(i + 0.5 + shape.jitter * (2.0 * unit(engine) - 1.0)) * pitch,
                           (j + 0.5 + shape.jitter * (2.0 * unit(engine) - 1.0)) * pitch};
      const double angle = 2.0 * std::numbers::pi * unit(engine);
      ball.velocity = Vec2{std::cos(angle), std::sin(angle)} * (shape.speed * unit(engine));
      ball.mass = 0.5 + 1.5 * unit(engine);
      world.add_ball(ball);
    }
  }
  return world;
}

// Σ m·|v|: the scale momentum errors are measured against (the total itself may be near 0).
double momentum_scale(const World& world) {
  double sum = 0.0;
  for (BallId id : world.balls()) sum += world.mass(id) * length(world.velocity(id));
  return sum;
}

// Each elastic bounce changes the energy by a few roundings (~1e-16 relative) in a random
// direction; after n contacts the drift is ~√n·1e-16, 3e-14 for 10⁵ and 3e-13 for 10⁷. The bound
// 1e-10 leaves a wide margin and still catches any systematic loss (a wrong impulse, a missed
// restitution of 1, a bounce applied twice).
constexpr double kEnergyDriftTol = 1e-10;
// Each bounce exchanges exactly opposite impulses in exact arithmetic; the rounding of the two
// velocity updates is ~1e-16 of the pair's momentum, so the total drifts by ~√n·1e-16 of Σ m|v|.
constexpr double kMomentumDriftTol = 1e-12;

void expect_elastic_periodic_gas_conserves(std::uint64_t collisions, std::uint64_t chunk) {
  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {40.0, 40.0};
  World world = gas(def, GasShape{}, 61);
  const double energy = world.kinetic_energy();
  const Vec2 momentum = world.momentum();
  const double scale = momentum_scale(world);
  for (std::uint64_t done = 0; done < collisions; done += chunk) {
    ASSERT_EQ(world.run_collisions(chunk), chunk);
    ASSERT_LE(std::abs(world.kinetic_energy() - energy), kEnergyDriftTol * energy)
        << "after " << done + chunk << " contacts";
    ASSERT_LE(length(world.momentum() - momentum), kMomentumDriftTol * scale)
        << "after " << done + chunk << " contacts";
  }
  EXPECT_EQ(world.collision_count(), collisions);
  EXPECT_FALSE(world.audit().has_value());
}

TEST(WorldConservation, ElasticPeriodicGasKeepsEnergyAndMomentum) {
  expect_elastic_periodic_gas_conserves(100'000, 10'000);
}

TEST(WorldConservation, ElasticPeriodicGasKeepsEnergyAndMomentumLong) {
  if (!long_tests_enabled()) GTEST_SKIP() << "set CAROM_LONG_TESTS=1";
  expect_elastic_periodic_gas_conserves(10'000'000, 1'000'000);
}

// Worlds of 2¹⁶ balls and more prefetch the events ahead and defer filing new events in the
// queue (world_lookahead.cpp, event_queue.hpp), and from 2¹⁸ balls the lookahead goes a stage
// deeper; none of it may change a result. Such a gas, run in chunks (each run starts and ends
// the deferral and the lookahead afresh) and in one run, must end in the same state bit for bit,
// keep its energy and momentum, and pass the audit, in a periodic world and in a box (whose grid
// has edge cells the lookahead leaves out).
void expect_large_world_keeps_every_guarantee(int per_row, std::size_t least_balls) {
  constexpr std::uint64_t kContacts = 60'000;
  for (const Boundary boundary : {Boundary::periodic, Boundary::box}) {
    SCOPED_TRACE(boundary == Boundary::periodic ? "periodic" : "box");
    WorldDef def;
    def.boundary = boundary;
    def.lower = {0.0, 0.0};
    def.upper = {2.0 * per_row, 2.0 * per_row};  // a pitch of 2, as in the gases above
    World chunked = gas(def, GasShape{per_row}, 63);
    World whole = gas(def, GasShape{per_row}, 63);
    ASSERT_GE(chunked.ball_count(), least_balls);
    const double energy = whole.kinetic_energy();
    const Vec2 momentum = whole.momentum();
    const double scale = momentum_scale(whole);
    for (std::uint64_t done = 0; done < kContacts; done += kContacts / 6) {
      ASSERT_EQ(chunked.run_collisions(kContacts / 6), kContacts / 6);
    }
    ASSERT_EQ(whole.run_collisions(kContacts), kContacts);
    ASSERT_EQ(chunked.time(), whole.time());
    for (const BallId id : whole.balls()) {
      ASSERT_EQ(chunked.position(id), whole.position(id)) << "ball " << id.index;
      ASSERT_EQ(chunked.velocity(id), whole.velocity(id)) << "ball " << id.index;
    }
    EXPECT_LE(std::abs(whole.kinetic_energy() - energy), kEnergyDriftTol * energy);
    if (boundary == Boundary::periodic) {  // (walls take momentum)
      EXPECT_LE(length(whole.momentum() - momentum), kMomentumDriftTol * scale);
    }
    EXPECT_FALSE(whole.audit().has_value());
  }
}

TEST(WorldConservation, LargeWorldsThatPrefetchAheadKeepEveryGuarantee) {
  expect_large_world_keeps_every_guarantee(257, std::size_t{1} << 16);  // 66 049 balls
}

TEST(WorldConservation, LargeWorldsThatLookDeeperAheadKeepEveryGuarantee) {
  expect_large_world_keeps_every_guarantee(513, std::size_t{1} << 18);  // 263 169 balls
}

// A call that might never return (inelastic collapse) first runs in a child process under an
// alarm, so that a hang fails the test instead of stalling the suite. The run below takes ~0.1 s
// in an optimised build; 30 s is generous even under a sanitizer.
constexpr unsigned kGasWatchdogSeconds = 30;

TEST(WorldConservationDeathTest, InelasticGasWithCollapseGuardKeepsAdvancingAndCools) {
  constexpr double kEndTime = 20.0;
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {20.0, 20.0};
  def.restitution = 0.5;
  // Measured on this scene: with 0 (no guard) the run stalls before t = 2, spending its time on
  // ever faster contacts within clusters; 1e-4 (a hundredth of the time a ball takes to cross a
  // gap at the starting speeds) lets it reach t = 20 with ~7·10⁴ contacts.
  def.collapse_time = 1e-4;
  // Dense: radii 0.40–0.48 of the pitch, about 60% of the box covered.
  const GasShape dense{20, 0.40, 0.48, 0.01, 10.0};

  EXPECT_EXIT(
      {
        alarm(kGasWatchdogSeconds);
        World world = gas(def, dense, 62);
        world.run_until(kEndTime);
        std::_Exit(world.time() == kEndTime ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "")
      << "run_until must reach the end time (killed by SIGALRM: it never returned)";
  if (HasFailure()) return;

  World world = gas(def, dense, 62);
  const double energy = world.kinetic_energy();
  world.run_until(kEndTime);
  EXPECT_EQ(world.time(), kEndTime);
  EXPECT_GT(world.collision_count(), 10'000u);
  // With e = 0.5 a contact removes 3/8 of the pair's relative normal energy; after hundreds
  // of contacts per ball the gas keeps well under 1% of its energy (measured: ~0.06%).
  EXPECT_LT(world.kinetic_energy(), 0.01 * energy);
  EXPECT_GT(world.kinetic_energy(), 0.0);
  EXPECT_FALSE(world.audit().has_value());
}

}  // namespace
}  // namespace carom
