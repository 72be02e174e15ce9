// A ball against a wall: the segment's interior from either side, its end points (corners),
// and the edges of that contact.
#include <gtest/gtest.h>

#include <cmath>

#include "carom/sweep.hpp"

namespace carom {
namespace {

const Segment kFloor{{-5.0, 0.0}, {5.0, 0.0}};

TEST(SweepBallSegment, HitsInteriorFromAbove) {
  const Impact impact = sweep_ball_segment({{1.0, 3.0}, 1.0}, {0.0, -4.0}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.a_at, (Vec2{1.0, 1.0}));
  EXPECT_EQ(impact.point, (Vec2{1.0, 0.0}));
  EXPECT_EQ(impact.b_at, impact.point);
  EXPECT_EQ(impact.normal, (Vec2{0.0, -1.0}));  // from the ball towards the wall
}

TEST(SweepBallSegment, HitsInteriorFromBelow) {
  const Impact impact = sweep_ball_segment({{-2.0, -3.0}, 1.0}, {2.0, 4.0}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.normal, (Vec2{0.0, 1.0}));
  EXPECT_EQ(impact.point, (Vec2{-1.0, 0.0}));
}

TEST(SweepBallSegment, SlantedWall) {
  // The line x + y = 0 through (−5, 5) and (5, −5); ball at (3, 3), distance 3√2, radius √2,
  // moving by (−2, −2) per step: it closes at 2√2 per step and touches after 2√2: t = 1.
  const Segment slanted{{-5.0, 5.0}, {5.0, -5.0}};
  const Impact impact = sweep_ball_segment({{3.0, 3.0}, std::sqrt(2.0)}, {-2.0, -2.0}, slanted);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 1.0, 1e-15);
  EXPECT_NEAR(impact.point.x, 0.0, 1e-15);
  EXPECT_NEAR(impact.normal.x, -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(impact.normal.y, -std::sqrt(0.5), 1e-15);
}

TEST(SweepBallSegment, HitsEndPointLikeACorner) {
  // Ball passes beside the segment's end: its path stays 0.6 away from the end point's line of
  // motion, so it meets the end point (5, 0) when |(x − 5, 0.6)| = 1, x = 5 − 0.8.
  const Impact impact =
      sweep_ball_segment({{0.0, 0.6}, 1.0}, {10.0, 0.0}, Segment{{5.0, -5.0}, {5.0, 0.0}});
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.42, 1e-15);
  EXPECT_EQ(impact.point, (Vec2{5.0, 0.0}));
  EXPECT_NEAR(impact.normal.x, 0.8, 1e-15);
  EXPECT_NEAR(impact.normal.y, -0.6, 1e-15);
}

TEST(SweepBallSegment, HeadOnIntoTheEndPoint) {
  const Impact impact = sweep_ball_segment({{-10.0, 0.0}, 1.0}, {8.0, 0.0}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.point, (Vec2{-5.0, 0.0}));
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
}

TEST(SweepBallSegment, PassesBeyondTheEndIsNoHit) {
  const Impact impact = sweep_ball_segment({{7.0, 3.0}, 1.0}, {0.0, -6.0}, kFloor);
  EXPECT_FALSE(impact.hit);  // 2 beyond the end, radius 1
}

TEST(SweepBallSegment, RollingAlongTheWallIsNoHit) {
  const Impact impact = sweep_ball_segment({{-3.0, 1.0}, 1.0}, {6.0, 0.0}, kFloor);
  EXPECT_FALSE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
}

TEST(SweepBallSegment, SlidingAlongTheWallIsNoHitWhereverTheNearestPointRounds) {
  // Found by the world's "ball rolling along a wall" scene: at x = 13/3 the nearest point on
  // the wall, a + (b − a)·fraction, rounds an ulp ahead of the centre, which looked like a
  // 1e-15 approach. The interior's direction is now the wall's exact normal.
  const Segment floor{{0.0, 0.0}, {10.0, 0.0}};
  for (int i = 1; i < 1000; ++i) {
    const double x = 10.0 * i / 1000.0 + 1.0 / 3.0;
    const Impact impact = sweep_ball_segment({{x, 0.5}, 0.5}, {1.0, 0.0}, floor);
    ASSERT_FALSE(impact.hit) << "x = " << x;
    ASSERT_FALSE(impact.overlapping) << "x = " << x;
  }
}

TEST(SweepBallSegment, TouchingAndLeavingIsNoHit) {
  const Impact impact = sweep_ball_segment({{0.0, 1.0}, 1.0}, {1.0, 1.0}, kFloor);
  EXPECT_FALSE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
}

TEST(SweepBallSegment, TouchingAndPressingHitsAtZero) {
  const Impact impact = sweep_ball_segment({{0.0, 1.0}, 1.0}, {1.0, -1.0}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_FALSE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_EQ(impact.normal, (Vec2{0.0, -1.0}));
}

TEST(SweepBallSegment, OverlappingAndApproachingHitsAtZeroFlagged) {
  const Impact impact = sweep_ball_segment({{0.0, 0.5}, 1.0}, {0.0, -1.0}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_EQ(impact.point, (Vec2{0.0, 0.0}));
}

TEST(SweepBallSegment, OverlappingAndSeparatingIsReportedButNoHit) {
  const Impact impact = sweep_ball_segment({{0.0, 0.5}, 1.0}, {0.0, 1.0}, kFloor);
  EXPECT_FALSE(impact.hit);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.normal, (Vec2{0.0, -1.0}));
}

TEST(SweepBallSegment, ZeroLengthSegmentIsAPoint) {
  const Segment dot_like{{0.0, 3.0}, {0.0, 3.0}};
  const Impact impact = sweep_ball_segment({{0.0, 0.0}, 1.0}, {0.0, 4.0}, dot_like);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.point, (Vec2{0.0, 3.0}));
}

TEST(SweepBallSegment, FastBallDoesNotTunnelThroughThinWall) {
  const Impact impact = sweep_ball_segment({{0.0, -1e6}, 1e-3}, {1e-3, 2e6}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.5 - 0.5e-9, 1e-15);
}

TEST(SweepBallSegment, EarliestOfInteriorAndEndPoint) {
  // Moving diagonally towards the floor near its end: the interior is reached first.
  const Impact impact = sweep_ball_segment({{4.0, 2.0}, 1.0}, {2.0, -2.0}, kFloor);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.point, (Vec2{5.0, 0.0}));  // exactly at the end: both candidates agree
}

TEST(TimeOfImpactBallSegment, Horizon) {
  const Ball ball{{0.0, 5.0}, 1.0};
  EXPECT_EQ(time_of_impact_ball_segment(ball, {0.0, -2.0}, kFloor, 10.0).t, 2.0);
  EXPECT_FALSE(time_of_impact_ball_segment(ball, {0.0, -2.0}, kFloor, 1.5).hit);
}

// Found by the world fuzzer: a ball dragged until it touched a slanted wall, then dragged through
// it. By the side test (distance from the line) it touched the wall; by the nearest-point test
// (contact_at_start) it was 2e-16 clear. Each left the contact to the other, and the ball crossed
// the interior to meet the far end point 0.002 later, overlapping the wall by 0.006.
TEST(SweepBallSegment, TouchingTheInteriorWhereTheTwoMeasuresDisagreeHitsAtZero) {
  const Segment wall{{0.00030518043793392844, 0.043030441748683909},
                     {3.7650110627908751, 7.8416113527122908}};
  const Ball ball{{3.661002536209665, 7.8561818951218099}, 0.1};
  const Vec2 move = Vec2{5.882352941176471, 5.882352941176471} - ball.center;
  const Impact impact = time_of_impact_ball_segment(ball, move, wall, 1.0);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.0);
  // The interior's normal, not the end point's.
  const Vec2 along = normalized(wall.b - wall.a);
  EXPECT_NEAR(impact.normal.x, along.y, 1e-12);
  EXPECT_NEAR(impact.normal.y, -along.x, 1e-12);
}

}  // namespace
}  // namespace carom
