// The library's closed-form time of impact against a brute-force reference: dense sampling of
// the gap along the motion, then bisection (reference_distance.hpp). The two share no code.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>

#include "carom/sweep.hpp"
#include "random_cases.hpp"
#include "reference_distance.hpp"

namespace carom {
namespace sweep_reference_tests {

using testing::GapFunction;
using testing::RandomCases;

constexpr int kReferenceCases = 20'000;
constexpr int kSamples = 2'000;
constexpr double kBisectionTol = 1e-13;
// A "clear" reference hit goes at least this deep at a sample: a brief graze between two
// samples may be missed by the reference and is left to the property tests.
constexpr double kClearDepth = 1e-6;
// Agreement in t. The reference's bisection is good to 1e-13, but where the gap's slope at the
// contact is small (a shallow hit) both answers move with rounding of the gap, ~1e-15 / slope;
// a clear hit's slope is at least ~1e-4 here, so 1e-9 holds with a wide margin.
constexpr double kTimeTol = 1e-9;

// One random case: the library's answer and the reference surface distance gap(t).
struct Case {
  Impact library;
  GapFunction gap;
};

// Compares the library with the reference on kReferenceCases random cases from `make` (cases that
// start in contact are left to the edge tests), and checks that at least min_compared were clear
// hits.
void compare_random_cases(std::uint64_t seed, int min_compared,
                          const std::function<Case(RandomCases&)>& make) {
  RandomCases random(seed);
  int compared = 0;
  for (int i = 0; i < kReferenceCases; ++i) {
    const Case c = make(random);
    if (c.gap(0.0) <= 0.0) continue;
    const auto reference = testing::first_contact(c.gap, 1.0, kSamples, kBisectionTol);
    if (reference && reference->deepest_gap < -kClearDepth) {
      ASSERT_TRUE(c.library.hit) << "case " << i << ": reference hits at t = " << reference->t;
      ASSERT_NEAR(c.library.t, reference->t, kTimeTol) << "case " << i;
      ++compared;
    } else if (c.library.hit) {
      // A contact the sampling did not see clearly: it must still be a real touch.
      ASSERT_NEAR(c.gap(c.library.t), 0.0, 1e-9) << "case " << i;
    }
  }
  EXPECT_GT(compared, min_compared);
}

TEST(SweepReference, BallBall) {
  compare_random_cases(11, kReferenceCases / 8, [](RandomCases& random) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 move_a = random.move_towards(a.center, b.center, 4.0);
    const Vec2 move_b = random.point(6.0);
    return Case{sweep_ball_ball(a, move_a, b, move_b), [=](double t) {
                  return distance(a.center + move_a * t, b.center + move_b * t) - a.radius -
                         b.radius;
                }};
  });
}

TEST(SweepReference, BallSegment) {
  compare_random_cases(12, kReferenceCases / 20, [](RandomCases& random) {
    const Segment segment = random.segment(8.0);
    const Ball ball = random.ball(10.0);
    const Vec2 move = random.move_towards(ball.center, random.point(6.0), 4.0);
    return Case{sweep_ball_segment(ball, move, segment), [=](double t) {
                  return testing::distance_to_segment(ball.center + move * t, segment) -
                         ball.radius;
                }};
  });
}

TEST(SweepReference, BallArc) {
  compare_random_cases(13, kReferenceCases / 20, [](RandomCases& random) {
    const Arc arc = random.arc(6.0);
    const Ball ball = random.ball(10.0);
    const Vec2 move = random.move_towards(ball.center, random.point(6.0), 4.0);
    return Case{sweep_ball_arc(ball, move, arc), [=](double t) {
                  return testing::distance_to_arc(ball.center + move * t, arc) - ball.radius;
                }};
  });
}

TEST(SweepReference, BallInsideArcBowls) {
  // Balls starting inside the arc's circle exercise the inner face and the gap.
  compare_random_cases(14, kReferenceCases / 20, [](RandomCases& random) {
    Arc arc = random.arc(2.0);
    arc.radius = random.uniform(3.0, 8.0);
    const double ball_radius = random.uniform(0.1, 0.9) * arc.radius;
    const Ball ball{arc.center + random.point(arc.radius * 0.5), ball_radius};
    const Vec2 move = random.point(3.0 * arc.radius);
    return Case{sweep_ball_arc(ball, move, arc), [=](double t) {
                  return testing::distance_to_arc(ball.center + move * t, arc) - ball.radius;
                }};
  });
}

}  // namespace sweep_reference_tests
}  // namespace carom
