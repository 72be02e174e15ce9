// Balls in a bowl: contacts with the inside of an arc, where a ball moving along the wall
// re-enters it at once (docs/engine.md, "Response"). Before carom::bounce_inside_arc such
// a ball left through the arc.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "carom/bounce.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

BallDef bowl_ball(Vec2 position, Vec2 velocity, double radius = 0.5) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  return def;
}

// The distance of the ball's centre from the bowl's centre, checked against the bowl at every
// step: never beyond ρ (the arc's radius less the ball's) by more than the audit's rounding.
double steps_in_bowl(World& world, BallId ball, Vec2 center, int steps, double dt) {
  double nearest_to_center = INFINITY;
  for (int k = 0; k < steps; ++k) {
    world.step(dt);
    const auto problem = world.audit();
    EXPECT_FALSE(problem.has_value()) << "step " << k << ": " << *problem;
    if (problem) break;
    nearest_to_center = std::min(nearest_to_center, length(world.position(ball) - center));
  }
  return nearest_to_center;
}

// The fuzzer's case: a ball touching the inside of a full circle at its bottom, moving along it.
TEST(WorldBowl, BallSlidingAlongTheInsideOfAnArcStaysInside) {
  World world;
  world.add_arc({{20.0, 20.0}, 8.5, std::numbers::pi, 3.0 * std::numbers::pi});
  const BallId ball = world.add_ball(bowl_ball({20.0, 12.0}, {7.0, 0.0}));
  world.step(0.0121);
  EXPECT_FALSE(world.audit().has_value()) << *world.audit();
  EXPECT_LE(length(world.position(ball) - Vec2{20.0, 20.0}), 8.0 * (1.0 + 1e-15));
}

// Circular billiards keeps the angle to the wall, so a ball started along the wall circles in
// chords at the leaving angle (sine 2⁻⁷): chords of 2ρ·2⁻⁷ = 0.125 for ρ = 8, one contact every
// 0.125/7 time units at speed 7, within ρ·(1 − cos α) ≈ ρ·2⁻¹⁵ of the circle, its speed kept.
TEST(WorldBowl, ElasticBallStartedAlongTheWallCirclesInChordsKeepingItsEnergy) {
  World world;
  const Vec2 center{20.0, 20.0};
  world.add_arc({center, 8.5, 0.0, 2.0 * std::numbers::pi});
  const BallId ball = world.add_ball(bowl_ball({20.0, 12.0}, {7.0, 0.0}));
  const double energy = world.kinetic_energy();
  std::size_t contacts = 0;
  const double nearest = [&] {
    double least = INFINITY;
    for (int k = 0; k < 200; ++k) {
      world.step(0.1);
      contacts += world.contacts().size();
      EXPECT_FALSE(world.audit().has_value());
      least = std::min(least, length(world.position(ball) - center));
    }
    return least;
  }();
  // 20 time units of 140 units of travel: a contact at the start and one per 0.125 after.
  EXPECT_NEAR(static_cast<double>(contacts), 1.0 + 140.0 / 0.125, 2.0);
  // Energy: each contact turns the velocity (a few roundings of the speed), nothing more.
  EXPECT_NEAR(world.kinetic_energy(), energy, 1e-12 * energy);
  // The chords' midpoints are the nearest to the centre, ρ·cos α (α = asin 2⁻⁷); the steps'
  // ends fall anywhere along the chords, never nearer.
  const double rho = 8.0;
  EXPECT_GE(nearest, rho * std::sqrt(1.0 - kBowlLeavingSine * kBowlLeavingSine) - 1e-12);
  EXPECT_LE(length(world.position(ball) - center), rho * (1.0 + 1e-15));
}

// An inelastic ball loses normal speed bounce by bounce; once it arrives flatter than the
// sliding angle it slides (elastic bounces), so it keeps circling at a constant speed instead
// of leaving through the wall (where it went after ~50 bounces at e = 0.5 before).
TEST(WorldBowl, InelasticBallSettlesIntoSlidingAndStaysInside) {
  WorldDef def;
  def.restitution = 0.5;
  World world(def);
  const Vec2 center{0.0, 0.0};
  world.add_arc({center, 5.0, 0.0, 2.0 * std::numbers::pi});
  const BallId ball = world.add_ball(bowl_ball({0.0, -2.0}, {3.0, -4.0}));
  steps_in_bowl(world, ball, center, 1500, 1.0 / 60.0);  // 25 time units
  const double settled_speed = length(world.velocity(ball));
  EXPECT_GT(settled_speed, 1.0);  // it slides on, having lost its speed across the wall only
  EXPECT_LT(settled_speed, 5.0);
  const double nearest = steps_in_bowl(world, ball, center, 1500, 1.0 / 60.0);
  EXPECT_NEAR(length(world.velocity(ball)), settled_speed, 1e-12 * settled_speed);
  // Sliding, the angle's sine lies in [2⁻⁷, 2⁻⁶): every chord within ρ·(1 − cos α) < ρ·2⁻¹³
  // of the circle (ρ = 4.5).
  EXPECT_GT(nearest, 4.5 * (1.0 - 0x1p-13));
  EXPECT_LE(length(world.position(ball) - center), 4.5 * (1.0 + 1e-15));
}

// Found by the world fuzzer: nearest_free stops a ball on the inside of a bowl's top, then it is
// given a velocity along the wall but a rounding inwards (−1.7·10⁻¹⁵ across 7). Its path never
// got back inside the circle it touches the wall along, so no crossing was found, and it left
// through the arc: a ball on that circle counts as touching now unless its path goes back in.
TEST(WorldBowl, BallMovingARoundingInwardsAlongTheWallStaysInside) {
  World world;
  const Vec2 center{20.0, 0.70344090943770499};
  world.add_arc({center, 8.5, std::numbers::pi, 3.0 * std::numbers::pi});
  const BallId ball = world.add_ball(bowl_ball({20.0, 0.032654306858930345}, {}, 0.1));
  world.set_position(ball, {20.0, 20.0}, Placement::nearest_free);
  world.set_velocity(ball, {7.0, -1.7145055188062944e-15});
  const double nearest = steps_in_bowl(world, ball, center, 300, 1.0 / 60.0);
  EXPECT_GT(nearest, 8.4 * (1.0 - 0x1p-13));  // sliding round, as in the tests above
  EXPECT_NEAR(length(world.velocity(ball)), 7.0, 1e-12);
}

}  // namespace
}  // namespace carom
