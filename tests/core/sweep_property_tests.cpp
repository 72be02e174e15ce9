// Properties of the time of impact over 100 000 random cases each (fixed seeds, reproducible).
//
// Tolerances. Coordinates here are O(10) and radii O(0.05..3), so one rounding of a position is
// about 2e-15. kContactTol = 1e-9 (relative to the contact distance, as docs/guarantees.md
// promises) leaves a margin of 10⁵ over that for the handful of operations between inputs and
// a_at/b_at; the closed-form root has no cancellation, so it is met with room to spare even near
// grazes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "carom/sweep.hpp"
#include "random_cases.hpp"
#include "reference_distance.hpp"

namespace carom {
namespace {

using testing::RandomCases;

constexpr int kCases = 100'000;
constexpr double kContactTol = 1e-9;
// Earlier sampled times must be strictly apart, up to a few roundings of the distance.
constexpr double kApartTol = 1e-12;
constexpr int kEarlierSamples = 32;

struct BallPairCase {
  Ball a, b;
  Vec2 move_a, move_b;
};

BallPairCase random_pair(RandomCases& random) {
  BallPairCase c;
  c.a = random.ball(10.0);
  c.b = random.ball(10.0);
  c.move_a = random.move_towards(c.a.center, c.b.center, 4.0);
  c.move_b = random.point(6.0);
  return c;
}

double centre_distance(const BallPairCase& c, double t) {
  return distance(c.a.center + c.move_a * t, c.b.center + c.move_b * t);
}

TEST(SweepBallBallProperty, ReportedTimeIsTheFirstTouch) {
  RandomCases random(1);
  int hits = 0;
  for (int i = 0; i < kCases; ++i) {
    const BallPairCase c = random_pair(random);
    const Impact impact = sweep_ball_ball(c.a, c.move_a, c.b, c.move_b);
    if (!impact.hit || impact.overlapping) continue;
    ++hits;
    const double reach = c.a.radius + c.b.radius;
    ASSERT_GE(impact.t, 0.0);
    ASSERT_LE(impact.t, 1.0);
    ASSERT_NEAR(distance(impact.a_at, impact.b_at), reach, kContactTol * reach) << "case " << i;
    ASSERT_NEAR(length(impact.normal), 1.0, 1e-15);
    for (int k = 0; k < kEarlierSamples; ++k) {
      const double earlier = impact.t * k / kEarlierSamples;
      ASSERT_GT(centre_distance(c, earlier), reach * (1.0 - kApartTol)) << "case " << i;
    }
    // Approaching at contact: the relative velocity points into B.
    ASSERT_GT(dot(c.move_a - c.move_b, impact.normal), 0.0);
  }
  EXPECT_GT(hits, kCases / 8);  // the generator must exercise hits, not only misses
}

TEST(SweepBallBallProperty, NoHitMeansTheClosestApproachStaysApart) {
  RandomCases random(2);
  int misses = 0;
  for (int i = 0; i < kCases; ++i) {
    const BallPairCase c = random_pair(random);
    const Impact impact = sweep_ball_ball(c.a, c.move_a, c.b, c.move_b);
    if (impact.hit || impact.overlapping) continue;
    ++misses;
    // Closest approach of the relative motion within the step, in closed form.
    const Vec2 s = c.a.center - c.b.center;
    const Vec2 u = c.move_a - c.move_b;
    const double a = length_squared(u);
    const double closest_t = a > 0.0 ? std::clamp(-dot(s, u) / a, 0.0, 1.0) : 0.0;
    const double reach = c.a.radius + c.b.radius;
    ASSERT_GE(centre_distance(c, closest_t), reach * (1.0 - kContactTol)) << "case " << i;
  }
  EXPECT_GT(misses, kCases / 8);
}

TEST(SweepBallBallProperty, SwappingAAndBGivesTheSameTimeAndOppositeNormal) {
  RandomCases random(3);
  for (int i = 0; i < kCases; ++i) {
    const BallPairCase c = random_pair(random);
    const Impact ab = sweep_ball_ball(c.a, c.move_a, c.b, c.move_b);
    const Impact ba = sweep_ball_ball(c.b, c.move_b, c.a, c.move_a);
    ASSERT_EQ(ab.hit, ba.hit) << "case " << i;
    ASSERT_EQ(ab.overlapping, ba.overlapping);
    if (!ab.hit) continue;
    ASSERT_EQ(ab.t, ba.t);  // the same arithmetic on negated inputs: bit-identical
    ASSERT_EQ(ab.normal, -ba.normal);
    ASSERT_EQ(ab.a_at, ba.b_at);
    ASSERT_EQ(ab.b_at, ba.a_at);
    ASSERT_NEAR(ab.point.x, ba.point.x, 1e-12);
    ASSERT_NEAR(ab.point.y, ba.point.y, 1e-12);
  }
}

// Translating both balls or adding the same velocity to both changes the inputs' rounding, so
// t can move by the rounding of the relative quantities amplified by the root's conditioning:
// far from a graze that is ~1e-14. Near a graze (discriminant → 0) t is ill-conditioned and hit
// may even flip; such cases are recognised by their small discriminant and skipped.
bool near_graze(const BallPairCase& c) {
  const Vec2 s = c.a.center - c.b.center;
  const Vec2 u = c.move_a - c.move_b;
  const double reach = c.a.radius + c.b.radius;
  const double h = cross(s, u);
  const double discriminant = length_squared(u) * reach * reach - h * h;
  return std::abs(discriminant) < 1e-6 * length_squared(u) * reach * reach;
}

TEST(SweepBallBallProperty, TranslationAndCommonVelocityChangeOnlyPositions) {
  RandomCases random(4);
  constexpr double kShiftTol = 1e-9;
  int compared = 0;
  for (int i = 0; i < kCases; ++i) {
    const BallPairCase c = random_pair(random);
    if (near_graze(c)) continue;
    const Impact base = sweep_ball_ball(c.a, c.move_a, c.b, c.move_b);
    if (base.overlapping) continue;

    const Vec2 shift = random.point(50.0);
    const Impact moved = sweep_ball_ball({c.a.center + shift, c.a.radius}, c.move_a,
                                         {c.b.center + shift, c.b.radius}, c.move_b);
    const Vec2 drift = random.point(20.0);
    const Impact boosted = sweep_ball_ball(c.a, c.move_a + drift, c.b, c.move_b + drift);
    ASSERT_EQ(base.hit, moved.hit) << "case " << i;
    ASSERT_EQ(base.hit, boosted.hit) << "case " << i;
    if (!base.hit) continue;
    ++compared;
    ASSERT_NEAR(moved.t, base.t, kShiftTol) << "case " << i;
    ASSERT_NEAR(boosted.t, base.t, kShiftTol) << "case " << i;
    ASSERT_NEAR(moved.a_at.x, base.a_at.x + shift.x, kShiftTol * 100.0);
    ASSERT_NEAR(moved.a_at.y, base.a_at.y + shift.y, kShiftTol * 100.0);
    ASSERT_NEAR(moved.normal.x, base.normal.x, kShiftTol);
    ASSERT_NEAR(moved.normal.y, base.normal.y, kShiftTol);
    ASSERT_NEAR(boosted.normal.x, base.normal.x, kShiftTol);
    ASSERT_NEAR(boosted.normal.y, base.normal.y, kShiftTol);
  }
  EXPECT_GT(compared, kCases / 8);
}

// ---- static shapes: first touch and no false miss, checked with the independent distance ----

Vec2 anchor(const Segment& segment);
Vec2 anchor(const Arc& arc);
Vec2 anchor(Vec2 point);

struct StaticCase {
  Ball ball;
  Vec2 move;
};

template <typename Shape, typename Sweep, typename Distance>
void check_static_shape(std::uint64_t seed, Shape (*make)(RandomCases&), Sweep sweep,
                        Distance distance_to) {
  RandomCases random(seed);
  int hits = 0;
  int misses = 0;
  for (int i = 0; i < kCases; ++i) {
    const Shape shape = make(random);
    StaticCase c{random.ball(10.0), {}};
    c.move = random.move_towards(c.ball.center, anchor(shape), 3.0);
    const auto gap = [&](double t) {
      return distance_to(c.ball.center + c.move * t, shape) - c.ball.radius;
    };
    if (gap(0.0) <= 0.0) continue;  // starts in contact: covered by the edge tests
    const Impact impact = sweep(c.ball, c.move, shape);
    if (impact.hit) {
      ++hits;
      ASSERT_NEAR(gap(impact.t), 0.0, kContactTol * c.ball.radius) << "case " << i;
      ASSERT_NEAR(distance(impact.a_at, impact.point), c.ball.radius, kContactTol * c.ball.radius);
      for (int k = 0; k < kEarlierSamples; ++k) {
        ASSERT_GT(gap(impact.t * k / kEarlierSamples), -kApartTol * c.ball.radius) << "case " << i;
      }
      ASSERT_GE(dot(c.move, impact.normal), 0.0) << "case " << i;  // approaching
    } else {
      ++misses;
      // Sampled densely, the whole step stays apart (up to rounding).
      for (int k = 0; k <= 256; ++k) {
        ASSERT_GT(gap(k / 256.0), -kContactTol * c.ball.radius) << "case " << i << " k " << k;
      }
    }
  }
  EXPECT_GT(hits, kCases / 8);
  EXPECT_GT(misses, kCases / 8);
}

// A point on or near each shape for the random moves to aim at, so hits are common.
Vec2 anchor(const Segment& segment) { return (segment.a + segment.b) * 0.5; }
Vec2 anchor(const Arc& arc) {
  const double middle = 0.5 * (arc.start_angle + arc.end_angle);
  return arc.center + Vec2{std::cos(middle), std::sin(middle)} * arc.radius;
}
Vec2 anchor(Vec2 point) { return point; }

Segment make_segment(RandomCases& random) { return random.segment(8.0); }
Arc make_arc(RandomCases& random) { return random.arc(6.0); }
Vec2 make_point(RandomCases& random) { return random.point(8.0); }

TEST(SweepBallSegmentProperty, FirstTouchAndNoFalseMiss) {
  check_static_shape(5, make_segment, sweep_ball_segment, testing::distance_to_segment);
}

TEST(SweepBallArcProperty, FirstTouchAndNoFalseMiss) {
  check_static_shape(6, make_arc, sweep_ball_arc, testing::distance_to_arc);
}

TEST(SweepBallPointProperty, FirstTouchAndNoFalseMiss) {
  check_static_shape(7, make_point, sweep_ball_point,
                     [](Vec2 p, Vec2 point) { return distance(p, point); });
}

}  // namespace
}  // namespace carom
