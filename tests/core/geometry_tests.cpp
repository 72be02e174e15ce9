// Nearest points, distances and the periodic cell (carom/geometry.hpp), the functions the World
// uses for its own checks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "carom/error.hpp"
#include "carom/geometry.hpp"

namespace carom {
namespace {

TEST(Geometry, NearestPointOfASegment) {
  const Segment s{{0.0, 0.0}, {4.0, 0.0}};
  EXPECT_EQ(nearest_point(s, {1.0, 3.0}), (Vec2{1.0, 0.0}));   // the interior
  EXPECT_EQ(nearest_point(s, {-2.0, 1.0}), (Vec2{0.0, 0.0}));  // before a
  EXPECT_EQ(nearest_point(s, {9.0, -1.0}), (Vec2{4.0, 0.0}));  // past b
  EXPECT_EQ(distance(s, {1.0, 3.0}), 3.0);
  const Segment point{{2.0, 2.0}, {2.0, 2.0}};
  EXPECT_EQ(nearest_point(point, {5.0, 6.0}), (Vec2{2.0, 2.0}));
  EXPECT_EQ(distance(point, {5.0, 6.0}), 5.0);
}

TEST(Geometry, NearestPointOfAnArc) {
  // The upper half circle of radius 2 about the origin.
  const Arc arc{{0.0, 0.0}, 2.0, 0.0, std::numbers::pi};
  const Vec2 up = nearest_point(arc, {0.0, 5.0});
  EXPECT_NEAR(up.x, 0.0, 1e-15);
  EXPECT_EQ(up.y, 2.0);
  EXPECT_NEAR(distance(arc, {0.0, 0.5}), 1.5, 1e-15);  // from inside
  // Below the span: the nearer end point.
  const Vec2 end = nearest_point(arc, {1.5, -3.0});
  EXPECT_EQ(end, (Vec2{2.0, 0.0}));
  EXPECT_THROW((void)nearest_point(Arc{{0.0, 0.0}, -1.0, 0.0, 1.0}, {1.0, 1.0}), InvalidArgument);
}

TEST(Geometry, MinimumImageTakesTheShortestOffset) {
  const PeriodicCell cell({0.0, 0.0}, {10.0, 4.0});
  EXPECT_EQ(cell.period(), (Vec2{10.0, 4.0}));
  EXPECT_EQ(cell.minimum_image({3.0, 1.0}), (Vec2{3.0, 1.0}));
  EXPECT_EQ(cell.minimum_image({9.0, -3.5}), (Vec2{-1.0, 0.5}));
  // Exactly half a period is already shortest (a tie).
  EXPECT_EQ(cell.minimum_image({5.0, -2.0}), (Vec2{5.0, -2.0}));
  // Offsets of several periods are reduced by whole periods.
  EXPECT_EQ(cell.minimum_image({47.0, 17.0}), (Vec2{-3.0, 1.0}));
  EXPECT_EQ(cell.minimum_image({-31.0, -9.0}), (Vec2{-1.0, -1.0}));
}

TEST(Geometry, WrapBringsAPointIntoTheHalfOpenCell) {
  const PeriodicCell cell({-1.0, 2.0}, {3.0, 6.0});
  EXPECT_EQ(cell.wrap({0.5, 3.0}), (Vec2{0.5, 3.0}));
  EXPECT_EQ(cell.wrap({4.0, 7.0}), (Vec2{0.0, 3.0}));
  EXPECT_EQ(cell.wrap({-5.5, -6.0}), (Vec2{2.5, 2.0}));
  // The upper edge is the lower one.
  EXPECT_EQ(cell.wrap({3.0, 6.0}), (Vec2{-1.0, 2.0}));
  // A point a rounding below the lower edge lands inside, never on the upper edge.
  const Vec2 p = cell.wrap({std::nextafter(-1.0, -2.0), 2.0});
  EXPECT_GE(p.x, -1.0);
  EXPECT_LT(p.x, 3.0);
}

}  // namespace
}  // namespace carom
