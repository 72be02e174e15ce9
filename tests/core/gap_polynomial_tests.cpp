// The closings of polynomial gaps (src/core/gap_polynomial.hpp): polynomials with known roots,
// touches and grazes at the edge of the rounding, the rules at t = 0, horizons from 0 to
// infinity, magnitudes far from 1, and random quartics against their known roots.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/gap_polynomial.hpp"

namespace carom::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The polynomial lead·Π(t − root), its weights the magnitudes of its expanded terms (each
// coefficient is a sum of products of roots: the sum of their magnitudes bounds its rounding).
GapPolynomial from_roots(double lead, const std::vector<double>& roots) {
  std::vector<double> c{lead};
  std::vector<double> w{std::abs(lead)};
  for (const double root : roots) {
    std::vector<double> next(c.size() + 1, 0.0);
    std::vector<double> next_w(c.size() + 1, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i + 1] += c[i];
      next[i] -= c[i] * root;
      next_w[i + 1] += w[i];
      next_w[i] += w[i] * std::abs(root);
    }
    c = next;
    w = next_w;
  }
  GapPolynomial p;
  const std::size_t degree = c.size() - 1;
  for (std::size_t i = 0; i <= degree; ++i) {
    p.c[i] = c[i];
    p.weight[i] = w[i];
  }
  return p;
}

std::vector<double> closings(const GapPolynomial& p, double horizon = kInfinity,
                             AtStart at_start = AtStart::counts) {
  const GapClosings found = gap_closings(p, horizon, at_start);
  return {found.t.begin(), found.t.begin() + static_cast<std::ptrdiff_t>(found.count)};
}

GapPolynomial coefficients(std::array<double, 5> c) {
  GapPolynomial p;
  p.c = c;
  for (std::size_t i = 0; i < c.size(); ++i) p.weight[i] = std::abs(c[i]);
  return p;
}

TEST(GapPolynomial, ExpandsRootsInAscendingPowers) {
  const GapPolynomial p = from_roots(1.0, {1.0, 2.0});  // t² − 3t + 2
  EXPECT_EQ(p.c[0], 2.0);
  EXPECT_EQ(p.c[1], -3.0);
  EXPECT_EQ(p.c[2], 1.0);
}

TEST(GapPolynomial, QuarticClosesAtEachFall) {
  // Positive at 0, falls through 1, rises through 2, falls through 3, rises through 4.
  const std::vector<double> found = closings(from_roots(1.0, {1.0, 2.0, 3.0, 4.0}));
  ASSERT_EQ(found.size(), 2u);
  // Horner's rounding near 3 is about 10⁻¹³ (terms up to 315), over a slope of 2 there.
  EXPECT_NEAR(found[0], 1.0, 1e-13);
  EXPECT_NEAR(found[1], 3.0, 1e-13);
}

TEST(GapPolynomial, HorizonCutsLaterClosings) {
  EXPECT_EQ(closings(from_roots(1.0, {1.0, 2.0, 3.0, 4.0}), 2.5).size(), 1u);
  EXPECT_TRUE(closings(from_roots(1.0, {1.0, 2.0, 3.0, 4.0}), 0.999).empty());
  EXPECT_TRUE(closings(from_roots(1.0, {1.0, 2.0, 3.0, 4.0}), 0.0).empty());
}

TEST(GapPolynomial, ClosingIsTheRootToItsRounding) {
  for (const double root : {0.1, 0.7, 1.0, 3.3, 17.0, 1e-9, 1e9}) {
    const std::vector<double> found = closings(from_roots(-1.0, {root, -5.0}));
    ASSERT_EQ(found.size(), 1u) << root;
    // The computed coefficients put the root within a few units of `root`.
    EXPECT_NEAR(found[0], root, 1e-15 * root) << root;
  }
}

TEST(GapPolynomial, GrazeIsNoClosing) {
  // (t − 1)²·(t² + 1): touches zero at 1 and rises again.
  GapPolynomial p = from_roots(1.0, {1.0, 1.0});
  const GapPolynomial q = coefficients({1.0, 0.0, 1.0, 0.0, 0.0});
  GapPolynomial product;
  for (std::size_t i = 0; i <= 2; ++i) {
    for (std::size_t j = 0; j <= 2; ++j) {
      product.c[i + j] += p.c[i] * q.c[j];
      product.weight[i + j] += p.weight[i] * q.weight[j];
    }
  }
  EXPECT_TRUE(closings(product).empty());
  // A quadratic graze: (t − 2)².
  EXPECT_TRUE(closings(from_roots(1.0, {2.0, 2.0})).empty());
}

TEST(GapPolynomial, TouchThenFallClosesOnce) {
  // (t − 1)²·(3 − t): touches at 1, then falls through 3.
  const std::vector<double> found = closings(from_roots(-1.0, {1.0, 1.0, 3.0}));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0], 3.0, 1e-13);
  // (1 − t)³: falls through 1 with zero slope there.
  const std::vector<double> flat = closings(from_roots(-1.0, {1.0, 1.0, 1.0}));
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_NEAR(flat[0], 1.0, 1e-4);  // a triple root is known only to the cube root of rounding
  EXPECT_LE(flat[0], 1.0 + 1e-5);
}

TEST(GapPolynomial, ShallowDipsCloseOnceBeyondTheRounding) {
  // (t − 1)² − ε: a dip of depth ε; it closes at 1 − √ε once ε is beyond the rounding.
  for (const double depth : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    GapPolynomial p = from_roots(1.0, {1.0, 1.0});
    p.c[0] -= depth;
    const std::vector<double> found = closings(p);
    ASSERT_EQ(found.size(), 1u) << depth;
    // The slope there is 2√ε: a rounding of 10⁻¹⁵ in the value moves the root by 10⁻¹⁵ / 2√ε.
    EXPECT_NEAR(found[0], 1.0 - std::sqrt(depth), 1e-15 / std::sqrt(depth)) << depth;
  }
  // Above zero by more than the rounding: no closing.
  GapPolynomial clear = from_roots(1.0, {1.0, 1.0});
  clear.c[0] += 1e-10;
  EXPECT_TRUE(closings(clear).empty());
}

TEST(GapPolynomial, StartRules) {
  // Touching and falling: a closing at 0 when the start counts, none when it is ignored.
  EXPECT_EQ(closings(coefficients({0.0, -1.0, 0.0, 0.0, 0.0})), std::vector<double>{0.0});
  EXPECT_TRUE(
      closings(coefficients({0.0, -1.0, 0.0, 0.0, 0.0}), kInfinity, AtStart::ignored).empty());
  // Touching, no speed, pressed together by the second derivative (a ball at rest on a floor).
  EXPECT_EQ(closings(coefficients({0.0, 0.0, -1.0, 0.0, 0.0})), std::vector<double>{0.0});
  // Touching and opening: none, and none later for a gap that keeps rising.
  EXPECT_TRUE(closings(coefficients({0.0, 1.0, 0.0, 0.0, 0.0})).empty());
  EXPECT_TRUE(closings(coefficients({0.0, 0.0, 1.0, 0.0, 0.0})).empty());
  // Touching, rising, then falling back: the fall counts (a ball thrown up off a floor lands).
  const std::vector<double> lands = closings(coefficients({0.0, 2.0, -1.0, 0.0, 0.0}));
  ASSERT_EQ(lands.size(), 1u);
  EXPECT_NEAR(lands[0], 2.0, 1e-14);
  // Overlapping and closing further (a closing at 0), opening through 1, closing through 2.
  const std::vector<double> again = closings(from_roots(1.0, {-0.5, 1.0, 2.0, 3.0}));
  ASSERT_EQ(again.size(), 2u);
  EXPECT_EQ(again[0], 0.0);
  EXPECT_NEAR(again[1], 2.0, 1e-15);
  // Overlapping and opening (no closing at 0), then closing through 2.
  const std::vector<double> opened = closings(from_roots(-1.0, {1.0, 2.0, -3.0}));
  ASSERT_EQ(opened.size(), 1u);
  EXPECT_NEAR(opened[0], 2.0, 1e-15);
  // Overlapping and closing: 0 when the start counts.
  EXPECT_EQ(closings(coefficients({-1.0, -1.0, 0.0, 0.0, 0.0})), std::vector<double>{0.0});
  EXPECT_TRUE(
      closings(coefficients({-1.0, -1.0, 0.0, 0.0, 0.0}), kInfinity, AtStart::ignored).empty());
  // A constant gap never closes.
  EXPECT_TRUE(closings(coefficients({-1.0, 0.0, 0.0, 0.0, 0.0})).empty());
  EXPECT_TRUE(closings(coefficients({0.0, 0.0, 0.0, 0.0, 0.0})).empty());
}

TEST(GapPolynomial, TouchWithinRoundingCountsAsTouching) {
  // A value of 1e-17 against terms of magnitude 1: zero within the rounding, so a falling gap
  // closes at 0 and a rising one does not.
  GapPolynomial falling = coefficients({1e-17, -1.0, 0.0, 0.0, 0.0});
  falling.weight[0] = 1.0;
  EXPECT_EQ(closings(falling), std::vector<double>{0.0});
  GapPolynomial rising = coefficients({-1e-17, 1.0, 0.0, 0.0, 0.0});
  rising.weight[0] = 1.0;
  EXPECT_TRUE(closings(rising).empty());
}

TEST(GapPolynomial, FarAndNearRoots) {
  // Roots at 10^±k: found to relative precision, however far from 1 (as far as the cubic's
  // coefficients, r³, stay normal doubles).
  for (int k = -100; k <= 100; k += 10) {
    const double root = std::pow(10.0, k);
    const std::vector<double> found = closings(from_roots(1.0, {root, 2.0 * root, -root}));
    ASSERT_FALSE(found.empty()) << k;
    // lead·(t − r)(t − 2r)(t + r) is positive at 0+ (2r³ > 0): it falls through r first.
    EXPECT_NEAR(found[0] / root, 1.0, 1e-13) << k;
  }
  // A root beyond a huge horizon, and an infinite horizon: it is found by the root bound.
  const std::vector<double> far = closings(from_roots(-1.0, {1e200}));
  ASSERT_EQ(far.size(), 1u);
  EXPECT_NEAR(far[0] / 1e200, 1.0, 1e-14);
}

TEST(GapPolynomial, RandomQuarticsAgainstTheirRoots) {
  // Four real roots, at least 10⁻³ apart, or two real and a complex pair; the closings are the
  // roots at which the sign goes from + to −.
  std::mt19937_64 engine(42);
  std::uniform_real_distribution<double> uniform(-2.0, 10.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 100'000; ++i) {
    std::vector<double> roots;
    const bool complex_pair = unit(engine) < 0.3;
    const int real_count = complex_pair ? 2 : 4;
    while (static_cast<int>(roots.size()) < real_count) {
      const double r = uniform(engine);
      bool apart = true;
      for (const double other : roots) apart &= std::abs(r - other) >= 1e-3;
      if (apart) roots.push_back(r);
    }
    const double lead = unit(engine) < 0.5 ? -1.0 : 1.0;
    GapPolynomial p = from_roots(lead, roots);
    if (complex_pair) {
      // Times (t − x)² + y², x and y random: no real roots added, the shape changes.
      const double x = uniform(engine);
      const double y = 0.01 + unit(engine);
      const GapPolynomial q = coefficients({x * x + y * y, -2.0 * x, 1.0, 0.0, 0.0});
      GapPolynomial product;
      for (std::size_t a = 0; a <= 2; ++a) {
        for (std::size_t b = 0; b <= 2; ++b) {
          product.c[a + b] += p.c[a] * q.c[b];
          product.weight[a + b] += p.weight[a] * q.weight[b];
        }
      }
      p = product;
    }
    std::sort(roots.begin(), roots.end());
    // The expected closings: sign of p just after each root in [0, ∞).
    std::vector<double> expected;
    double value_at_zero = p.c[0];
    if (value_at_zero <= 0.0) continue;  // the start rules are tested above
    for (const double r : roots) {
      if (r <= 0.0) continue;
      double after = 0.0;
      for (int k = 4; k >= 0; --k) after = after * (r + 1e-4) + p.c[static_cast<std::size_t>(k)];
      if (after < 0.0) expected.push_back(r);
    }
    const std::vector<double> found = closings(p);
    ASSERT_EQ(found.size(), expected.size()) << "case " << i;
    for (std::size_t k = 0; k < found.size(); ++k) {
      // Within the rounding of the value there, 2^-48·Σ weight·r^i, over the slope there.
      const double r = expected[k];
      double slope = 0.0;
      double rounding = 0.0;
      for (std::size_t j = 4; j >= 1; --j) {
        slope = slope * r + static_cast<double>(j) * p.c[j];
      }
      for (std::size_t j = 5; j-- > 0;) rounding = rounding * r + p.weight[j];
      const double tolerance = 0x1p-48 * rounding / std::abs(slope) + 1e-15 * r;
      ASSERT_NEAR(found[k], r, tolerance) << "case " << i;
    }
    ++compared;
  }
  EXPECT_GT(compared, 30'000);
}

}  // namespace
}  // namespace carom::detail
