// A ball against a wall that moves rigidly (src/core/rigid_sweep.hpp): closed-form cases, and
// random turning segments and arcs against a brute-force reference (the distance to the wall
// carried by its own formula, sampled densely along straight, falling and growing motions, the
// first closing bisected).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/arc_frame.hpp"
#include "core/rigid_sweep.hpp"
#include "random_cases.hpp"
#include "reference_distance.hpp"

namespace carom::detail {
namespace rigid_sweep_tests {

// The reference's own carrying of a point: rotation by the angle about the pivot, which moves.
Vec2 carry(Vec2 x, const RigidMotion& m, double t) {
  const double angle = m.angular_velocity * t;
  const Vec2 d = x - m.pivot;
  return m.pivot + m.velocity * t +
         Vec2{std::cos(angle) * d.x - std::sin(angle) * d.y,
              std::sin(angle) * d.x + std::cos(angle) * d.y};
}

Vec2 centre_at(const Ball& ball, const Motion& motion, double t) {
  return ball.center + motion.velocity * t + motion.acceleration * (0.5 * t * t);
}

double segment_gap(const Ball& ball, const Motion& motion, const Segment& s, const RigidMotion& m,
                   double t) {
  const Segment carried{carry(s.a, m, t), carry(s.b, m, t)};
  return testing::distance_to_segment(centre_at(ball, motion, t), carried) -
         (ball.radius + motion.growth * t);
}

double arc_gap(const Ball& ball, const Motion& motion, const Arc& arc, const RigidMotion& m,
               double t) {
  const double angle = m.angular_velocity * t;
  const Arc carried{carry(arc.center, m, t), arc.radius, arc.start_angle + angle,
                    arc.end_angle + angle};
  return testing::distance_to_arc(centre_at(ball, motion, t), carried) -
         (ball.radius + motion.growth * t);
}

TEST(RigidSweep, AFlipperTurningIntoABallAtRestMeetsItWhenItsEdgeReachesTheBall) {
  // A segment from the pivot (0, 0) to (2, 0) turning counter-clockwise at 1 rad per unit of
  // time; a ball of radius 0.5 at rest centred at (1, 1.5). The line reaches distance 0.5 from
  // the centre when the angle θ satisfies the distance from (1, 1.5) to the line at θ equals 0.5:
  // |−sin θ·1 + cos θ·1.5| = 0.5, i.e. sin(φ − θ)·√3.25 = 0.5 with tan φ = 1.5.
  const Ball ball{{1.0, 1.5}, 0.5};
  const RigidMotion turning{{}, 1.0, {0.0, 0.0}};
  const RigidContact contact =
      rigid_ball_segment(ball, Motion{{}, {}}, {{0.0, 0.0}, {2.0, 0.0}}, turning, 2.0);
  ASSERT_TRUE(contact.impact.hit);
  const double phi = std::atan2(1.5, 1.0);
  const double expected = phi - std::asin(0.5 / std::sqrt(3.25));
  EXPECT_NEAR(contact.impact.t, expected, 1e-12);
  // The normal points from the ball to the wall: along the segment's turned normal, downwards.
  const Vec2 normal{std::sin(expected), -std::cos(expected)};
  EXPECT_NEAR(contact.impact.normal.x, normal.x, 1e-9);
  EXPECT_NEAR(contact.impact.normal.y, normal.y, 1e-9);
}

TEST(RigidSweep, ATurningWallThatNeverReachesTheBallReportsNoContact) {
  // The ball sits beyond the segment's reach from the pivot.
  const Ball ball{{3.0, 0.0}, 0.5};
  const RigidMotion turning{{}, 5.0, {0.0, 0.0}};
  const RigidContact contact =
      rigid_ball_segment(ball, Motion{{}, {}}, {{0.0, 0.0}, {2.0, 0.0}}, turning, 100.0);
  EXPECT_FALSE(contact.impact.hit);
  EXPECT_EQ(contact.checked, 100.0);
}

TEST(RigidSweep, APointTurningAboutItselfIsAnEnvelopeOfNoSize) {
  // A zero-length segment at the pivot: its envelope has radius 0, which the search must take
  // (it once passed it to a query that refuses a radius of 0).
  const Ball ball{{3.0, 0.0}, 0.5};
  const RigidMotion turning{{1.0, 0.0}, 4.0, {0.0, 0.0}};
  const RigidContact contact =
      rigid_ball_segment(ball, Motion{{}, {}}, {{0.0, 0.0}, {0.0, 0.0}}, turning, 10.0);
  ASSERT_TRUE(contact.impact.hit);
  EXPECT_NEAR(contact.impact.t, 2.5, 1e-9);  // the point, moving at 1, reaches the ball's edge
}

TEST(RigidSweep, AWallThatOnlyTranslatesUsesTheRelativeClosedForm) {
  // A horizontal segment rising at 2 towards a ball falling from rest under gravity −1: the gap
  // 3 − 0.5 closes when 2t + t²/2 = 2.5, t = −2 + √9 = 1.
  const Ball ball{{0.0, 3.0}, 0.5};
  const RigidMotion rising{{0.0, 2.0}, 0.0, {0.0, 0.0}};
  const RigidContact contact =
      rigid_ball_segment(ball, Motion{{}, {0.0, -1.0}}, {{-1.0, 0.0}, {1.0, 0.0}}, rising, 5.0);
  ASSERT_TRUE(contact.impact.hit);
  EXPECT_NEAR(contact.impact.t, 1.0, 1e-14);
  EXPECT_NEAR(contact.impact.point.y, 2.0, 1e-14);
  EXPECT_NEAR(contact.impact.a_at.y, 2.5, 1e-14);
}

TEST(RigidSweep, CarryingWithoutTurningIsExact) {
  const RigidMotion sliding{{0.25, -0.5}, 0.0, {7.0, 3.0}};
  const Vec2 x{0.1, 0.3};
  EXPECT_EQ(carried_point(x, sliding, 2.0), (x + Vec2{0.5, -1.0}));
  EXPECT_EQ(carried_direction({0.6, 0.8}, sliding, 2.0), (Vec2{0.6, 0.8}));
}

// Compares one case with the reference; returns whether it hit.
template <typename Gap>
bool check_against_reference(const Gap& gap, const RigidContact& contact, double horizon,
                             double scale, const char* what, int k) {
  const auto reference = testing::first_contact(gap, horizon, 20000, 1e-13 * horizon);
  const double tolerance = 1e-9 * scale;
  if (contact.impact.hit) {
    // A contact found is a touch: the gap there is zero to its rounding, and no clear closing
    // the reference sees comes before it.
    EXPECT_NEAR(gap(contact.impact.t), 0.0, tolerance) << what << " case " << k;
    if (reference) {
      EXPECT_LE(contact.impact.t, reference->t + 1e-9 * horizon) << what << " case " << k;
    }
    return true;
  }
  // None found in [0, checked]: the reference finds no clear closing there.
  if (reference && reference->t < contact.checked) {
    EXPECT_GT(reference->deepest_gap, -tolerance)
        << what << " case " << k << ": missed a closing at " << reference->t;
  }
  return false;
}

TEST(RigidSweep, TurningSegmentsAgreeWithABruteForceReference) {
  testing::RandomCases random(0x5e9);
  int hits = 0;
  constexpr int kCases = 1500;
  for (int k = 0; k < kCases; ++k) {
    const Segment segment = random.segment(3.0);
    const RigidMotion rigid{random.point(1.0) * (k % 3 == 0 ? 1.0 : 0.0), random.uniform(-6.0, 6.0),
                            random.point(2.0)};
    Ball ball = random.ball(6.0);
    ball.radius = std::min(ball.radius, 1.0);
    const Motion motion{random.move_towards(ball.center, segment.a, 2.0),
                        k % 4 == 1 ? Vec2{0.0, -3.0} : Vec2{},
                        k % 4 == 2 ? random.uniform(0.0, 0.5) : 0.0};
    const auto gap = [&](double t) { return segment_gap(ball, motion, segment, rigid, t); };
    if (gap(0.0) <= 1e-9) continue;  // overlapping already
    const double horizon = 2.0;
    const RigidContact contact = rigid_ball_segment(ball, motion, segment, rigid, horizon);
    EXPECT_TRUE(contact.impact.hit || contact.checked == horizon) << "case " << k;
    hits += check_against_reference(gap, contact, horizon, 10.0, "segment", k) ? 1 : 0;
  }
  EXPECT_GT(hits, kCases / 4);
}

TEST(RigidSweep, TurningArcsAgreeWithABruteForceReference) {
  testing::RandomCases random(0xa2c);
  int hits = 0;
  constexpr int kCases = 1500;
  for (int k = 0; k < kCases; ++k) {
    Arc arc = random.arc(3.0);
    arc.radius = std::min(arc.radius, 3.0);
    const ArcFrame frame = make_arc_frame("test", arc);
    const RigidMotion rigid{random.point(1.0) * (k % 3 == 0 ? 1.0 : 0.0), random.uniform(-6.0, 6.0),
                            random.point(2.0)};
    Ball ball = random.ball(6.0);
    ball.radius = std::min(ball.radius, 1.0);
    const Motion motion{random.move_towards(ball.center, frame.start_point, 2.0),
                        k % 4 == 1 ? Vec2{0.0, -3.0} : Vec2{},
                        k % 4 == 2 ? random.uniform(0.0, 0.5) : 0.0};
    const auto gap = [&](double t) { return arc_gap(ball, motion, arc, rigid, t); };
    if (gap(0.0) <= 1e-9) continue;
    const double horizon = 2.0;
    const RigidContact contact = rigid_ball_arc(ball, motion, arc, frame, rigid, horizon);
    EXPECT_TRUE(contact.impact.hit || contact.checked == horizon) << "case " << k;
    hits += check_against_reference(gap, contact, horizon, 10.0, "arc", k) ? 1 : 0;
  }
  EXPECT_GT(hits, kCases / 4);
}

TEST(RigidSweep, AContactIsApproachingAndTheNormalPointsAtTheCarriedWall) {
  testing::RandomCases random(0x77);
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    const Segment segment = random.segment(3.0);
    const RigidMotion rigid{{}, random.uniform(-6.0, 6.0), random.point(2.0)};
    const Ball ball{random.point(6.0), 0.3};
    const Motion motion{random.move_towards(ball.center, segment.b, 1.0), {}};
    if (segment_gap(ball, motion, segment, rigid, 0.0) <= 1e-9) continue;
    const RigidContact contact = rigid_ball_segment(ball, motion, segment, rigid, 3.0);
    if (!contact.impact.hit) continue;
    const double t = contact.impact.t;
    // The gap falls through the contact (sampled either side, a little way off).
    const double h = 1e-6;
    if (t > h) {
      EXPECT_GT(segment_gap(ball, motion, segment, rigid, t - h),
                segment_gap(ball, motion, segment, rigid, t + h))
          << "case " << k;
    }
    const Segment carried = carried_segment(segment, rigid, t);
    EXPECT_NEAR(length(contact.impact.point - contact.impact.a_at), 0.3, 1e-9);
    EXPECT_NEAR(testing::distance_to_segment(contact.impact.point, carried), 0.0, 1e-9);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

}  // namespace rigid_sweep_tests
}  // namespace carom::detail
