// Edges of the two-moving-balls time of impact, one test each, plus the tutorial's method
// followed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "carom/bounce.hpp"
#include "carom/sweep.hpp"

namespace carom {
namespace {

// A worked example in the tutorial's steps, with the numbers done by hand:
//   ball 1 at (0, 0), radius 1, moves by v1 = (8, 0); ball 2 at (10, 1), radius 1, moves by
//   v2 = (−2, 0).
//   v3 = v1 − v2 = (10, 0): in ball 2's frame ball 1 slides along the x axis to (10, 0).
//   Contact when the centres are r1 + r2 = 2 apart: (x − 10)² + 1² = 4, so x = 10 − √3,
//   v4 = (10 − √3, 0) and t = |v4| / |v3| = 1 − √3/10 = 0.826794919...
//   p1 = (0, 0) + t·(8, 0) = (6.614359..., 0);  p2 = (10, 1) + t·(−2, 0) = (8.346410..., 1).
//   vc = p2 − p1 = (√3, 1), length 2; unit normal n = (√3/2, 1/2).
//   v1a = (v1·n) n = 4√3·n = (6, 2√3);       v1b = v1 − v1a = (2, −2√3)
//   v2a = (v2·n) n = −√3·n = (−3/2, −√3/2);  v2b = v2 − v2a = (−1/2, √3/2)
//   ball 1 leaves with v2a + v1b = (1/2, −5√3/2), ball 2 with v1a + v2b = (11/2, 5√3/2).
//   Momentum (6, 0) before and after; energy 64 + 4 = 68 = (1/4 + 75/4) + (121/4 + 75/4).
TEST(SweepBallBall, TutorialWorkedExample) {
  const double root3 = std::sqrt(3.0);
  const Ball ball1{{0.0, 0.0}, 1.0};
  const Ball ball2{{10.0, 1.0}, 1.0};
  const Vec2 v1{8.0, 0.0};
  const Vec2 v2{-2.0, 0.0};

  const Impact impact = sweep_ball_ball(ball1, v1, ball2, v2);
  ASSERT_TRUE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
  constexpr double kBallBallTol = 1e-14;  // a few ulps of the O(10) quantities involved
  EXPECT_NEAR(impact.t, 1.0 - root3 / 10.0, kBallBallTol);
  EXPECT_NEAR(impact.a_at.x, 8.0 * (1.0 - root3 / 10.0), kBallBallTol);
  EXPECT_NEAR(impact.a_at.y, 0.0, kBallBallTol);
  EXPECT_NEAR(impact.b_at.x, 10.0 - 2.0 * (1.0 - root3 / 10.0), kBallBallTol);
  EXPECT_NEAR(impact.b_at.y, 1.0, kBallBallTol);
  EXPECT_NEAR(impact.normal.x, root3 / 2.0, kBallBallTol);
  EXPECT_NEAR(impact.normal.y, 0.5, kBallBallTol);
  // Equal radii: the contact point is halfway between the centres.
  EXPECT_NEAR(impact.point.x, (impact.a_at.x + impact.b_at.x) / 2.0, kBallBallTol);
  EXPECT_NEAR(impact.point.y, 0.5, kBallBallTol);

  const BounceResult exchange = bounce_equal_mass(v1, v2, impact.b_at - impact.a_at);
  EXPECT_NEAR(exchange.velocity_a.x, 0.5, kBallBallTol);
  EXPECT_NEAR(exchange.velocity_a.y, -2.5 * root3, kBallBallTol);
  EXPECT_NEAR(exchange.velocity_b.x, 5.5, kBallBallTol);
  EXPECT_NEAR(exchange.velocity_b.y, 2.5 * root3, kBallBallTol);

  const BounceResult general = bounce(v1, 1.0, v2, 1.0, impact.normal, 1.0);
  EXPECT_NEAR(general.velocity_a.x, 0.5, kBallBallTol);
  EXPECT_NEAR(general.velocity_a.y, -2.5 * root3, kBallBallTol);
  EXPECT_NEAR(general.velocity_b.x, 5.5, kBallBallTol);
  EXPECT_NEAR(general.velocity_b.y, 2.5 * root3, kBallBallTol);
}

TEST(SweepBallBall, HeadOnExact) {
  const Impact impact =
      sweep_ball_ball({{0.0, 0.0}, 1.0}, {8.0, 0.0}, {{10.0, 0.0}, 1.0}, {-8.0, 0.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);  // 8 of gap closed at 16 per step: exact in binary
  EXPECT_EQ(impact.a_at, (Vec2{4.0, 0.0}));
  EXPECT_EQ(impact.b_at, (Vec2{6.0, 0.0}));
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
  EXPECT_EQ(impact.point, (Vec2{5.0, 0.0}));
}

TEST(SweepBallBall, MovingAgainstStandingBall) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 0.5}, {0.0, 4.0}, {{0.0, 3.0}, 1.5});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.25);
  EXPECT_EQ(impact.a_at, (Vec2{0.0, 1.0}));
  EXPECT_EQ(impact.b_at, (Vec2{0.0, 3.0}));
  EXPECT_EQ(impact.normal, (Vec2{0.0, 1.0}));
  EXPECT_EQ(impact.point, (Vec2{0.0, 1.5}));  // on A's surface, radius 0.5 from its centre
}

TEST(SweepBallBall, StopsShortIsNoHit) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {3.0, 0.0}, {{6.0, 0.0}, 1.0});
  EXPECT_FALSE(impact.hit);  // needs 4 to touch, moves 3
  EXPECT_FALSE(impact.overlapping);
}

TEST(SweepBallBall, ReachesExactlyAtStepEnd) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {4.0, 0.0}, {{6.0, 0.0}, 1.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 1.0);
}

TEST(SweepBallBall, TouchingAtStartAndSeparatingIsNoHit) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {-1.0, 0.5}, {{2.0, 0.0}, 1.0});
  EXPECT_FALSE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
}

TEST(SweepBallBall, TouchingAtStartAndSlidingPastIsNoHit) {
  // Relative motion exactly across the line of centres: the gap opens at second order.
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {0.0, 1.0}, {{2.0, 0.0}, 1.0});
  EXPECT_FALSE(impact.hit);
}

TEST(SweepBallBall, TouchingAtStartAndApproachingHitsAtZero) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {1.0, 0.0}, {{2.0, 0.0}, 1.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
}

TEST(SweepBallBall, OverlappingAndApproachingHitsAtZeroFlagged) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {1.0, 0.0}, {{1.5, 0.0}, 1.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_EQ(impact.a_at, (Vec2{0.0, 0.0}));
  EXPECT_EQ(impact.b_at, (Vec2{1.5, 0.0}));
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
}

TEST(SweepBallBall, OverlappingAndSeparatingIsReportedButNoHit) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {-1.0, 0.0}, {{1.5, 0.0}, 1.0});
  EXPECT_FALSE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
}

TEST(SweepBallBall, CoincidentCentresMovingCountAsApproaching) {
  const Impact impact = sweep_ball_ball({{1.0, 1.0}, 1.0}, {0.0, 2.0}, {{1.0, 1.0}, 1.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_EQ(impact.normal, (Vec2{0.0, 1.0}));  // the relative motion stands in for the line
}

TEST(SweepBallBall, ZeroRelativeMotionIsNoHit) {
  const Impact impact =
      sweep_ball_ball({{0.0, 0.0}, 1.0}, {5.0, 5.0}, {{3.0, 0.0}, 1.0}, {5.0, 5.0});
  EXPECT_FALSE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
}

TEST(SweepBallBall, BothStandingStillIsNoHit) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {}, {{3.0, 0.0}, 1.0});
  EXPECT_FALSE(impact.hit);
}

TEST(SweepBallBall, TangentialGrazeIsNoHit) {
  // The relative path passes B's centre at exactly r1 + r2 = 2: the discriminant is exactly 0.
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {10.0, 0.0}, {{5.0, 2.0}, 1.0});
  EXPECT_FALSE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
}

TEST(SweepBallBall, JustInsideTheGrazeHits) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {10.0, 0.0}, {{5.0, 1.999999}, 1.0});
  ASSERT_TRUE(impact.hit);
  // Half-chord √(4 − 1.999999²) ≈ 2.0e-3 before the closest approach at x = 5.
  EXPECT_NEAR(impact.t, (5.0 - std::sqrt(4.0 - 1.999999 * 1.999999)) / 10.0, 1e-12);
}

TEST(SweepBallBall, MovingAwayIsNoHit) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {-5.0, 0.0}, {{3.0, 0.0}, 1.0});
  EXPECT_FALSE(impact.hit);
}

TEST(SweepBallBall, FastBallsDoNotTunnel) {
  // Each moves 10⁶ radii per step; a discrete check at the step's ends would see nothing.
  const Impact impact =
      sweep_ball_ball({{-1e6, 0.5}, 1.0}, {2e6, 0.0}, {{1e6, -0.5}, 1.0}, {-2e6, 0.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.5 - std::sqrt(3.0) / 4e6, 1e-12);
}

TEST(SweepBallBall, LargePositionsSmallRadii) {
  // Positions near 10⁶ are spaced 1.16e-10 apart in double, so the gaps below carry that much
  // absolute rounding; relative to the 3e-3 gap that is about 4e-8 in t.
  const Ball a{{1e6, 1e6}, 1e-3};
  const Ball b{{1e6 + 0.005, 1e6}, 1e-3};
  const Impact impact = sweep_ball_ball(a, {0.01, 0.0}, b);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.3, 1e-7);
  EXPECT_NEAR(distance(impact.a_at, impact.b_at), 2e-3, 1e-9);
  // Tangential graze at that scale: still no false contact.
  const Impact graze =
      sweep_ball_ball({{1e6, 1e6}, 1e-3}, {0.01, 0.0}, {{1e6 + 0.005, 1e6 + 0.0025}, 1e-3});
  EXPECT_FALSE(graze.hit);
}

TEST(SweepBallBall, LargeRadiiSmallGap) {
  // Radii 10⁶, a gap of 1 closed by a relative movement of 2: every quantity is an integer
  // below 2⁵³, so the answer is exact.
  const Impact impact =
      sweep_ball_ball({{0.0, 0.0}, 1e6}, {1.0, 0.0}, {{2e6 + 1.0, 0.0}, 1e6}, {-1.0, 0.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.a_at, (Vec2{0.5, 0.0}));
  EXPECT_EQ(impact.point, (Vec2{1e6 + 0.5, 0.0}));
}

TEST(SweepBallBall, TinyEverything) {
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1e-9}, {4e-9, 0.0}, {{4e-9, 0.0}, 1e-9});
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.5, 1e-15);
}

TEST(TimeOfImpactBallBall, HorizonScalesTheStep) {
  // Velocities per time unit; contact at time 2.5 found with horizon 3, not with horizon 2.
  const Ball a{{0.0, 0.0}, 1.0};
  const Ball b{{7.0, 0.0}, 1.0};
  const Impact within = time_of_impact_ball_ball(a, {2.0, 0.0}, b, {}, 3.0);
  ASSERT_TRUE(within.hit);
  EXPECT_EQ(within.t, 2.5);
  EXPECT_EQ(within.a_at, (Vec2{5.0, 0.0}));
  EXPECT_FALSE(time_of_impact_ball_ball(a, {2.0, 0.0}, b, {}, 2.0).hit);
  // Horizon 0 answers only "in contact and approaching now".
  EXPECT_FALSE(time_of_impact_ball_ball(a, {2.0, 0.0}, b, {}, 0.0).hit);
}

TEST(TimeOfImpactBallBall, StepFormIsTimeFormWithHorizonOne) {
  const Ball a{{0.3, -0.2}, 0.7};
  const Ball b{{4.1, 1.9}, 1.1};
  const Impact step = sweep_ball_ball(a, {5.0, 3.0}, b, {-1.0, -0.5});
  const Impact time = time_of_impact_ball_ball(a, {5.0, 3.0}, b, {-1.0, -0.5}, 1.0);
  ASSERT_TRUE(step.hit);
  EXPECT_EQ(step.t, time.t);
  EXPECT_EQ(step.normal, time.normal);
}

TEST(SweepBallPoint, PointIsABallOfRadiusZero) {
  const Impact impact = sweep_ball_point({{0.0, 0.0}, 1.0}, {0.0, 4.0}, {0.0, 3.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.a_at, (Vec2{0.0, 2.0}));
  EXPECT_EQ(impact.b_at, (Vec2{0.0, 3.0}));
  EXPECT_EQ(impact.point, (Vec2{0.0, 3.0}));
  EXPECT_EQ(impact.normal, (Vec2{0.0, 1.0}));
  EXPECT_FALSE(sweep_ball_point({{0.0, 0.0}, 1.0}, {0.0, 4.0}, {1.0, 3.0}).hit);  // graze
}

}  // namespace
}  // namespace carom
