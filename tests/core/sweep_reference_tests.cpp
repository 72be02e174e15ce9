// The library's closed-form time of impact against a brute-force reference: dense sampling of
// the gap along the motion, then bisection (reference_distance.hpp). The two share no code.
#include <gtest/gtest.h>

#include <cmath>

#include "carom/sweep.hpp"
#include "random_cases.hpp"
#include "reference_distance.hpp"

namespace carom {
namespace {

using testing::GapFunction;
using testing::RandomCases;

constexpr int kCases = 20'000;
constexpr int kSamples = 2'000;
constexpr double kBisectionTol = 1e-13;
// A "clear" reference hit goes at least this deep at a sample: a brief graze between two
// samples may be missed by the reference and is left to the property tests.
constexpr double kClearDepth = 1e-6;
// Agreement in t. The reference's bisection is good to 1e-13, but where the gap's slope at the
// contact is small (a shallow hit) both answers move with rounding of the gap, ~1e-15 / slope;
// a clear hit's slope is at least ~1e-4 here, so 1e-9 holds with a wide margin.
constexpr double kTimeTol = 1e-9;

struct Tally {
  int compared = 0;
  int library_only = 0;
};

// One case: `library` is the library's answer; gap(t) the reference surface distance.
void compare(const Impact& library, const GapFunction& gap, int index, Tally& tally) {
  const auto reference = testing::first_contact(gap, 1.0, kSamples, kBisectionTol);
  if (reference && reference->deepest_gap < -kClearDepth) {
    ASSERT_TRUE(library.hit) << "case " << index << ": reference hits at t = " << reference->t;
    ASSERT_NEAR(library.t, reference->t, kTimeTol) << "case " << index;
    ++tally.compared;
  } else if (library.hit) {
    // A contact the sampling did not see clearly: it must still be a real touch.
    ASSERT_NEAR(gap(library.t), 0.0, 1e-9) << "case " << index;
    ++tally.library_only;
  }
}

TEST(SweepReference, BallBall) {
  RandomCases random(11);
  Tally tally;
  for (int i = 0; i < kCases; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 move_a = random.move_towards(a.center, b.center, 4.0);
    const Vec2 move_b = random.point(6.0);
    const GapFunction gap = [&](double t) {
      return distance(a.center + move_a * t, b.center + move_b * t) - a.radius - b.radius;
    };
    if (gap(0.0) <= 0.0) continue;
    compare(sweep_ball_ball(a, move_a, b, move_b), gap, i, tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.compared, kCases / 8);
}

TEST(SweepReference, BallSegment) {
  RandomCases random(12);
  Tally tally;
  for (int i = 0; i < kCases; ++i) {
    const Segment segment = random.segment(8.0);
    const Ball ball = random.ball(10.0);
    const Vec2 move = random.move_towards(ball.center, random.point(6.0), 4.0);
    const GapFunction gap = [&](double t) {
      return testing::distance_to_segment(ball.center + move * t, segment) - ball.radius;
    };
    if (gap(0.0) <= 0.0) continue;
    compare(sweep_ball_segment(ball, move, segment), gap, i, tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.compared, kCases / 20);
}

TEST(SweepReference, BallArc) {
  RandomCases random(13);
  Tally tally;
  for (int i = 0; i < kCases; ++i) {
    const Arc arc = random.arc(6.0);
    const Ball ball = random.ball(10.0);
    const Vec2 move = random.move_towards(ball.center, random.point(6.0), 4.0);
    const GapFunction gap = [&](double t) {
      return testing::distance_to_arc(ball.center + move * t, arc) - ball.radius;
    };
    if (gap(0.0) <= 0.0) continue;
    compare(sweep_ball_arc(ball, move, arc), gap, i, tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.compared, kCases / 20);
}

TEST(SweepReference, BallInsideArcBowls) {
  // Balls starting inside the arc's circle exercise the inner face and the gap.
  RandomCases random(14);
  Tally tally;
  for (int i = 0; i < kCases; ++i) {
    Arc arc = random.arc(2.0);
    arc.radius = random.uniform(3.0, 8.0);
    const double ball_radius = random.uniform(0.1, 0.9) * arc.radius;
    const Ball ball{arc.center + random.point(arc.radius * 0.5), ball_radius};
    const Vec2 move = random.point(3.0 * arc.radius);
    const GapFunction gap = [&](double t) {
      return testing::distance_to_arc(ball.center + move * t, arc) - ball.radius;
    };
    if (gap(0.0) <= 0.0) continue;
    compare(sweep_ball_arc(ball, move, arc), gap, i, tally);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.compared, kCases / 20);
}

}  // namespace
}  // namespace carom
