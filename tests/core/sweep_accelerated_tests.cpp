// Time of impact under a constant acceleration (carom::Motion): closed-form cases (a drop onto a
// floor, a ball at rest on one), the rules at the start, near-tangent paths on either side of
// touching, scaling, and random cases of every shape against the brute-force reference
// (reference_distance.hpp: dense sampling of the distance, then bisection; no shared code).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "core/table_motion.hpp"
#include "long_tests.hpp"
#include "random_cases.hpp"
#include "reference_distance.hpp"

namespace carom {
namespace {

using testing::GapFunction;
using testing::RandomCases;

constexpr Vec2 kGravity{0.0, -9.81};

Vec2 at(Vec2 p, Vec2 v, Vec2 a, double t) { return p + v * t + a * (0.5 * t * t); }

bool same(const Impact& x, const Impact& y) {
  return x.hit == y.hit && x.overlapping == y.overlapping && x.t == y.t && x.a_at == y.a_at &&
         x.b_at == y.b_at && x.normal == y.normal && x.point == y.point;
}

TEST(SweepAccelerated, ZeroAccelerationIsTheStraightLineQuery) {
  RandomCases random(1);
  for (int i = 0; i < 2000; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 v = random.move_towards(a.center, b.center, 4.0);
    const Vec2 w = random.point(3.0);
    const Segment segment = random.segment(8.0);
    const Arc arc = random.arc(6.0);
    ASSERT_TRUE(same(time_of_impact_ball_ball(a, Motion{v, {}}, b, Motion{w, {}}, 1.0),
                     time_of_impact_ball_ball(a, v, b, w, 1.0)));
    ASSERT_TRUE(same(time_of_impact_ball_point(a, Motion{v, {}}, b.center, 1.0),
                     time_of_impact_ball_point(a, v, b.center, 1.0)));
    ASSERT_TRUE(same(time_of_impact_ball_segment(a, Motion{v, {}}, segment, 1.0),
                     time_of_impact_ball_segment(a, v, segment, 1.0)));
    ASSERT_TRUE(same(time_of_impact_ball_arc(a, Motion{v, {}}, arc, 1.0),
                     time_of_impact_ball_arc(a, v, arc, 1.0)));
  }
}

TEST(SweepAccelerated, DropOntoAFloor) {
  // From rest at height 10 (radius 0.5) onto y = 0: t = √(2·9.5 / 9.81).
  const Ball ball{{1.0, 10.0}, 0.5};
  const Impact impact =
      time_of_impact_ball_segment(ball, Motion{{}, kGravity}, {{-5.0, 0.0}, {5.0, 0.0}}, 10.0);
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, std::sqrt(2.0 * 9.5 / 9.81), 1e-14);
  EXPECT_NEAR(impact.a_at.y, 0.5, 1e-13);
  EXPECT_EQ(impact.normal, (Vec2{0.0, -1.0}));
  EXPECT_NEAR(impact.point.x, 1.0, 1e-15);
  EXPECT_NEAR(impact.point.y, 0.0, 1e-13);
  // Thrown up at 4 from the floor's contact: it lands after 2·4 / 9.81.
  const Ball on_floor{{0.0, 0.5}, 0.5};
  const Impact lands = time_of_impact_ball_segment(on_floor, Motion{{0.0, 4.0}, kGravity},
                                                   {{-5.0, 0.0}, {5.0, 0.0}}, 10.0);
  ASSERT_TRUE(lands.hit);
  EXPECT_NEAR(lands.t, 8.0 / 9.81, 1e-14);
  // The horizon cuts it off.
  EXPECT_FALSE(time_of_impact_ball_segment(on_floor, Motion{{0.0, 4.0}, kGravity},
                                           {{-5.0, 0.0}, {5.0, 0.0}}, 0.8)
                   .hit);
}

TEST(SweepAccelerated, AtRestOnASupportIsAContactNow) {
  const Segment floor{{-5.0, 0.0}, {5.0, 0.0}};
  const Ball resting{{0.0, 0.5}, 0.5};
  const Impact now = time_of_impact_ball_segment(resting, Motion{{}, kGravity}, floor, 1.0);
  ASSERT_TRUE(now.hit);
  EXPECT_EQ(now.t, 0.0);
  EXPECT_EQ(now.normal, (Vec2{0.0, -1.0}));
  // Sliding along it at any speed: still pressed into it.
  EXPECT_TRUE(time_of_impact_ball_segment(resting, Motion{{3.0, 0.0}, kGravity}, floor, 1.0).hit);
  // Hanging under a ceiling that gravity pulls it away from: no contact.
  const Ball under{{0.0, -0.5}, 0.5};
  EXPECT_FALSE(time_of_impact_ball_segment(under, Motion{{}, kGravity}, floor, 1.0).hit);
  // On top of a peg (a point) and on top of a ball.
  const Ball on_peg{{0.0, 1.0}, 1.0};
  const Impact peg = time_of_impact_ball_point(on_peg, Motion{{}, kGravity}, {0.0, 0.0}, 1.0);
  ASSERT_TRUE(peg.hit);
  EXPECT_EQ(peg.t, 0.0);
  const Impact stacked = time_of_impact_ball_ball(on_peg, Motion{{}, kGravity}, {{0.0, -1.0}, 1.0},
                                                  Motion{{}, {}}, 1.0);
  ASSERT_TRUE(stacked.hit);
  EXPECT_EQ(stacked.t, 0.0);
  EXPECT_EQ(stacked.normal, (Vec2{0.0, -1.0}));
  // Two balls falling together, touching: their relative motion is none.
  EXPECT_FALSE(time_of_impact_ball_ball(on_peg, Motion{{}, kGravity}, {{0.0, -1.0}, 1.0},
                                        Motion{{}, kGravity}, 1.0)
                   .hit);
  // At rest at the bottom of a bowl (the lower half of a circle of radius 3).
  const Arc bowl{{0.0, 0.0}, 3.0, std::numbers::pi, 2.0 * std::numbers::pi};
  const Ball in_bowl{{0.0, -2.0}, 1.0};
  const Impact bottom = time_of_impact_ball_arc(in_bowl, Motion{{}, kGravity}, bowl, 1.0);
  ASSERT_TRUE(bottom.hit);
  EXPECT_EQ(bottom.t, 0.0);
  EXPECT_NEAR(bottom.normal.y, -1.0, 1e-15);
}

TEST(SweepAccelerated, PressingIntoAnArcFromAPlacementsRoundingHitsAtOnce) {
  // A ball placed against an arc ends up overlapping its circle by a rounding, from inside (in
  // the bowl) or from outside. Pressing on, it meets the arc at once, as the straight-line sweep
  // says, and falling does not change that.
  const Arc arc{{0.0, 0.0}, 3.0, -0.5 * std::numbers::pi, std::numbers::pi};
  const double angle = std::numbers::pi / 4.0;
  const Vec2 out{std::cos(angle), std::sin(angle)};
  for (const double side : {-1.0, 1.0}) {
    const double distance = 3.0 + side * (1.0 - 1e-14);  // 1e-14 into the wall
    const Ball ball{out * distance, 1.0};
    const Vec2 pressing = out * (-side * 2.0);
    for (const Vec2 gravity : {Vec2{}, kGravity}) {
      const Impact impact = time_of_impact_ball_arc(ball, Motion{pressing, gravity}, arc, 1.0);
      ASSERT_TRUE(impact.hit) << side << " " << gravity.y;
      EXPECT_EQ(impact.t, 0.0) << side << " " << gravity.y;
      EXPECT_NEAR(dot(impact.normal, out), -side, 1e-12) << side;
    }
    // Leaving, it does not meet it at once (falling, it may meet it later).
    const Impact leaving = time_of_impact_ball_arc(ball, Motion{-pressing, kGravity}, arc, 1e-3);
    EXPECT_FALSE(leaving.hit) << side;
  }
}

TEST(SweepAccelerated, ThrownPastAnEndFallsOntoTheSegment) {
  // The ball starts below the line of a segment that begins at x = 0, rises beside it and
  // comes down on top of it: the far side of the line, reached round the end.
  const Segment shelf{{0.0, 0.0}, {10.0, 0.0}};
  const Ball ball{{-2.0, -3.0}, 0.5};
  const Motion motion{{2.5, 12.0}, kGravity};
  const Impact impact = time_of_impact_ball_segment(ball, motion, shelf, 10.0);
  ASSERT_TRUE(impact.hit);
  // Landing: y(t) = 0.5 on the way down, −3 + 12t − 4.905t² = 0.5.
  const double landing = (12.0 + std::sqrt(144.0 - 4.0 * 4.905 * 3.5)) / (2.0 * 4.905);
  EXPECT_NEAR(impact.t, landing, 1e-13);
  EXPECT_GT(impact.a_at.x, 0.0);
  EXPECT_EQ(impact.normal, (Vec2{0.0, -1.0}));
}

TEST(SweepAccelerated, ParabolaMeetsACircleTwiceAndTheSpanChooses) {
  // A ball thrown through a ring: its path enters the ring's circle twice; an arc covering only
  // the second entry is met there.
  const Ball ball{{-6.0, 0.0}, 0.25};
  const Motion motion{{3.0, 6.0}, kGravity};
  const double horizon = 3.0;
  const auto reference = [&](const Arc& arc) {
    return testing::first_contact(
        [&](double t) {
          return testing::distance_to_arc(at(ball.center, motion.velocity, motion.acceleration, t),
                                          arc) -
                 ball.radius;
        },
        horizon, 200'000, 1e-13);
  };
  for (const Arc arc : {Arc{{0.0, 0.0}, 2.0, 0.0, 2.0 * std::numbers::pi},
                        Arc{{0.0, 0.0}, 2.0, -1.0, 0.5}, Arc{{0.0, 0.0}, 2.0, 2.0, 3.0}}) {
    const auto expected = reference(arc);
    const Impact impact = time_of_impact_ball_arc(ball, motion, arc, horizon);
    ASSERT_EQ(impact.hit, expected.has_value()) << arc.start_angle;
    if (expected) {
      EXPECT_NEAR(impact.t, expected->t, 1e-9) << arc.start_angle;
    }
  }
}

// A path's closest approach to a point, then that point moved off by δ in the direction of the
// approach: a contact when δ is an overlap beyond the rounding, none when it is a clearance.
TEST(SweepAccelerated, NearTangentPathsOnEitherSideOfTouching) {
  RandomCases random(7);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ball ball{random.point(5.0), random.log_uniform(0.1, 2.0)};
    const Vec2 v = random.point(4.0);
    const Vec2 a = random.point(10.0);
    // The closest approach to a random point, by golden section on a bracketing sample.
    const Vec2 target = random.point(6.0);
    const auto distance_at = [&](double t) { return distance(at(ball.center, v, a, t), target); };
    double best_t = 0.0;
    for (int k = 0; k <= 400; ++k) {
      const double t = 0.5 + k * (1.0 / 400.0);
      if (distance_at(t) < distance_at(best_t)) best_t = t;
    }
    if (best_t <= 0.5 || best_t >= 1.5) continue;  // the closest approach is not inside
    double lo = best_t - 1.0 / 400.0;
    double hi = best_t + 1.0 / 400.0;
    for (int k = 0; k < 200; ++k) {
      const double m1 = lo + (hi - lo) * 0.382;
      const double m2 = lo + (hi - lo) * 0.618;
      (distance_at(m1) < distance_at(m2) ? hi : lo) = distance_at(m1) < distance_at(m2) ? m2 : m1;
    }
    const double closest = distance_at(0.5 * (lo + hi));
    if (closest < ball.radius + 0.5) continue;  // keep the point clear of the ball's start
    for (const double delta : {1e-3, 1e-6, 1e-9}) {
      // A point at the closest distance − radius ± δ from the path: as a ball of that radius.
      const double touching = closest - ball.radius;
      const Ball overlapped{target, touching + delta};
      const Ball clear{target, touching - delta};
      const Impact hit =
          time_of_impact_ball_ball(ball, Motion{v, a}, overlapped, Motion{{}, {}}, 2.0);
      const Impact miss = time_of_impact_ball_ball(ball, Motion{v, a}, clear, Motion{{}, {}}, 2.0);
      ASSERT_TRUE(hit.hit) << "case " << i << " delta " << delta;
      ASSERT_FALSE(miss.hit) << "case " << i << " delta " << delta;
      ASSERT_LE(hit.t, 0.5 * (lo + hi) + 1e-9) << "case " << i;
      ++hits;
    }
  }
  EXPECT_GT(hits, 1000);
}

TEST(SweepAccelerated, BallBallIsSymmetric) {
  RandomCases random(3);
  for (int i = 0; i < 5000; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Motion ma{random.move_towards(a.center, b.center, 4.0), random.point(10.0)};
    const Motion mb{random.point(3.0), random.point(10.0)};
    const Impact ab = time_of_impact_ball_ball(a, ma, b, mb, 1.0);
    const Impact ba = time_of_impact_ball_ball(b, mb, a, ma, 1.0);
    ASSERT_EQ(ab.hit, ba.hit) << i;
    ASSERT_EQ(ab.t, ba.t) << i;
    if (ab.hit) {
      ASSERT_NEAR(ab.normal.x, -ba.normal.x, 1e-12);
      ASSERT_NEAR(ab.normal.y, -ba.normal.y, 1e-12);
    }
  }
}

TEST(SweepAccelerated, ScalingByPowersOfTwoChangesNothing) {
  // Lengths by 2^k and times by 2^j: the contact time scales by 2^j, exactly.
  RandomCases random(5);
  for (int i = 0; i < 500; ++i) {
    const Ball ball = random.ball(10.0);
    const Vec2 point = random.point(6.0);
    const Motion motion{random.move_towards(ball.center, point, 4.0), random.point(10.0)};
    const Impact base = time_of_impact_ball_point(ball, motion, point, 1.0);
    for (const int k : {-400, -40, 40, 400}) {
      for (const int j : {-200, 30}) {
        const auto length = [&](double x) { return std::ldexp(x, k); };
        const auto vector = [&](Vec2 x, int e) {
          return Vec2{std::ldexp(x.x, e), std::ldexp(x.y, e)};
        };
        const Ball scaled_ball{vector(ball.center, k), length(ball.radius)};
        const Motion scaled_motion{vector(motion.velocity, k - j),
                                   vector(motion.acceleration, k - 2 * j)};
        const Impact scaled = time_of_impact_ball_point(scaled_ball, scaled_motion,
                                                        vector(point, k), std::ldexp(1.0, j));
        ASSERT_EQ(scaled.hit, base.hit) << i << " " << k << " " << j;
        ASSERT_EQ(scaled.t, std::ldexp(base.t, j)) << i << " " << k << " " << j;
      }
    }
  }
}

TEST(SweepAccelerated, RefusesBadArguments) {
  const Ball ball{{0.0, 0.0}, 1.0};
  const double nan = std::nan("");
  try {
    (void)time_of_impact_ball_point(ball, Motion{{}, {0.0, nan}}, {3.0, 0.0}, 1.0);
    FAIL() << "a NaN acceleration was accepted";
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("motion_a.acceleration"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW((void)time_of_impact_ball_ball(ball, Motion{{}, {}}, {{3.0, 0.0}, 1.0},
                                              Motion{{}, {HUGE_VAL, 0.0}}, 1.0),
               InvalidArgument);
  EXPECT_THROW(
      (void)time_of_impact_ball_segment(ball, Motion{{}, kGravity}, {{}, {1.0, 0.0}}, -1.0),
      InvalidArgument);
  EXPECT_THROW((void)time_of_impact_ball_arc(ball, Motion{{}, kGravity}, {{}, 2.0, 0.0, 7.0}, 1.0),
               InvalidArgument);
}

// ---- against the brute-force reference ------------------------------------------------------

constexpr int kSamples = 2'000;
constexpr double kBisectionTol = 1e-13;
constexpr double kClearDepth = 1e-6;
constexpr double kTimeTol = 1e-9;

struct Case {
  Impact library;
  GapFunction gap;
};

// `cases` random cases from `make` over t in [0, 1] (cases that start in contact are left to the
// tests above): every clear reference hit is found, at the reference's time; every other hit
// the library reports is a real touch.
void compare_random_cases(std::uint64_t seed, int cases,
                          const std::function<Case(RandomCases&)>& make) {
  RandomCases random(seed);
  int compared = 0;
  for (int i = 0; i < cases; ++i) {
    const Case c = make(random);
    if (c.gap(0.0) <= 0.0) continue;
    const auto reference = testing::first_contact(c.gap, 1.0, kSamples, kBisectionTol);
    if (reference && reference->deepest_gap < -kClearDepth) {
      ASSERT_TRUE(c.library.hit) << "case " << i << ": reference hits at t = " << reference->t;
      ASSERT_NEAR(c.library.t, reference->t, kTimeTol) << "case " << i;
      ++compared;
    } else if (c.library.hit) {
      ASSERT_NEAR(c.gap(c.library.t), 0.0, 1e-9) << "case " << i;
    }
  }
  EXPECT_GT(compared, cases / 20);
}

int reference_cases() { return testing::long_tests_enabled() ? 100'000 : 10'000; }

Vec2 random_acceleration(RandomCases& random) { return random.point(20.0); }

TEST(SweepAcceleratedReference, BallBall) {
  compare_random_cases(21, reference_cases(), [](RandomCases& random) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Motion ma{random.move_towards(a.center, b.center, 4.0), random_acceleration(random)};
    const Motion mb{random.point(6.0), random_acceleration(random)};
    return Case{time_of_impact_ball_ball(a, ma, b, mb, 1.0), [=](double t) {
                  return distance(at(a.center, ma.velocity, ma.acceleration, t),
                                  at(b.center, mb.velocity, mb.acceleration, t)) -
                         a.radius - b.radius;
                }};
  });
}

// Two pool balls on a cloth, each in the state its velocity and spin put it in (sliding with any
// spin, or rolling), each on its own parabola until the first of the two states ends: the gaps a
// table world asks about, at a table's sizes (57 mm balls, accelerations of μ·g).
TEST(SweepAcceleratedReference, PoolBallsInTheirTableStates) {
  const detail::Cloth cloth{9.81, 0.2, 0.01, 0.044};
  constexpr double kPoolRadius = 0.028575;
  const auto table_ball = [&](RandomCases& random, Vec2 velocity) {
    const bool rolling = random.uniform(0.0, 1.0) < 0.3;
    const Vec2 spin =
        rolling ? Vec2{-velocity.y, velocity.x} * (1.0 / kPoolRadius) : random.point(150.0);
    return detail::TableBall{velocity, spin, random.uniform(-50.0, 50.0), kPoolRadius};
  };
  compare_random_cases(29, reference_cases(), [&](RandomCases& random) {
    const Ball a{random.point(0.4), kPoolRadius};
    const Ball b{random.point(0.4), kPoolRadius};
    const detail::TableBall ta = table_ball(random, random.move_towards(a.center, b.center, 3.0));
    const detail::TableBall tb = table_ball(random, random.point(1.0));
    const detail::StateMotion sa = detail::state_motion(ta, cloth);
    const detail::StateMotion sb = detail::state_motion(tb, cloth);
    const Motion ma{ta.velocity, sa.acceleration};
    const Motion mb{tb.velocity, sb.acceleration};
    const double horizon = std::min({1.0, sa.duration, sb.duration});
    return Case{time_of_impact_ball_ball(a, ma, b, mb, horizon), [=](double t) {
                  if (t > horizon) return 1.0;  // (past the states' ends: not this query's)
                  return distance(at(a.center, ma.velocity, ma.acceleration, t),
                                  at(b.center, mb.velocity, mb.acceleration, t)) -
                         a.radius - b.radius;
                }};
  });
}

TEST(SweepAcceleratedReference, BallPoint) {
  compare_random_cases(22, reference_cases(), [](RandomCases& random) {
    const Ball ball = random.ball(10.0);
    const Vec2 point = random.point(6.0);
    const Motion m{random.move_towards(ball.center, point, 4.0), random_acceleration(random)};
    return Case{time_of_impact_ball_point(ball, m, point, 1.0), [=](double t) {
                  return distance(at(ball.center, m.velocity, m.acceleration, t), point) -
                         ball.radius;
                }};
  });
}

TEST(SweepAcceleratedReference, BallSegment) {
  compare_random_cases(23, reference_cases(), [](RandomCases& random) {
    const Segment segment = random.segment(8.0);
    const Ball ball = random.ball(10.0);
    const Motion m{random.move_towards(ball.center, random.point(6.0), 4.0),
                   random_acceleration(random)};
    return Case{time_of_impact_ball_segment(ball, m, segment, 1.0), [=](double t) {
                  return testing::distance_to_segment(
                             at(ball.center, m.velocity, m.acceleration, t), segment) -
                         ball.radius;
                }};
  });
}

TEST(SweepAcceleratedReference, BallArc) {
  compare_random_cases(24, reference_cases(), [](RandomCases& random) {
    const Arc arc = random.arc(6.0);
    const Ball ball = random.ball(10.0);
    const Motion m{random.move_towards(ball.center, random.point(6.0), 4.0),
                   random_acceleration(random)};
    return Case{time_of_impact_ball_arc(ball, m, arc, 1.0), [=](double t) {
                  return testing::distance_to_arc(at(ball.center, m.velocity, m.acceleration, t),
                                                  arc) -
                         ball.radius;
                }};
  });
}

TEST(SweepAcceleratedReference, BallInsideArcBowls) {
  compare_random_cases(25, reference_cases(), [](RandomCases& random) {
    Arc arc = random.arc(2.0);
    arc.radius = random.uniform(3.0, 8.0);
    const double ball_radius = random.uniform(0.1, 0.9) * arc.radius;
    const Ball ball{arc.center + random.point(arc.radius * 0.5), ball_radius};
    const Motion m{random.point(3.0 * arc.radius), random.point(6.0 * arc.radius)};
    return Case{time_of_impact_ball_arc(ball, m, arc, 1.0), [=](double t) {
                  return testing::distance_to_arc(at(ball.center, m.velocity, m.acceleration, t),
                                                  arc) -
                         ball.radius;
                }};
  });
}

// ---- growing balls ----------------------------------------------------------------------------

TEST(SweepGrowth, BallsAtRestMeetWhenTheirRadiiFillTheGap) {
  // Centres 10 apart, radii 1 and 2 growing at 0.5 and 1.5: the gap of 7 closes at 7/2.
  const Impact two = time_of_impact_ball_ball({{0.0, 0.0}, 1.0}, Motion{{}, {}, 0.5},
                                              {{10.0, 0.0}, 2.0}, Motion{{}, {}, 1.5}, 10.0);
  ASSERT_TRUE(two.hit);
  EXPECT_DOUBLE_EQ(two.t, 3.5);
  EXPECT_EQ(two.normal, (Vec2{1.0, 0.0}));
  // The contact point divides the centres' line by the radii at the contact (2.75 and 7.25).
  EXPECT_DOUBLE_EQ(two.point.x, 2.75);
  // Against a segment's line and a point, only the ball grows.
  const Impact wall = time_of_impact_ball_segment({{0.0, 3.0}, 1.0}, Motion{{}, {}, 0.25},
                                                  {{-5.0, 0.0}, {5.0, 0.0}}, 10.0);
  ASSERT_TRUE(wall.hit);
  EXPECT_DOUBLE_EQ(wall.t, 8.0);
  EXPECT_EQ(wall.normal, (Vec2{0.0, -1.0}));
  const Impact point =
      time_of_impact_ball_point({{0.0, 3.0}, 1.0}, Motion{{}, {}, 0.25}, {0.0, 0.0}, 10.0);
  ASSERT_TRUE(point.hit);
  EXPECT_DOUBLE_EQ(point.t, 8.0);
}

TEST(SweepGrowth, GrowthOutrunsARetreatAndATouchGrowingIsAContactNow) {
  // Moving away at 1 while the sum of radii grows at 3: the gap of 2 closes at 1.
  const Impact away = time_of_impact_ball_ball({{0.0, 0.0}, 1.0}, Motion{{-1.0, 0.0}, {}, 1.5},
                                               {{4.0, 0.0}, 1.0}, Motion{{}, {}, 1.5}, 10.0);
  ASSERT_TRUE(away.hit);
  EXPECT_DOUBLE_EQ(away.t, 1.0);
  // Touching and parting slower than the growth: in contact now.
  const Impact touching = time_of_impact_ball_ball({{0.0, 0.0}, 1.0}, Motion{{-0.5, 0.0}, {}, 1.0},
                                                   {{2.0, 0.0}, 1.0}, Motion{{}, {}, 0.0}, 1.0);
  ASSERT_TRUE(touching.hit);
  EXPECT_EQ(touching.t, 0.0);
  // Parting faster than the growth: no contact.
  EXPECT_FALSE(time_of_impact_ball_ball({{0.0, 0.0}, 1.0}, Motion{{-2.0, 0.0}, {}, 1.0},
                                        {{2.0, 0.0}, 1.0}, Motion{{}, {}, 0.0}, 1.0)
                   .hit);
  // A growing ball in a bowl meets the wall however it moves.
  const Impact bowl = time_of_impact_ball_arc({{0.0, 0.0}, 1.0}, Motion{{}, {}, 1.0},
                                              {{0.0, 0.0}, 5.0, 0.0, 6.0}, 10.0);
  ASSERT_TRUE(bowl.hit);
  EXPECT_NEAR(bowl.t, 4.0, 1e-12);
}

TEST(SweepGrowth, ZeroGrowthIsTheStraightLineQueryAndShrinkingIsRefused) {
  const Ball a{{0.0, 0.0}, 1.0};
  const Ball b{{5.0, 1.0}, 1.5};
  EXPECT_TRUE(same(time_of_impact_ball_ball(a, Motion{{2.0, 0.5}, {}, 0.0}, b,
                                            Motion{{-1.0, 0.0}, {}, 0.0}, 3.0),
                   time_of_impact_ball_ball(a, Vec2{2.0, 0.5}, b, Vec2{-1.0, 0.0}, 3.0)));
  EXPECT_THROW((void)time_of_impact_ball_point(a, Motion{{}, {}, -1.0}, {3.0, 0.0}, 1.0),
               InvalidArgument);
  EXPECT_THROW(
      (void)time_of_impact_ball_ball(a, Motion{{}, {}, 0.0}, b, Motion{{}, {}, std::nan("")}, 1.0),
      InvalidArgument);
}

double random_growth(RandomCases& random) { return random.uniform(0.0, 3.0); }

TEST(SweepGrowthReference, BallBall) {
  compare_random_cases(31, reference_cases(), [](RandomCases& random) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Motion ma{random.move_towards(a.center, b.center, 4.0), random_acceleration(random),
                    random_growth(random)};
    const Motion mb{random.point(6.0), random.uniform(0.0, 1.0) < 0.5 ? ma.acceleration : Vec2{},
                    random_growth(random)};
    return Case{time_of_impact_ball_ball(a, ma, b, mb, 1.0), [=](double t) {
                  return distance(at(a.center, ma.velocity, ma.acceleration, t),
                                  at(b.center, mb.velocity, mb.acceleration, t)) -
                         (a.radius + ma.growth * t) - (b.radius + mb.growth * t);
                }};
  });
}

TEST(SweepGrowthReference, BallPoint) {
  compare_random_cases(32, reference_cases(), [](RandomCases& random) {
    const Ball ball = random.ball(10.0);
    const Vec2 point = random.point(6.0);
    const Motion m{random.move_towards(ball.center, point, 4.0), Vec2{}, random_growth(random)};
    return Case{time_of_impact_ball_point(ball, m, point, 1.0), [=](double t) {
                  return distance(at(ball.center, m.velocity, m.acceleration, t), point) -
                         (ball.radius + m.growth * t);
                }};
  });
}

TEST(SweepGrowthReference, BallSegment) {
  compare_random_cases(33, reference_cases(), [](RandomCases& random) {
    const Segment segment = random.segment(8.0);
    const Ball ball = random.ball(10.0);
    const Motion m{random.move_towards(ball.center, random.point(6.0), 4.0), Vec2{},
                   random_growth(random)};
    return Case{time_of_impact_ball_segment(ball, m, segment, 1.0), [=](double t) {
                  return testing::distance_to_segment(
                             at(ball.center, m.velocity, m.acceleration, t), segment) -
                         (ball.radius + m.growth * t);
                }};
  });
}

TEST(SweepGrowthReference, BallArc) {
  compare_random_cases(34, reference_cases(), [](RandomCases& random) {
    const Arc arc = random.arc(6.0);
    const Ball ball = random.ball(10.0);
    const Motion m{random.move_towards(ball.center, random.point(6.0), 4.0), Vec2{},
                   random_growth(random)};
    return Case{time_of_impact_ball_arc(ball, m, arc, 1.0), [=](double t) {
                  return testing::distance_to_arc(at(ball.center, m.velocity, m.acceleration, t),
                                                  arc) -
                         (ball.radius + m.growth * t);
                }};
  });
}

TEST(SweepGrowthReference, BallInsideArcBowls) {
  compare_random_cases(35, reference_cases(), [](RandomCases& random) {
    Arc arc = random.arc(2.0);
    arc.radius = random.uniform(3.0, 8.0);
    const double ball_radius = random.uniform(0.1, 0.6) * arc.radius;
    const Ball ball{arc.center + random.point(arc.radius * 0.3), ball_radius};
    const Motion m{random.point(3.0 * arc.radius), Vec2{}, random.uniform(0.0, 0.3) * arc.radius};
    return Case{time_of_impact_ball_arc(ball, m, arc, 1.0), [=](double t) {
                  return testing::distance_to_arc(at(ball.center, m.velocity, m.acceleration, t),
                                                  arc) -
                         (ball.radius + m.growth * t);
                }};
  });
}

}  // namespace
}  // namespace carom
