// Extreme but valid input for the time of impact: 10⁶ diameters per step, radii from
// 10⁻⁶ to 10⁶ in one pair, balls exactly touching at the start, an arc of zero span and a
// segment of zero length (both a point). Each works exactly as documented in sweep.hpp; the one
// finite input refused is an arc whose circle reaches beyond the double range.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "random_cases.hpp"

namespace carom {
namespace {

// ---- 10⁶ diameters per step -------------------------------------------------------------------

TEST(SweepEdgeInput, MillionDiametersPerStepBallBall) {
  // Radius 1 moving 2·10⁶ (10⁶ diameters) at a ball 10⁶ + 2 away: the gap of 10⁶ is closed at
  // exactly half the step (every quantity an integer below 2⁵³, so the answer is exact).
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1.0}, {2e6, 0.0}, {{1e6 + 2.0, 0.0}, 1.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.5);
  EXPECT_EQ(impact.a_at, (Vec2{1e6, 0.0}));
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
  // Both balls that fast, passing 1.9 apart (radii 1): a contact a discrete check would miss.
  const Impact crossing =
      sweep_ball_ball({{-1e6, 0.95}, 1.0}, {2e6, 0.0}, {{1e6, -0.95}, 1.0}, {-2e6, 0.0});
  ASSERT_TRUE(crossing.hit);
  // Touch at centre distance 2: along x they are 2·√(1 − 0.95²) apart, closing at 4·10⁶ per
  // step from 2·10⁶. The positions carry 1.2e-10 rounding, 3e-17 of the step.
  EXPECT_NEAR(crossing.t, 0.5 - std::sqrt(1.0 - 0.95 * 0.95) / 2e6, 1e-15);
}

TEST(SweepEdgeInput, MillionDiametersPerStepWallsAndArcs) {
  const Impact wall = sweep_ball_segment({{0.0, -1e6}, 1.0}, {0.0, 2e6}, {{-5.0, 1.0}, {5.0, 1.0}});
  ASSERT_TRUE(wall.hit);
  EXPECT_EQ(wall.t, 0.5);  // the centre travels 10⁶ to y = 0, one radius below the wall
  EXPECT_EQ(wall.normal, (Vec2{0.0, 1.0}));
  const Impact arc = sweep_ball_arc({{0.0, -1e6}, 1.0}, {0.0, 2e6},
                                    {{0.0, 5.0}, 4.0, std::numbers::pi, 2.0 * std::numbers::pi});
  ASSERT_TRUE(arc.hit);
  EXPECT_EQ(arc.t, 0.5);  // the arc's lowest point (0, 1) meets the ball's top at y = 0
}

// ---- radii 10⁻⁶ and 10⁶ in one pair -----------------------------------------------------------

TEST(SweepEdgeInput, RadiiFromMicroToMegaInOnePair) {
  // A 10⁻⁶ ball moving 3·10⁶ head on at a 10⁶ ball 2·10⁶ away: contact after travelling
  // 2·10⁶ − 10⁶ − 10⁻⁶. The quadratic's terms are near 10¹², whose rounding (1.2e-4) is 4e-17
  // of c; t to 2e-16 relative.
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1e-6}, {3e6, 0.0}, {{2e6, 0.0}, 1e6});
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, (1e6 - 1e-6) / 3e6, 2e-16);
  EXPECT_NEAR(impact.point.x, 1e6, 1e-9);  // on the big ball's surface
  // Off centre: the small ball passes the big one at distance 10⁶ + 2·10⁻⁶ from its centre,
  // just beyond the reach 10⁶ + 10⁻⁶: no contact. And 10⁻⁶·0.5 inside it: contact.
  EXPECT_FALSE(sweep_ball_ball({{0.0, 1e6 + 2e-6}, 1e-6}, {4e6, 0.0}, {{2e6, 0.0}, 1e6}).hit);
  EXPECT_TRUE(sweep_ball_ball({{0.0, 1e6 + 0.5e-6}, 1e-6}, {4e6, 0.0}, {{2e6, 0.0}, 1e6}).hit);
  // Swapped roles, the big ball moving: the same contact time (the pair's symmetry).
  const Impact swapped = sweep_ball_ball({{2e6, 0.0}, 1e6}, {-3e6, 0.0}, {{0.0, 0.0}, 1e-6});
  ASSERT_TRUE(swapped.hit);
  EXPECT_EQ(swapped.t, impact.t);
}

TEST(SweepEdgeInput, MicroBallAgainstMegaArcAndWall) {
  // A 10⁻⁶ ball inside a bowl of radius 10⁶, dropped from its centre: it meets the bottom
  // when its centre is 10⁶ − 10⁻⁶ below the bowl's centre.
  const Impact bowl = sweep_ball_arc({{0.0, 0.0}, 1e-6}, {0.0, -2e6},
                                     {{0.0, 0.0}, 1e6, std::numbers::pi, 2.0 * std::numbers::pi});
  ASSERT_TRUE(bowl.hit);
  EXPECT_NEAR(bowl.t, (1e6 - 1e-6) / 2e6, 2e-16);
  EXPECT_EQ(bowl.normal, (Vec2{0.0, -1.0}));
  const Impact wall = sweep_ball_segment({{0.0, 0.0}, 1e-6}, {2e6, 0.0}, {{1e6, -1e6}, {1e6, 1e6}});
  ASSERT_TRUE(wall.hit);
  EXPECT_NEAR(wall.t, (1e6 - 1e-6) / 2e6, 2e-16);
}

// ---- exactly touching at the start ------------------------------------------------------------

// For every shape and at three scales (exact powers of two, so touching stays exact): pressing
// in is a hit at t = 0, leaving or sliding along is no hit, and touching is never overlapping.
TEST(SweepEdgeInput, ExactlyTouchingAtTheStartEveryShapeAndScale) {
  for (const int e : {-900, 0, 900}) {
    const double k = std::ldexp(1.0, e);
    const Ball ball{{0.0, 0.0}, k};
    const Vec2 in{k, 0.0};     // towards +x, where every shape touches the ball
    const Vec2 out{-k, 0.0};   // away
    const Vec2 slide{0.0, k};  // tangential
    const Ball other{{2.0 * k, 0.0}, k};
    const Vec2 point{k, 0.0};
    const Segment wall{{k, -k}, {k, k}};
    const Arc arc{{2.0 * k, 0.0},
                  k,
                  std::numbers::pi / 2.0,
                  3.0 * std::numbers::pi / 2.0};  // its left half, touching at (k, 0)
    const std::string scale = "scale 2^" + std::to_string(e);

    const Impact pressing[] = {sweep_ball_ball(ball, in, other), sweep_ball_point(ball, in, point),
                               sweep_ball_segment(ball, in, wall), sweep_ball_arc(ball, in, arc)};
    for (const Impact& impact : pressing) {
      EXPECT_TRUE(impact.hit) << scale;
      EXPECT_EQ(impact.t, 0.0) << scale;
      EXPECT_FALSE(impact.overlapping) << scale;
      EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0})) << scale;
    }
    for (const Vec2 move : {out, slide}) {
      const Impact leaving[] = {
          sweep_ball_ball(ball, move, other), sweep_ball_point(ball, move, point),
          sweep_ball_segment(ball, move, wall), sweep_ball_arc(ball, move, arc)};
      for (const Impact& impact : leaving) {
        EXPECT_FALSE(impact.hit) << scale << " move (" << move.x << ", " << move.y << ")";
        EXPECT_FALSE(impact.overlapping) << scale;
      }
    }
  }
}

// ---- zero-length shapes -----------------------------------------------------------------------

TEST(SweepEdgeInput, ZeroLengthSegmentIsExactlyItsPoint) {
  testing::RandomCases random(9101);
  for (int i = 0; i < 20000; ++i) {
    const Ball a = random.ball(10.0);
    const Vec2 p = random.point(10.0);
    const Vec2 move = random.move_towards(a.center, p, 3.0);
    const Impact point = sweep_ball_point(a, move, p);
    const Impact segment = sweep_ball_segment(a, move, {p, p});
    ASSERT_EQ(segment.hit, point.hit) << "case " << i;
    ASSERT_EQ(segment.overlapping, point.overlapping) << "case " << i;
    ASSERT_EQ(segment.t, point.t) << "case " << i;
    ASSERT_EQ(segment.normal, point.normal) << "case " << i;
    ASSERT_EQ(segment.point, point.point) << "case " << i;
  }
}

TEST(SweepEdgeInput, ZeroSpanArcIsItsPoint) {
  // The arc's point is centre + radius·(cos θ, sin θ), computed here as the library does.
  testing::RandomCases random(9102);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ball a = random.ball(10.0);
    const Arc arc_like = random.arc(10.0);
    const Arc arc{arc_like.center, arc_like.radius, arc_like.start_angle, arc_like.start_angle};
    const Vec2 p =
        arc.center + Vec2{std::cos(arc.start_angle), std::sin(arc.start_angle)} * arc.radius;
    const Vec2 move = random.move_towards(a.center, p, 3.0);
    const Impact point = sweep_ball_point(a, move, p);
    const Impact zero_span = sweep_ball_arc(a, move, arc);
    ASSERT_EQ(zero_span.hit, point.hit) << "case " << i;
    ASSERT_EQ(zero_span.t, point.t) << "case " << i;
    ASSERT_EQ(zero_span.point, point.point) << "case " << i;
    hits += point.hit ? 1 : 0;
  }
  EXPECT_GT(hits, 2000);
}

TEST(SweepEdgeInput, CentreExactlyOnAPointAndMovingHitsAtZero) {
  // As for a segment or an arc: a centre on the shape has no side to leave to. (Before, a point
  // alone answered no hit here, unlike the zero-length segment at the same place.)
  const Impact impact = sweep_ball_point({{1.0, 2.0}, 0.5}, {0.0, 3.0}, {1.0, 2.0});
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 0.0);
  EXPECT_TRUE(impact.overlapping);
  EXPECT_EQ(impact.normal, (Vec2{0.0, 1.0}));
  EXPECT_FALSE(sweep_ball_point({{1.0, 2.0}, 0.5}, {}, {1.0, 2.0}).hit);  // standing still
}

// ---- the one refusal of finite input ----------------------------------------------------------

TEST(SweepEdgeInput, ArcReachingBeyondTheDoubleRangeIsRefused) {
  const Arc beyond{{1e308, 0.0}, 1e308, 0.0, std::numbers::pi};
  try {
    (void)sweep_ball_arc({{0.0, 0.0}, 1.0}, {1.0, 0.0}, beyond);
    FAIL() << "accepted an arc whose circle reaches 2e308";
  } catch (const InvalidArgument& error) {
    EXPECT_EQ(error.argument(), "arc.radius");
    EXPECT_EQ(error.value(), "1e+308");
    EXPECT_NE(std::string(error.what()).find("double range"), std::string::npos) << error.what();
  }
  // Just inside the range it is accepted.
  EXPECT_NO_THROW((void)sweep_ball_arc({{0.0, 0.0}, 1.0}, {1.0, 0.0},
                                       {{8e307, 0.0}, 8e307, 0.0, std::numbers::pi}));
}

}  // namespace
}  // namespace carom
