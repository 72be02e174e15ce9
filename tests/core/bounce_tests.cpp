#include <gtest/gtest.h>

#include <cmath>

#include "carom/bounce.hpp"
#include "carom/error.hpp"
#include "random_cases.hpp"

namespace carom {
namespace {

using testing::RandomCases;

TEST(Bounce, EqualMassHeadOnExchangesVelocities) {
  const BounceResult r = bounce({3.0, 0.0}, 2.0, {-1.0, 0.0}, 2.0, {1.0, 0.0});
  EXPECT_EQ(r.velocity_a, (Vec2{-1.0, 0.0}));
  EXPECT_EQ(r.velocity_b, (Vec2{3.0, 0.0}));
  EXPECT_EQ(r.impulse, 8.0);  // mass 2, velocity change 4
}

TEST(Bounce, KeepsTheTangentialParts) {
  const BounceResult r = bounce({3.0, 5.0}, 1.0, {-1.0, -2.0}, 1.0, {1.0, 0.0});
  EXPECT_EQ(r.velocity_a, (Vec2{-1.0, 5.0}));
  EXPECT_EQ(r.velocity_b, (Vec2{3.0, -2.0}));
}

TEST(Bounce, NormalNeedNotBeUnit) {
  const BounceResult r = bounce({3.0, 0.0}, 1.0, {-1.0, 0.0}, 1.0, {10.0, 0.0});
  EXPECT_EQ(r.velocity_a, (Vec2{-1.0, 0.0}));
}

TEST(Bounce, SeparatingPairIsUntouched) {
  const BounceResult r = bounce({-3.0, 1.0}, 1.0, {1.0, 0.0}, 1.0, {1.0, 0.0});
  EXPECT_EQ(r.velocity_a, (Vec2{-3.0, 1.0}));
  EXPECT_EQ(r.velocity_b, (Vec2{1.0, 0.0}));
  EXPECT_EQ(r.impulse, 0.0);
}

TEST(Bounce, PerfectlyInelasticMovesTogetherAlongTheNormal) {
  const BounceResult r = bounce({4.0, 1.0}, 1.0, {0.0, 0.0}, 3.0, {1.0, 0.0}, 0.0);
  EXPECT_DOUBLE_EQ(r.velocity_a.x, 1.0);  // momentum 4 over mass 4
  EXPECT_DOUBLE_EQ(r.velocity_b.x, 1.0);
  EXPECT_EQ(r.velocity_a.y, 1.0);
}

TEST(Bounce, HeavyAndLightOneDimensional) {
  // m1 = 3, m2 = 1, u1 = 2, u2 = 0, e = 1: v1 = (m1 − m2)/(m1 + m2)·u1 = 1, v2 = 2m1/(m1 + m2)·u1
  // = 3.
  const BounceResult r = bounce({2.0, 0.0}, 3.0, {0.0, 0.0}, 1.0, {1.0, 0.0});
  EXPECT_DOUBLE_EQ(r.velocity_a.x, 1.0);
  EXPECT_DOUBLE_EQ(r.velocity_b.x, 3.0);
}

TEST(Bounce, ImmovableBallReflects) {
  const BounceResult r = bounce({2.0, 1.0}, 1.0, {0.0, 0.0}, kImmovable, {1.0, 0.0}, 0.5);
  EXPECT_EQ(r.velocity_a, (Vec2{-1.0, 1.0}));
  EXPECT_EQ(r.velocity_b, (Vec2{0.0, 0.0}));
  EXPECT_EQ(r.impulse, 3.0);
  // And from the other side: an immovable A pushes B.
  const BounceResult pushed = bounce({1.0, 0.0}, kImmovable, {-2.0, 0.0}, 2.0, {1.0, 0.0});
  EXPECT_EQ(pushed.velocity_a, (Vec2{1.0, 0.0}));
  EXPECT_EQ(pushed.velocity_b, (Vec2{4.0, 0.0}));
}

TEST(BounceOffStatic, ReflectsWithRestitution) {
  const WallBounceResult r = bounce_off_static({3.0, -4.0}, 2.0, {0.0, -1.0}, 0.5);
  EXPECT_EQ(r.velocity, (Vec2{3.0, 2.0}));
  EXPECT_EQ(r.impulse, 12.0);
  const WallBounceResult leaving = bounce_off_static({3.0, 4.0}, 2.0, {0.0, -1.0});
  EXPECT_EQ(leaving.velocity, (Vec2{3.0, 4.0}));
  EXPECT_EQ(leaving.impulse, 0.0);
}

TEST(BounceEqualMass, IsTheTutorialExchange) {
  const BounceResult r = bounce_equal_mass({1.0, 2.0}, {-3.0, 4.0}, {0.0, 5.0});
  EXPECT_EQ(r.velocity_a, (Vec2{1.0, 4.0}));
  EXPECT_EQ(r.velocity_b, (Vec2{-3.0, 2.0}));
  EXPECT_EQ(r.impulse, -2.0);  // separating along the line: the exchange still happens
}

// ---- properties over random cases -----------------------------------------------------------
// Tolerances: velocities O(10) and masses O(0.1..10) give momenta O(100) and energies O(1e3);
// each output is a handful of roundings away, so 1e-12 relative covers it with margin.

constexpr int kBounceCases = 100'000;
constexpr double kRelTol = 1e-12;

struct BouncePair {
  Vec2 va, vb, normal;
  double ma, mb, e;
};

BouncePair random_bounce_pair(RandomCases& random) {
  return {random.point(10.0),
          random.point(10.0),
          random.point(1.0),
          random.log_uniform(0.1, 10.0),
          random.log_uniform(0.1, 10.0),
          random.uniform(0.0, 1.0)};
}

double kinetic(Vec2 v, double m) { return 0.5 * m * length_squared(v); }

TEST(BounceProperty, ConservesMomentum) {
  RandomCases random(21);
  for (int i = 0; i < kBounceCases; ++i) {
    const BouncePair p = random_bounce_pair(random);
    const BounceResult r = bounce(p.va, p.ma, p.vb, p.mb, p.normal, p.e);
    const Vec2 before = p.va * p.ma + p.vb * p.mb;
    const Vec2 after = r.velocity_a * p.ma + r.velocity_b * p.mb;
    const double scale = length(p.va) * p.ma + length(p.vb) * p.mb;
    ASSERT_NEAR(after.x, before.x, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(after.y, before.y, kRelTol * scale) << "case " << i;
  }
}

TEST(BounceProperty, ElasticConservesEnergyAndInelasticLosesThePredictedAmount) {
  RandomCases random(22);
  for (int i = 0; i < kBounceCases; ++i) {
    const BouncePair p = random_bounce_pair(random);
    const double e = (i % 2 == 0) ? 1.0 : p.e;
    const BounceResult r = bounce(p.va, p.ma, p.vb, p.mb, p.normal, e);
    const double before = kinetic(p.va, p.ma) + kinetic(p.vb, p.mb);
    const double after = kinetic(r.velocity_a, p.ma) + kinetic(r.velocity_b, p.mb);
    // Predicted loss: (1 − e²)/2 · μ · (approach speed)², μ the reduced mass; and the impulse
    // agrees with it: J = (1 + e)·μ·(approach speed).
    const double approach = std::max(0.0, dot(p.va - p.vb, normalized(p.normal)));
    const double reduced_mass = p.ma * p.mb / (p.ma + p.mb);
    const double loss = 0.5 * (1.0 - e * e) * reduced_mass * approach * approach;
    ASSERT_NEAR(before - after, loss, kRelTol * before) << "case " << i;
    ASSERT_NEAR(r.impulse, (1.0 + e) * reduced_mass * approach, kRelTol * before);
    ASSERT_GE(r.impulse, 0.0);
    // After the bounce an approaching pair separates at e times the approach speed.
    if (approach > 0.0) {
      ASSERT_NEAR(dot(r.velocity_b - r.velocity_a, normalized(p.normal)), e * approach,
                  kRelTol * 100.0);
    }
  }
}

TEST(BounceProperty, EqualMassImpulseAgreesWithTheExchange) {
  RandomCases random(23);
  for (int i = 0; i < kBounceCases; ++i) {
    const BouncePair p = random_bounce_pair(random);
    if (dot(p.va - p.vb, p.normal) <= 0.0) continue;  // the exchange applies to approaching pairs
    const BounceResult general = bounce(p.va, p.ma, p.vb, p.ma, p.normal, 1.0);
    const BounceResult exchange = bounce_equal_mass(p.va, p.vb, p.normal);
    const double scale = length(p.va) + length(p.vb);
    ASSERT_NEAR(general.velocity_a.x, exchange.velocity_a.x, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(general.velocity_a.y, exchange.velocity_a.y, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(general.velocity_b.x, exchange.velocity_b.x, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(general.velocity_b.y, exchange.velocity_b.y, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(general.impulse, exchange.impulse * p.ma, kRelTol * scale * p.ma);
  }
}

TEST(BounceProperty, StaticBounceMatchesAnImmovablePartner) {
  RandomCases random(24);
  for (int i = 0; i < kBounceCases; ++i) {
    const BouncePair p = random_bounce_pair(random);
    const WallBounceResult wall = bounce_off_static(p.va, p.ma, p.normal, p.e);
    const BounceResult ball = bounce(p.va, p.ma, {}, kImmovable, p.normal, p.e);
    const double scale = length(p.va);
    ASSERT_NEAR(wall.velocity.x, ball.velocity_a.x, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(wall.velocity.y, ball.velocity_a.y, kRelTol * scale) << "case " << i;
    ASSERT_NEAR(wall.impulse, ball.impulse, kRelTol * scale * p.ma) << "case " << i;
  }
}

// ---- a ball in a bowl (bounce_inside_arc) ---------------------------------------------------
// The ball at the bottom of a bowl: the normal points down, away from the arc's centre.
constexpr Vec2 kDown{0.0, -1.0};

TEST(BounceInsideArc, AGrazeLeavesAtTheLeavingAngleWithItsSpeed) {
  const WallBounceResult r = bounce_inside_arc({5.0, 0.0}, 2.0, kDown, 0.5);
  EXPECT_NEAR(length(r.velocity), 5.0, 1e-15);
  EXPECT_NEAR(r.velocity.y, 5.0 * kBowlLeavingSine, 1e-15);
  EXPECT_GT(r.velocity.x, 0.0);
  EXPECT_NEAR(r.impulse, 2.0 * 5.0 * kBowlLeavingSine, 1e-15);
}

TEST(BounceInsideArc, ASteepArrivalBouncesAsOffAnyWall) {
  const WallBounceResult bowl = bounce_inside_arc({3.0, -4.0}, 2.0, kDown, 0.5);
  const WallBounceResult flat = bounce_off_static({3.0, -4.0}, 2.0, kDown, 0.5);
  EXPECT_EQ(bowl.velocity, flat.velocity);  // (3, 2)
  EXPECT_EQ(bowl.impulse, flat.impulse);
}

TEST(BounceInsideArc, AFlatArrivalIsElasticWhateverTheRestitution) {
  // Sine 0.01: below kBowlSlidingSine (sliding), above kBowlLeavingSine (no turn needed).
  const WallBounceResult r = bounce_inside_arc({1.0, -0.01}, 1.0, kDown, 0.0);
  EXPECT_EQ(r.velocity, (Vec2{1.0, 0.01}));
  EXPECT_EQ(r.impulse, 0.02);
}

TEST(BounceInsideArc, ADeadBallIsTurnedAlongTheWallKeepingItsTangentialSpeed) {
  // e = 0 leaves (3, 0), flat along the wall: turned to the leaving angle, speed 3 kept.
  const WallBounceResult r = bounce_inside_arc({3.0, -4.0}, 1.0, kDown, 0.0);
  EXPECT_NEAR(length(r.velocity), 3.0, 1e-15);
  EXPECT_NEAR(r.velocity.y, 3.0 * kBowlLeavingSine, 1e-15);
  EXPECT_NEAR(r.impulse, 4.0 + 3.0 * kBowlLeavingSine, 1e-14);
}

TEST(BounceInsideArc, RejectsBadArguments) {
  const double nan = std::nan("");
  EXPECT_THROW((void)bounce_inside_arc({nan, 0.0}, 1.0, kDown), InvalidArgument);
  EXPECT_THROW((void)bounce_inside_arc({1.0, 0.0}, 0.0, kDown), InvalidArgument);
  EXPECT_THROW((void)bounce_inside_arc({1.0, 0.0}, 1.0, {0.0, 0.0}), InvalidArgument);
  EXPECT_THROW((void)bounce_inside_arc({1.0, 0.0}, 1.0, kDown, 1.5), InvalidArgument);
}

}  // namespace
}  // namespace carom
