// The closed form for a growing pair (core/growing_pair.hpp): where it decides, it agrees with
// the certified isolation of the Motion queries; it leaves touching, grazing and pace-keeping
// pairs undecided.
#include <gtest/gtest.h>

#include <cmath>

#include "carom/sweep.hpp"
#include "core/growing_pair.hpp"
#include "random_cases.hpp"

namespace carom {
namespace {

TEST(GrowingPair, DecidedClosingsAgreeWithTheCertifiedIsolation) {
  RandomCases random(41);
  int decided = 0;
  int found = 0;
  for (int i = 0; i < 100'000; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 u = random.point(6.0);
    const double ga = random.uniform(0.0, 3.0);
    const double gb = random.uniform(0.0, 3.0);
    const detail::GrowingPairClosing fast =
        detail::growing_pair_closing(a.center - b.center, u, a.radius + b.radius, ga + gb);
    if (!fast.decided) continue;
    ++decided;
    constexpr double kHorizon = 1e3;
    const Impact certified =
        time_of_impact_ball_ball(a, Motion{u, {}, ga}, b, Motion{{}, {}, gb}, kHorizon);
    ASSERT_EQ(fast.found && fast.t <= kHorizon, certified.hit) << "case " << i;
    if (!certified.hit) continue;
    ++found;
    ASSERT_NEAR(fast.t, certified.t, 1e-12 * (1.0 + certified.t)) << "case " << i;
  }
  EXPECT_GT(decided, 90'000);
  EXPECT_GT(found, 30'000);
}

TEST(GrowingPair, TouchingAndPaceKeepingPairsAreUndecided) {
  // Touching (the gap within its rounding of 0).
  EXPECT_FALSE(detail::growing_pair_closing({2.0, 0.0}, {-1.0, 0.0}, 2.0, 1.0).decided);
  // Parting exactly as fast as the radii grow (after a bounce of restitution 0).
  EXPECT_FALSE(detail::growing_pair_closing({3.0, 0.0}, {1.0, 0.0}, 2.0, 1.5).decided);
  // Apart, closing: decided, at the closed-form time (gap 6 closed at 1 + 2 = 3: t = 2).
  const detail::GrowingPairClosing closing =
      detail::growing_pair_closing({8.0, 0.0}, {-1.0, 0.0}, 2.0, 2.0);
  ASSERT_TRUE(closing.decided);
  ASSERT_TRUE(closing.found);
  EXPECT_DOUBLE_EQ(closing.t, 2.0);
}

TEST(GrowingPair, APairPartingFasterThanItGrowsNeverClosesWhateverItsGap) {
  // Touching (the gap within its rounding of 0, as just after a contact), parting at 3 while the
  // radii grow at 1: decided, no closing, as the certified isolation says.
  const detail::GrowingPairClosing parting =
      detail::growing_pair_closing({2.0, 0.0}, {3.0, 0.5}, 2.0, 1.0);
  ASSERT_TRUE(parting.decided);
  EXPECT_FALSE(parting.found);
  const Impact certified =
      time_of_impact_ball_ball(Ball{{2.0, 0.0}, 1.0}, Motion{{3.0, 0.5}, {}, 0.5},
                               Ball{{0.0, 0.0}, 1.0}, Motion{{}, {}, 0.5}, 1e3);
  EXPECT_FALSE(certified.hit);
  // Parting slower than the radii grow: they meet again, which only the isolation reads here.
  EXPECT_FALSE(detail::growing_pair_closing({2.0, 0.0}, {0.5, 0.0}, 2.0, 1.0).decided);
}

TEST(GrowingPair, MagnitudesOutsideTheWindowAreUndecided) {
  // A growth speed whose square is below 2⁻⁴⁰⁰, and a distance whose square passes 2⁵⁰⁰: the
  // rounding bounds would not hold (subnormal products, overflow), so the isolation decides.
  EXPECT_FALSE(detail::growing_pair_closing({8.0, 0.0}, {-1.0, 0.0}, 2.0, 1e-130).decided);
  EXPECT_FALSE(detail::growing_pair_closing({1e160, 0.0}, {-1.0, 0.0}, 2.0, 1.0).decided);
  EXPECT_FALSE(detail::growing_pair_closing({8.0, 0.0}, {-1e160, 0.0}, 2.0, 1.0).decided);
  EXPECT_TRUE(detail::growing_pair_closing({8.0, 0.0}, {-1.0, 0.0}, 2.0, 1e-50).decided);
}

}  // namespace
}  // namespace carom
