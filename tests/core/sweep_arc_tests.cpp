// A ball against an arc: from outside, from inside (a bowl), through the arc's gap, and at its
// end points.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "carom/error.hpp"
#include "carom/sweep.hpp"

namespace carom {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-14;  // a few ulps of the O(10) coordinates used here

// The upper half of the circle of radius 5 about the origin.
const Arc kDome{{0.0, 0.0}, 5.0, 0.0, kPi};
// The lower half: a bowl.
const Arc kBowl{{0.0, 0.0}, 5.0, kPi, 2.0 * kPi};

TEST(SweepBallArc, HitsFromOutside) {
  const Impact impact = sweep_ball_arc({{0.0, 10.0}, 1.0}, {0.0, -8.0}, kDome);
  ASSERT_TRUE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
  EXPECT_NEAR(impact.t, 0.5, kTol);
  EXPECT_NEAR(impact.point.y, 5.0, kTol);
  EXPECT_NEAR(impact.normal.y, -1.0, kTol);
}

TEST(SweepBallArc, HitsFromInsideTheBowl) {
  // Ball of radius 1 at the centre falling: touches the bowl when its centre is 4 below.
  const Impact impact = sweep_ball_arc({{0.0, 0.0}, 1.0}, {0.0, -8.0}, kBowl);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.5, kTol);
  EXPECT_NEAR(impact.a_at.y, -4.0, kTol);
  EXPECT_NEAR(impact.point.y, -5.0, kTol);
  EXPECT_NEAR(impact.normal.y, -1.0, kTol);
}

TEST(SweepBallArc, PassesThroughTheGapAndHitsTheFarSideFromInside) {
  // From below the dome's missing lower half, the ball enters the circle freely and meets the
  // dome's inner face at the top: centre at y = 4.
  const Impact impact = sweep_ball_arc({{0.0, -10.0}, 1.0}, {0.0, 20.0}, kDome);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.7, kTol);
  EXPECT_NEAR(impact.point.y, 5.0, kTol);
  EXPECT_NEAR(impact.normal.y, 1.0, kTol);
}

TEST(SweepBallArc, HitsTheEndPoint) {
  // The dome's end point (5, 0), approached from below along x = 5.6: touches when
  // |(5.6 − 5, y)| = 1, y = −0.8.
  const Impact impact = sweep_ball_arc({{5.6, -10.0}, 1.0}, {0.0, 10.0}, kDome);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.92, kTol);
  EXPECT_NEAR(impact.point.x, 5.0, kTol);
  EXPECT_NEAR(impact.point.y, 0.0, kTol);
  EXPECT_NEAR(impact.normal.x, -0.6, kTol);
  EXPECT_NEAR(impact.normal.y, 0.8, kTol);
}

TEST(SweepBallArc, MissesOutsideTheSpan) {
  // Falls beside the dome's gap far below: never reaches the upper half or its ends.
  EXPECT_FALSE(sweep_ball_arc({{0.0, -10.0}, 1.0}, {0.0, 3.0}, kDome).hit);
  // Moves away from the dome.
  EXPECT_FALSE(sweep_ball_arc({{0.0, 10.0}, 1.0}, {0.0, 8.0}, kDome).hit);
}

TEST(SweepBallArc, RestingInTheBowlAndMovingUpHitsTheOtherSideLater) {
  // Touching the bottom from inside and leaving it: no contact now, but the ball crosses the
  // bowl's circle and can meet its inside again only within the span. Straight up it leaves
  // through the open top: no hit.
  EXPECT_FALSE(sweep_ball_arc({{0.0, -4.0}, 1.0}, {0.0, 20.0}, kBowl).hit);
  // Sideways and up, it meets the bowl's wall at the other side, below the rim.
  const Impact impact = sweep_ball_arc({{0.0, -4.0}, 1.0}, {8.0, 2.0}, kBowl);
  ASSERT_TRUE(impact.hit);
  EXPECT_GT(impact.t, 0.0);
  EXPECT_NEAR(length(impact.a_at), 4.0, 1e-12);
  EXPECT_LT(impact.point.y, 0.0);
}

// Inside a circle a ball touching the wall and moving along it re-enters the wall at once (the
// gap closes at second order): unlike a graze of a flat or convex wall, it is a hit now, with
// normal speed 0 (carom::bounce_inside_arc answers it).
TEST(SweepBallArc, TouchingTheInsideAndMovingAlongItHitsAtZero) {
  const Impact step = sweep_ball_arc({{0.0, -4.0}, 1.0}, {3.0, 0.0}, kBowl);
  ASSERT_TRUE(step.hit);
  EXPECT_FALSE(step.overlapping);
  EXPECT_EQ(step.t, 0.0);
  EXPECT_NEAR(step.normal.x, 0.0, kTol);
  EXPECT_NEAR(step.normal.y, -1.0, kTol);
  EXPECT_NEAR(step.point.y, -5.0, kTol);
  const Impact timed = time_of_impact_ball_arc({{0.0, -4.0}, 1.0}, {-3.0, 0.0}, kBowl, 10.0);
  ASSERT_TRUE(timed.hit);
  EXPECT_EQ(timed.t, 0.0);
  // At rest it stays: no hit.
  EXPECT_FALSE(time_of_impact_ball_arc({{0.0, -4.0}, 1.0}, {0.0, 0.0}, kBowl, 10.0).hit);
}

TEST(SweepBallArc, TouchingTheOutsideAndMovingAlongItIsNoHit) {
  // The convex side: a ball moving along it slides clear.
  EXPECT_FALSE(sweep_ball_arc({{0.0, 6.0}, 1.0}, {3.0, 0.0}, kDome).hit);
}

// A ball as large as the arc's circle on its centre fills it: any motion meets the wall at once,
// where it moves to.
TEST(SweepBallArc, BallFillingTheCircleHitsAtZeroWhereItMoves) {
  const Arc ring{{0.0, 0.0}, 5.0, 0.0, 2.0 * kPi};
  const Impact impact = time_of_impact_ball_arc({{0.0, 0.0}, 5.0}, {0.0, -2.0}, ring, 1.0);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_NEAR(impact.normal.y, -1.0, kTol);
  EXPECT_NEAR(impact.point.y, -5.0, kTol);
  // Towards the dome's gap it meets nothing there.
  EXPECT_FALSE(time_of_impact_ball_arc({{0.0, 0.0}, 5.0}, {0.0, -2.0}, kDome, 1.0).hit);
}

TEST(SweepBallArc, OverlappingAndApproachingHitsAtZeroFlagged) {
  const Impact impact = sweep_ball_arc({{0.0, 5.5}, 1.0}, {0.0, -1.0}, kDome);
  ASSERT_TRUE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_NEAR(impact.point.y, 5.0, kTol);
}

TEST(SweepBallArc, OverlappingAndSeparatingIsReportedButNoHit) {
  const Impact impact = sweep_ball_arc({{0.0, 5.5}, 1.0}, {0.0, 1.0}, kDome);
  EXPECT_FALSE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
}

TEST(SweepBallArc, FullCircleHasNoGap) {
  const Arc ring{{0.0, 0.0}, 5.0, 0.0, 2.0 * kPi};
  const Impact impact = sweep_ball_arc({{0.0, -10.0}, 1.0}, {0.0, 20.0}, ring);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.2, kTol);  // outer face at y = −6
}

TEST(SweepBallArc, FullCircleComputedAsStartPlusTwoPiIsAccepted) {
  // (1.8 + 2π) − 1.8 rounds to one ulp above 2π: still the full circle, not an error.
  const Arc ring{{0.0, 0.0}, 5.0, 1.8, 1.8 + 2.0 * kPi};
  ASSERT_GT(ring.end_angle - ring.start_angle, 2.0 * kPi);
  EXPECT_TRUE(sweep_ball_arc({{0.0, -10.0}, 1.0}, {0.0, 20.0}, ring).hit);
  // A real excess is still refused.
  EXPECT_THROW((void)sweep_ball_arc({{0.0, -10.0}, 1.0}, {0.0, 20.0}, {{}, 5.0, 1.0, 7.3}),
               InvalidArgument);
}

TEST(SweepBallArc, ZeroSpanIsAPoint) {
  const Arc point_like{{0.0, 0.0}, 5.0, kPi / 2.0, kPi / 2.0};  // the point (0, 5)
  const Impact impact = sweep_ball_arc({{0.0, 10.0}, 1.0}, {0.0, -8.0}, point_like);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.5, kTol);
  // A path through the centre, away from that point, never touches it.
  EXPECT_FALSE(sweep_ball_arc({{-10.0, 0.0}, 1.0}, {20.0, 0.0}, point_like).hit);
}

TEST(SweepBallArc, BallLargerThanTheArcReachesAcrossItsCentre) {
  // Arc radius 1 (upper half), ball radius 3 coming from below: the ball's far side touches the
  // arc's top (0, 1) when its centre is at (0, −2).
  const Arc small{{0.0, 0.0}, 1.0, 0.0, kPi};
  const Impact impact = sweep_ball_arc({{0.0, -10.0}, 3.0}, {0.0, 10.0}, small);
  ASSERT_TRUE(impact.hit);
  // The end points (±1, 0) are met first: |(1, y)| = 3 at y = −√8.
  EXPECT_NEAR(impact.t, (10.0 - std::sqrt(8.0)) / 10.0, kTol);
}

TEST(TimeOfImpactBallArc, Horizon) {
  const Ball ball{{0.0, 10.0}, 1.0};
  EXPECT_NEAR(time_of_impact_ball_arc(ball, {0.0, -2.0}, kDome, 5.0).t, 2.0, kTol);
  EXPECT_FALSE(time_of_impact_ball_arc(ball, {0.0, -2.0}, kDome, 1.0).hit);
}

}  // namespace
}  // namespace carom
