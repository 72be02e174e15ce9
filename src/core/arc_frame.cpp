#include "arc_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "exact_range.hpp"
#include "validate.hpp"

namespace carom::detail {

bool ArcFrame::contains(Vec2 direction) const noexcept {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (span >= kTwoPi) return true;
  if (span <= std::numbers::pi) {
    // Counter-clockwise of the start and clockwise of the end. The dot products reject the
    // direction opposite a very short arc, for which both cross products vanish.
    return cross(start_direction, direction) >= 0.0 && cross(direction, end_direction) >= 0.0 &&
           (dot(direction, start_direction) >= 0.0 || dot(direction, end_direction) >= 0.0);
  }
  // A span over π: inside unless strictly within the missing part, which is shorter than π.
  return !(cross(end_direction, direction) > 0.0 && cross(direction, start_direction) > 0.0);
}

Vec2 ArcFrame::nearest(Vec2 p) const noexcept {
  if (p != center) {
    // Halved where the difference overflows: the direction is the same, and halving such huge
    // values is exact.
    const Vec2 offset = p - center;
    const Vec2 direction =
        is_finite(offset) ? normalized(offset) : normalized(p * 0.5 - center * 0.5);
    if (contains(direction)) return center + direction * radius;
  }
  const Vec2 to_start = p - start_point;
  const Vec2 to_end = p - end_point;
  if (is_finite(to_start) && is_finite(to_end)) {
    return not_longer(to_start, to_end) ? start_point : end_point;
  }
  return not_longer(p * 0.5 - start_point * 0.5, p * 0.5 - end_point * 0.5) ? start_point
                                                                            : end_point;
}

ArcFrame make_arc_frame(const char* function, const Arc& arc) {
  require_finite(function, "arc.center", arc.center);
  require_positive(function, "arc.radius", arc.radius);
  require_finite(function, "arc.start_angle", arc.start_angle);
  require_finite(function, "arc.end_angle", arc.end_angle);
  // The full-circle allowance below grows with the angles (4 ulps of the larger); at 2^40 rad it
  // is 2^-10 rad, beyond it would let a span far over 2π pass as a full circle (at 1e45 rad, a
  // span of 1e29). No arc needs more than ±2^40 rad (1.7e11 turns) to say where it starts.
  constexpr const char* kAngleBound = "must lie in [-2^40, 2^40] radians (1.0995e12)";
  require_that(std::abs(arc.start_angle) <= kLargestArcAngle, function, "arc.start_angle",
               arc.start_angle, kAngleBound);
  require_that(std::abs(arc.end_angle) <= kLargestArcAngle, function, "arc.end_angle",
               arc.end_angle, kAngleBound);
  // Every point of the circle must be a finite position, or its touched points could not be
  // reported.
  const double reach = std::max(std::abs(arc.center.x), std::abs(arc.center.y)) + arc.radius;
  require_that(std::isfinite(reach), function, "arc.radius", arc.radius,
               "the arc's circle must lie within the double range (|center| + radius finite)");
  double span = arc.end_angle - arc.start_angle;
  // end = start + 2π computed in doubles can overshoot 2π by the rounding of the larger angle;
  // that is a full circle, not an error.
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const double rounding = 4.0 * std::numeric_limits<double>::epsilon() *
                          std::max({std::abs(arc.start_angle), std::abs(arc.end_angle), kTwoPi});
  if (span > kTwoPi && span <= kTwoPi + rounding) span = kTwoPi;
  require_in_range(function, "arc.end_angle - arc.start_angle", span, 0.0, 2.0 * std::numbers::pi,
                   "the span must lie in [0, 2*pi]");
  ArcFrame frame;
  frame.center = arc.center;
  frame.radius = arc.radius;
  frame.span = span;
  frame.start_direction = {std::cos(arc.start_angle), std::sin(arc.start_angle)};
  frame.end_direction = {std::cos(arc.end_angle), std::sin(arc.end_angle)};
  frame.start_point = arc.center + frame.start_direction * arc.radius;
  frame.end_point = arc.center + frame.end_direction * arc.radius;
  return frame;
}

}  // namespace carom::detail
