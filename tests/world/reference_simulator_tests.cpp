// The oracle checked on its own, against answers worked out by hand, before anything is
// compared with it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "world/random_scene.hpp"
#include "world/reference_simulator.hpp"

namespace carom::testing {
namespace {

// Hand-worked answers are exact in real arithmetic; a few roundings separate them from doubles.
constexpr double kRoundingTol = 1e-12;

ReferenceBall moving(Vec2 position, Vec2 velocity, double radius = 0.5) {
  ReferenceBall ball;
  ball.position = position;
  ball.velocity = velocity;
  ball.radius = radius;
  return ball;
}

TEST(ReferenceSimulator, HeadOnPairMeetsWhenTheGapCloses) {
  ReferenceScene scene;
  scene.balls = {moving({0.0, 0.0}, {1.0, 0.0}), moving({5.0, 0.0}, {-1.0, 0.0})};
  ReferenceSimulator reference(scene);
  reference.run_until(4.0);
  ASSERT_EQ(reference.contacts().size(), 1u);
  const ReferenceContact& c = reference.contacts()[0];
  EXPECT_EQ(c.kind, ContactKind::ball_ball);
  EXPECT_EQ(c.a, 0u);
  EXPECT_EQ(c.b, 1u);
  EXPECT_NEAR(c.time, 2.0, kRoundingTol);  // the gap of 4 closes at 2 per time unit
  EXPECT_NEAR(c.approach_speed, 2.0, kRoundingTol);
  EXPECT_NEAR(c.impulse, 2.0, kRoundingTol);  // (1 + e)·μ·w with μ = 1/2
  EXPECT_NEAR(reference.balls()[0].velocity.x, -1.0, kRoundingTol);
  EXPECT_NEAR(reference.balls()[1].position.x, 5.0, kRoundingTol);  // 3 at t = 2, back by 2
  EXPECT_EQ(reference.time(), 4.0);
}

TEST(ReferenceSimulator, RestitutionOfAPairIsTheSmaller) {
  EXPECT_EQ(combined_restitution(0.3, 0.9), 0.3);
  EXPECT_EQ(combined_restitution(1.0, 0.5), 0.5);
  ReferenceScene scene;
  scene.balls = {moving({0.0, 0.0}, {1.0, 0.0}), moving({2.0, 0.0}, {-1.0, 0.0})};
  scene.balls[0].restitution = 0.5;
  ReferenceSimulator reference(scene);
  reference.run_until(2.0);
  ASSERT_EQ(reference.contacts().size(), 1u);
  // Equal masses, e = 0.5: they leave at half the approach speed, symmetrically.
  EXPECT_NEAR(reference.balls()[0].velocity.x, -0.5, kRoundingTol);
  EXPECT_NEAR(reference.balls()[1].velocity.x, 0.5, kRoundingTol);
}

TEST(ReferenceSimulator, BallInABoxMeetsTheWallsInTurn) {
  ReferenceScene scene;
  for (const ReferenceWall& wall : box_walls({0.0, 0.0}, {10.0, 10.0})) scene.walls.push_back(wall);
  scene.balls = {moving({5.0, 5.0}, {2.0, 0.0}, 1.0)};
  ReferenceSimulator reference(scene);
  reference.run_until(7.0);
  ASSERT_EQ(reference.contacts().size(), 2u);
  EXPECT_EQ(reference.contacts()[0].wall, 1u);  // the right side first, at x = 9
  EXPECT_NEAR(reference.contacts()[0].time, 2.0, kRoundingTol);
  EXPECT_EQ(reference.contacts()[1].wall, 3u);  // then the left side, at x = 1
  EXPECT_NEAR(reference.contacts()[1].time, 6.0, kRoundingTol);
  EXPECT_NEAR(reference.balls()[0].position.x, 3.0, kRoundingTol);
}

TEST(ReferenceSimulator, SimultaneousContactsGoInTheDocumentedOrder) {
  // Newton's cradle: the striker and a row of five touching balls.
  ReferenceScene scene;
  scene.balls.push_back(moving({-3.0, 0.0}, {1.0, 0.0}));
  for (int i = 0; i < 5; ++i) scene.balls.push_back(moving({i * 1.0, 0.0}, {}));
  ReferenceSimulator reference(scene);
  reference.run_until(3.0);
  ASSERT_EQ(reference.contacts().size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(reference.contacts()[k].a, k);
    EXPECT_EQ(reference.contacts()[k].b, k + 1);
    EXPECT_NEAR(reference.contacts()[k].time, 2.0, kRoundingTol);
  }
  EXPECT_NEAR(reference.balls()[5].velocity.x, 1.0, kRoundingTol);
  EXPECT_NEAR(reference.balls()[0].velocity.x, 0.0, kRoundingTol);
}

TEST(ReferenceSimulator, PeriodicPairMeetsThroughTheCellEdge) {
  ReferenceScene scene;
  scene.periodic = true;
  scene.lower = {0.0, 0.0};
  scene.upper = {10.0, 10.0};
  // 1 and 9 are 2 apart through the edge at 0 ≡ 10: the gap of 1 closes at 2 per time unit.
  scene.balls = {moving({1.0, 5.0}, {-1.0, 0.0}), moving({9.0, 5.0}, {1.0, 0.0})};
  ReferenceSimulator reference(scene);
  reference.run_until(1.0);
  ASSERT_EQ(reference.contacts().size(), 1u);
  EXPECT_NEAR(reference.contacts()[0].time, 0.5, kRoundingTol);
  EXPECT_NEAR(reference.contacts()[0].normal.x, -1.0, kRoundingTol);  // from ball 0 across 0
  // Bounced back: ball 0 at 0.5 + 0.5 = 1, ball 1 at 9.
  EXPECT_NEAR(reference.balls()[0].position.x, 1.0, kRoundingTol);
  EXPECT_NEAR(reference.balls()[1].position.x, 9.0, kRoundingTol);
}

TEST(ReferenceSimulator, PeriodicBallWrapsIntoTheCell) {
  ReferenceScene scene;
  scene.periodic = true;
  scene.lower = {0.0, 0.0};
  scene.upper = {10.0, 10.0};
  scene.balls = {moving({9.0, 9.0}, {3.0, -4.0})};
  ReferenceSimulator reference(scene);
  reference.run_until(1.0);
  EXPECT_NEAR(reference.balls()[0].position.x, 2.0, kRoundingTol);
  EXPECT_NEAR(reference.balls()[0].position.y, 5.0, kRoundingTol);
}

TEST(ReferenceSimulator, RunCollisionsStopsRightAfterTheLast) {
  ReferenceScene scene;
  for (const ReferenceWall& wall : box_walls({0.0, 0.0}, {10.0, 10.0})) scene.walls.push_back(wall);
  scene.balls = {moving({5.0, 5.0}, {2.0, 0.0}, 1.0)};
  ReferenceSimulator reference(scene);
  EXPECT_EQ(reference.run_collisions(1, 100.0), 1u);
  EXPECT_NEAR(reference.time(), 2.0, kRoundingTol);
  EXPECT_EQ(reference.run_collisions(5, 8.0), 1u);  // at t = 6; the next, t = 10, is past 8
  EXPECT_EQ(reference.time(), 8.0);
}

TEST(ReferenceSimulator, ElasticGasKeepsItsEnergy) {
  GasOptions options;
  options.ball_count = 60;
  options.side = 40.0;
  options.max_speed = 20.0;
  const ReferenceScene scene = random_gas(options, 5);
  auto energy = [](const std::vector<ReferenceBall>& balls) {
    double sum = 0.0;
    for (const ReferenceBall& b : balls) sum += 0.5 * b.mass * length_squared(b.velocity);
    return sum;
  };
  ReferenceSimulator reference(scene);
  reference.run_until(5.0);
  EXPECT_GT(reference.contacts().size(), 200u);
  // Each bounce rounds the energy by ~1e-16 relative; hundreds stay far below 1e-12.
  EXPECT_NEAR(energy(reference.balls()), energy(scene.balls), 1e-12 * energy(scene.balls));
  // No ball ever left the box.
  for (const ReferenceBall& b : reference.balls()) {
    EXPECT_GE(b.position.x, b.radius * (1.0 - 1e-9));
    EXPECT_LE(b.position.x, options.side - b.radius * (1.0 - 1e-9));
  }
}

}  // namespace
}  // namespace carom::testing
