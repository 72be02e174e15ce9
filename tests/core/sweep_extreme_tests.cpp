// Time of impact at the ends of the double range: scale invariance from 1e-300 to 1e300,
// differences that overflow, a tiny ball far away, and any finite input at all (a valid hit
// with t in range or no hit, never a NaN). The range and its limits: docs/derivation.md,
// "Any finite input", and docs/guarantees.md.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"
#include "random_cases.hpp"

namespace carom {
namespace {

constexpr double kMax = std::numeric_limits<double>::max();

// Power-of-two scales spanning the range: every scaled input stays a normal double (the random
// cases' values lie between about 1e-9 and 1e2, so 2^-950 and 2^+900 keep them within
// [2^-1022, 2^1023]). Scaling by a power of two is exact, so the answers must be the same.
const int kScales[] = {-950, -700, -520, -300, -170, -60, 60, 170, 300, 520, 700, 900};

Vec2 scaled(Vec2 v, int e) { return {std::ldexp(v.x, e), std::ldexp(v.y, e)}; }
Ball scaled(const Ball& b, int e) { return {scaled(b.center, e), std::ldexp(b.radius, e)}; }

bool has_nan(Vec2 v) { return std::isnan(v.x) || std::isnan(v.y); }
bool has_nan(const Impact& impact) {
  return std::isnan(impact.t) || has_nan(impact.a_at) || has_nan(impact.b_at) ||
         has_nan(impact.normal) || has_nan(impact.point);
}

TEST(SweepExtremeScale, BallBallIsScaleInvariantBitForBit) {
  testing::RandomCases random(8001);
  for (int i = 0; i < 4000; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 move_a = random.move_towards(a.center, b.center, 4.0);
    const Vec2 move_b = random.point(6.0);
    const Impact unit = sweep_ball_ball(a, move_a, b, move_b);
    for (const int e : kScales) {
      const Impact big =
          sweep_ball_ball(scaled(a, e), scaled(move_a, e), scaled(b, e), scaled(move_b, e));
      ASSERT_EQ(big.hit, unit.hit) << "case " << i << " scale 2^" << e;
      ASSERT_EQ(big.overlapping, unit.overlapping) << "case " << i << " scale 2^" << e;
      ASSERT_EQ(big.t, unit.t) << "case " << i << " scale 2^" << e;
      // Positions are sums and products, exact under power-of-two scaling.
      ASSERT_EQ(big.a_at, scaled(unit.a_at, e)) << "case " << i << " scale 2^" << e;
      // The normal divides by a hypot, whose last bit need not scale: 4 ulp.
      ASSERT_NEAR(big.normal.x, unit.normal.x, 1e-15) << "case " << i << " scale 2^" << e;
      ASSERT_NEAR(big.normal.y, unit.normal.y, 1e-15) << "case " << i << " scale 2^" << e;
    }
  }
}

TEST(SweepExtremeScale, BallPointIsScaleInvariantBitForBit) {
  testing::RandomCases random(8002);
  for (int i = 0; i < 4000; ++i) {
    const Ball a = random.ball(10.0);
    const Vec2 point = random.point(10.0);
    const Vec2 move = random.move_towards(a.center, point, 4.0);
    const Impact unit = sweep_ball_point(a, move, point);
    for (const int e : kScales) {
      const Impact big = sweep_ball_point(scaled(a, e), scaled(move, e), scaled(point, e));
      ASSERT_EQ(big.hit, unit.hit) << "case " << i << " scale 2^" << e;
      ASSERT_EQ(big.t, unit.t) << "case " << i << " scale 2^" << e;
    }
  }
}

// The segment and the arc take lengths through hypot and the arc's span test through
// normalised directions, whose last bits need not scale: the hit must agree, and t to 1e-12
// relative (a few ulp of the quotients it is made of). A case whose contact lies within 1e-9
// of a segment's or arc's end is skipped: there a last-bit difference may move the contact
// from the interior to the end point, both correct to rounding.
TEST(SweepExtremeScale, SegmentAndArcAreScaleInvariantToRounding) {
  testing::RandomCases random(8003);
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    const Ball a = random.ball(10.0);
    const Segment segment = random.segment(10.0);
    const Arc arc = random.arc(10.0);
    const Vec2 move = random.move_towards(a.center, segment.a, 6.0);
    const Impact unit_segment = sweep_ball_segment(a, move, segment);
    const Impact unit_arc = sweep_ball_arc(a, move, arc);
    const bool near_segment_end =
        unit_segment.hit && (distance(unit_segment.point, segment.a) < 1e-9 ||
                             distance(unit_segment.point, segment.b) < 1e-9);
    for (const int e : kScales) {
      if (!near_segment_end) {
        const Impact big = sweep_ball_segment(scaled(a, e), scaled(move, e),
                                              {scaled(segment.a, e), scaled(segment.b, e)});
        ASSERT_EQ(big.hit, unit_segment.hit) << "segment case " << i << " scale 2^" << e;
        ASSERT_NEAR(big.t, unit_segment.t, 1e-12 * unit_segment.t)
            << "segment case " << i << " scale 2^" << e;
        ++compared;
      }
      const Arc big_arc{scaled(arc.center, e), std::ldexp(arc.radius, e), arc.start_angle,
                        arc.end_angle};
      const Impact big = sweep_ball_arc(scaled(a, e), scaled(move, e), big_arc);
      ASSERT_EQ(big.hit, unit_arc.hit) << "arc case " << i << " scale 2^" << e;
      ASSERT_NEAR(big.t, unit_arc.t, 1e-12 * unit_arc.t) << "arc case " << i << " scale 2^" << e;
    }
  }
  EXPECT_GT(compared, 40000);
}

TEST(SweepExtremeScale, TimeFormScalesTimeSeparately) {
  // Velocities times 2^k and the horizon times 2^-k: the same contact at t times 2^-k, with
  // lengths at one scale and speeds at a very different one.
  testing::RandomCases random(8004);
  for (int i = 0; i < 2000; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 va = random.move_towards(a.center, b.center, 4.0);
    const Vec2 vb = random.point(6.0);
    const Impact unit = time_of_impact_ball_ball(a, va, b, vb, 1.0);
    for (const int k : {-900, -400, 400, 900}) {
      for (const int e : {-600, 0, 600}) {    // lengths scaled too
        if (std::abs(e + k) > 900) continue;  // velocities must stay normal doubles
        const Impact other = time_of_impact_ball_ball(scaled(a, e), scaled(va, e + k), scaled(b, e),
                                                      scaled(vb, e + k), std::ldexp(1.0, -k));
        ASSERT_EQ(other.hit, unit.hit) << "case " << i << " k " << k << " e " << e;
        ASSERT_EQ(other.t, std::ldexp(unit.t, -k)) << "case " << i << " k " << k << " e " << e;
      }
    }
  }
}

// Regression: beyond about 1e154 the squares of the quadratic overflowed to infinity, and the
// discriminant to NaN or infinity: a head-on collision was reported as no hit.
TEST(SweepExtremeRegression, HugeValuesOverflowedTheQuadratic) {
  // The integer case s = (−5, 0), u = (4, 0), R = 2 (t = 21/28 = 0.75 exactly) scaled by 2^700.
  const double k = std::ldexp(1.0, 700);
  const Impact exact = sweep_ball_ball({{0.0, 0.0}, k}, {4.0 * k, 0.0}, {{5.0 * k, 0.0}, k});
  ASSERT_TRUE(exact.hit);
  EXPECT_EQ(exact.t, 0.75);
  EXPECT_EQ(exact.a_at, (Vec2{3.0 * k, 0.0}));
  EXPECT_EQ(exact.normal, (Vec2{1.0, 0.0}));
  // And in decimal, at 1e200.
  const Impact impact = sweep_ball_ball({{0.0, 0.0}, 1e200}, {4e200, 0.0}, {{5e200, 0.0}, 1e200});
  ASSERT_TRUE(impact.hit);
  EXPECT_NEAR(impact.t, 0.75, 1e-15);
  EXPECT_FALSE(has_nan(impact));
}

// Regression: below about 1e-154 the squares underflowed to zero and every discriminant
// vanished: all contacts were reported as grazes (no hit).
TEST(SweepExtremeRegression, TinyValuesUnderflowedTheQuadratic) {
  const double k = std::ldexp(1.0, -700);
  const Impact exact = sweep_ball_ball({{0.0, 0.0}, k}, {4.0 * k, 0.0}, {{5.0 * k, 0.0}, k});
  ASSERT_TRUE(exact.hit);
  EXPECT_EQ(exact.t, 0.75);
  const Impact impact =
      sweep_ball_ball({{0.0, 0.0}, 1e-200}, {4e-200, 1e-201}, {{5e-200, 0.0}, 1e-200});
  ASSERT_TRUE(impact.hit);
  const Impact unit = sweep_ball_ball({{0.0, 0.0}, 1.0}, {4.0, 0.1}, {{5.0, 0.0}, 1.0});
  EXPECT_NEAR(impact.t, unit.t, 1e-15);
  // A wall at 1e-300: reached when the centre has come down from 3e-300 to 1e-300.
  const Impact wall = sweep_ball_segment({{0.0, 3e-300}, 1e-300}, {1e-300, -4e-300},
                                         {{-1e-299, 0.0}, {1e-299, 0.0}});
  ASSERT_TRUE(wall.hit);
  EXPECT_NEAR(wall.t, 0.5, 1e-15);
  EXPECT_EQ(wall.normal, (Vec2{0.0, -1.0}));
}

TEST(SweepExtremeRegression, DifferencesBeyondTheDoubleRange) {
  // Centres ±1.5e308 apart by 3e308 and a relative speed of 3e308: the differences overflow;
  // the halved problem answers as the same problem scaled down by 2^-1000.
  const Ball a{{-1.5e308, 0.0}, 1e307};
  const Ball b{{1.5e308, 0.0}, 1e307};
  const Impact impact = time_of_impact_ball_ball(a, {1.5e308, 0.0}, b, {-1.5e308, 0.0}, 2.0);
  ASSERT_TRUE(impact.hit);
  const Impact small =
      time_of_impact_ball_ball(scaled(a, -1000), scaled(Vec2{1.5e308, 0.0}, -1000),
                               scaled(b, -1000), scaled(Vec2{-1.5e308, 0.0}, -1000), 2.0);
  ASSERT_TRUE(small.hit);
  EXPECT_EQ(impact.t, small.t);
  EXPECT_EQ(impact.normal, (Vec2{1.0, 0.0}));
  EXPECT_FALSE(has_nan(impact));
  // Radii whose sum overflows.
  const Impact giants =
      time_of_impact_ball_ball({{-kMax, 0.0}, kMax}, {}, {{kMax, 0.0}, kMax}, {-1.0, 0.0}, 1.0);
  EXPECT_TRUE(giants.hit);  // touching (2·max apart, radii summing to 2·max) and approaching
  EXPECT_EQ(giants.t, 0.0);
  EXPECT_FALSE(has_nan(giants));
}

TEST(SweepExtremeRegression, TinyBallsFarApartHeadOn) {
  // Radii 1e-300 at distance 2e300 (a ratio of 2^1993): R² and (s×u)² cannot both be normal
  // doubles at any one scale; the head-on path (s×u = 0) still hits, at t = 1 to rounding.
  const Impact impact = time_of_impact_ball_ball({{-1e300, 0.0}, 1e-300}, {1e300, 0.0},
                                                 {{1e300, 0.0}, 1e-300}, {-1e300, 0.0}, 2.0);
  ASSERT_TRUE(impact.hit);
  EXPECT_EQ(impact.t, 1.0);
  // Off the head-on line by far more than the radii: no hit.
  EXPECT_FALSE(time_of_impact_ball_ball({{-1e300, 0.0}, 1e-300}, {1e300, 0.0},
                                        {{1e300, 1.0}, 1e-300}, {-1e300, 0.0}, 2.0)
                   .hit);
}

// Found by the time-of-impact fuzzer's smoke run: a ball missing a segment that ends
// at (1, −max) was given the nearest point a + (b − a)·1, which rounded to (0, −∞), and so a NaN
// normal. The nearest point is now the end point itself.
TEST(SweepExtremeRegression, NearestPointOfASegmentEndingAtTheRangesEdge) {
  const Ball ball{{kMax, -kMax}, 1.7974796903477642e308};
  const Vec2 velocity{-kMax, kMax};
  const Segment segment{{-kMax, -6.460459703411447e307}, {0.9999999999999999, -kMax}};
  const Impact impact = time_of_impact_ball_segment(ball, velocity, segment, 2.525e-321);
  EXPECT_FALSE(impact.hit);
  EXPECT_TRUE(is_finite(impact.point)) << impact.point.x << ", " << impact.point.y;
  EXPECT_TRUE(is_finite(impact.normal)) << impact.normal.x << ", " << impact.normal.y;
  EXPECT_EQ(impact.point, segment.b);
}

// ---- any finite input ------------------------------------------------------------------------

// Doubles from the whole finite range: ordinary values, the extremes, subnormals, and random
// bit patterns.
class AnyDouble {
 public:
  explicit AnyDouble(std::uint64_t seed) : random_(seed) {}

  double next() {
    static constexpr double kSpecial[] = {
        0.0,   -0.0,   1.0,      -1.0,      kMax,
        -kMax, 1e300,  -1e300,   1e-300,    -1e-300,
        1e154, 1e-154, 4.9e-324, -4.9e-324, 2.2250738585072014e-308,
        0.5};
    switch (random_.engine()() % 4) {
      case 0:
        return random_.uniform(-10.0, 10.0);
      case 1:
        return kSpecial[random_.engine()() % std::size(kSpecial)];
      case 2: {
        const double sign = random_.engine()() % 2 != 0 ? -1.0 : 1.0;
        return sign * std::ldexp(random_.uniform(1.0, 2.0),
                                 static_cast<int>(random_.engine()() % 2098) - 1074);
      }
      default: {
        double x = std::bit_cast<double>(random_.engine()());
        while (!std::isfinite(x)) x = std::bit_cast<double>(random_.engine()());
        return x;
      }
    }
  }
  double positive() {
    double x = std::abs(next());
    while (!(x > 0.0)) x = std::abs(next());
    return x;
  }
  Vec2 vec() { return {next(), next()}; }

 private:
  testing::RandomCases random_;
};

void expect_valid(const Impact& impact, double horizon, const char* what, int i) {
  ASSERT_FALSE(has_nan(impact)) << what << " case " << i;
  if (impact.hit) {
    ASSERT_GE(impact.t, 0.0) << what << " case " << i;
    ASSERT_LE(impact.t, horizon) << what << " case " << i;
    ASSERT_NEAR(length(impact.normal), 1.0, 1e-12) << what << " case " << i;
  } else {
    ASSERT_EQ(impact.t, 0.0) << what << " case " << i;
  }
}

TEST(SweepAnyFiniteInput, ValidHitOrNoHitNeverNaN) {
  AnyDouble any(8005);
  for (int i = 0; i < 60000; ++i) {
    const Ball a{any.vec(), any.positive()};
    const Ball b{any.vec(), any.positive()};
    const Vec2 va = any.vec();
    const Vec2 vb = any.vec();
    const double horizon = std::abs(any.next());
    expect_valid(time_of_impact_ball_ball(a, va, b, vb, horizon), horizon, "ball-ball", i);
    expect_valid(time_of_impact_ball_point(a, va, b.center, horizon), horizon, "ball-point", i);
    expect_valid(time_of_impact_ball_segment(a, va, {b.center, vb}, horizon), horizon,
                 "ball-segment", i);
    const Arc arc{b.center, b.radius, any.next(), 0.0};
    Arc spanned = arc;
    spanned.start_angle = std::fmod(arc.start_angle, 100.0);
    spanned.end_angle = spanned.start_angle + std::abs(std::fmod(any.next(), 6.28));
    try {
      expect_valid(time_of_impact_ball_arc(a, va, spanned, horizon), horizon, "ball-arc", i);
    } catch (const InvalidArgument& error) {
      // The one refusal for finite input: a circle reaching beyond the double range.
      ASSERT_EQ(error.argument(), "arc.radius") << "case " << i << ": " << error.what();
      ASSERT_FALSE(
          std::isfinite(std::max(std::abs(arc.center.x), std::abs(arc.center.y)) + arc.radius))
          << "case " << i;
    }
  }
}

TEST(SweepAnyFiniteInput, BatchAgreesWithScalarBitForBit) {
  AnyDouble any(8006);
  constexpr int kPairs = 20000;
  std::vector<double> col[10];
  std::vector<Impact> expected;
  for (int i = 0; i < kPairs; ++i) {
    const Ball a{any.vec(), any.positive()};
    const Ball b{any.vec(), any.positive()};
    const Vec2 ma = any.vec();
    const Vec2 mb = any.vec();
    const double values[] = {a.center.x, a.center.y, a.radius, ma.x, ma.y,
                             b.center.x, b.center.y, b.radius, mb.x, mb.y};
    for (int k = 0; k < 10; ++k) col[k].push_back(values[k]);
    expected.push_back(sweep_ball_ball(a, ma, b, mb));
  }
  const BallPairArrays pairs{col[0], col[1], col[2], col[3], col[4],
                             col[5], col[6], col[7], col[8], col[9]};
  std::vector<double> t(kPairs);
  const std::size_t hits = sweep_ball_ball_batch(pairs, t);
  std::size_t expected_hits = 0;
  for (int i = 0; i < kPairs; ++i) {
    const auto index = static_cast<std::size_t>(i);
    if (expected[index].hit) {
      ++expected_hits;
      ASSERT_EQ(t[index], expected[index].t) << "pair " << i;
    } else {
      ASSERT_EQ(t[index], kNoHit) << "pair " << i;
    }
  }
  EXPECT_EQ(hits, expected_hits);
}

TEST(SweepAnyFiniteInput, BatchWritingOverItsInputAgreesWithScalar) {
  // t may alias an input array; a pair outside the exact range is then still answered.
  const double k = std::ldexp(1.0, 700);  // pair 0 is pair 1 scaled by 2^700
  std::vector<double> ax{0.0, 0.0}, ay{0.0, 0.0}, ar{k, 1.0}, amx{4.0 * k, 4.0}, amy{0.0, 0.0};
  std::vector<double> bx{5.0 * k, 5.0}, by{0.0, 0.0}, br{k, 1.0}, bmx{0.0, 0.0}, bmy{0.0, 0.0};
  const BallPairArrays pairs{ax, ay, ar, amx, amy, bx, by, br, bmx, bmy};
  EXPECT_EQ(sweep_ball_ball_batch(pairs, amy), 2u);
  EXPECT_EQ(amy[0], 0.75);
  EXPECT_EQ(amy[1], 0.75);
}

}  // namespace
}  // namespace carom
