#include <gtest/gtest.h>

#include "carom/vec2.hpp"

namespace carom {
namespace {

TEST(Vec2, ArithmeticIsConstexpr) {
  constexpr Vec2 a{1.0, 2.0};
  constexpr Vec2 b{3.0, -4.0};
  static_assert(a + b == Vec2{4.0, -2.0});
  static_assert(a - b == Vec2{-2.0, 6.0});
  static_assert(-a == Vec2{-1.0, -2.0});
  static_assert(a * 2.0 == Vec2{2.0, 4.0});
  static_assert(2.0 * a == Vec2{2.0, 4.0});
  static_assert(b / 2.0 == Vec2{1.5, -2.0});
  static_assert(dot(a, b) == -5.0);
  static_assert(cross(a, b) == -10.0);
  static_assert(length_squared(b) == 25.0);
  static_assert(left_normal(Vec2{1.0, 0.0}) == Vec2{0.0, 1.0});
  static_assert(right_normal(Vec2{1.0, 0.0}) == Vec2{0.0, -1.0});
}

TEST(Vec2, CompoundAssignment) {
  Vec2 v{1.0, 1.0};
  v += {2.0, 3.0};
  EXPECT_EQ(v, (Vec2{3.0, 4.0}));
  v -= {1.0, 1.0};
  EXPECT_EQ(v, (Vec2{2.0, 3.0}));
  v *= 2.0;
  EXPECT_EQ(v, (Vec2{4.0, 6.0}));
  v /= 4.0;
  EXPECT_EQ(v, (Vec2{1.0, 1.5}));
}

TEST(Vec2, CrossSignTellsTurnDirection) {
  EXPECT_GT(cross({1.0, 0.0}, {0.0, 1.0}), 0.0);  // counter-clockwise
  EXPECT_LT(cross({1.0, 0.0}, {0.0, -1.0}), 0.0);
  EXPECT_EQ(cross({2.0, 4.0}, {1.0, 2.0}), 0.0);  // parallel
}

TEST(Vec2, LengthAndNormalized) {
  EXPECT_EQ(length({3.0, 4.0}), 5.0);
  EXPECT_EQ(distance({1.0, 1.0}, {4.0, 5.0}), 5.0);
  EXPECT_EQ(normalized({0.0, -7.0}), (Vec2{0.0, -1.0}));
  EXPECT_EQ(normalized({}), (Vec2{}));
  // hypot keeps lengths near the ends of the double range finite and exact.
  EXPECT_EQ(length({3e300, 4e300}), 5e300);
  EXPECT_EQ(length({3e-300, 4e-300}), 5e-300);
}

TEST(Vec2, ProjectionSplitsIntoAlongAndAcross) {
  constexpr Vec2 v{3.0, 4.0};
  constexpr Vec2 axis{2.0, 0.0};
  static_assert(project_onto(v, axis) == Vec2{3.0, 0.0});
  static_assert(project_onto_normal(v, axis) == Vec2{0.0, 4.0});
  constexpr Components parts = decompose(v, axis);
  static_assert(parts.along + parts.across == v);
}

TEST(Vec2, ProjectionOntoDiagonalIsOrthogonal) {
  const Vec2 v{8.0, -1.0};
  const Vec2 axis{1.0, 2.0};
  const Components parts = decompose(v, axis);
  EXPECT_NEAR(cross(parts.along, axis), 0.0, 1e-14);
  EXPECT_NEAR(dot(parts.across, axis), 0.0, 1e-14);
  EXPECT_NEAR(parts.along.x + parts.across.x, v.x, 1e-14);
  EXPECT_NEAR(parts.along.y + parts.across.y, v.y, 1e-14);
}

TEST(Vec2, ProjectionOntoZeroAxisKeepsEverythingAcross) {
  constexpr Vec2 v{1.0, 2.0};
  static_assert(project_onto(v, Vec2{}) == Vec2{});
  static_assert(project_onto_normal(v, Vec2{}) == v);
}

TEST(Vec2, IsFinite) {
  EXPECT_TRUE(is_finite({1.0, -1e308}));
  EXPECT_FALSE(is_finite({std::nan(""), 0.0}));
  EXPECT_FALSE(is_finite({0.0, HUGE_VAL}));
}

}  // namespace
}  // namespace carom
