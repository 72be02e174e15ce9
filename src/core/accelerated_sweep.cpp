// Time of impact under a constant acceleration: each gap a polynomial in time, closed by
// gap_polynomial.hpp (docs/derivation.md, "Gaps that are polynomials in time").
#include "accelerated_sweep.hpp"

#include <algorithm>
#include <cmath>

#include "exact_range.hpp"
#include "gap_polynomial.hpp"
#include "segment_frame.hpp"
#include "static_query.hpp"
#include "validate.hpp"

namespace carom {
namespace detail {
namespace {

// The earliest approaching contact found so far with a static shape, in real time.
struct Candidate {
  bool found = false;
  double t = 0.0;
  Vec2 point;   // the touched point of the shape
  Vec2 normal;  // unit, from the ball's centre towards point
};

void keep_earliest(Candidate& best, double t, Vec2 point, Vec2 normal) {
  if (!best.found || t < best.t) best = {true, t, point, normal};
}

// The first contact with a fixed point.
void point_contact(const StaticQuery& query, Vec2 point, Candidate& best) {
  const Path path = query.path_from(point);
  if (path.s == Vec2{}) {
    // A centre exactly on the point has no side to move away to: any motion deepens it.
    if (query.moves()) keep_earliest(best, 0.0, point, query.heading_at(0.0));
    return;
  }
  const GapClosings closings = query.closings(
      outside_circle(path, query.scaled_radius(), query.scaled_growth()), AtStart::counts);
  if (closings.count == 0) return;
  const double t = query.real_time(closings.t[0]);
  const Vec2 at = query.center_at(t);
  keep_earliest(best, t, point,
                direction_or(point - at, -path.at(closings.t[0]), query.heading_at(t)));
}

Impact finish_static(const Ball& ball, const Motion& motion, Vec2 nearest, const Candidate& best) {
  Impact out;
  out.overlapping = strictly_within_distance(nearest - ball.center, ball.radius);
  if (best.found) {
    out.hit = true;
    out.t = best.t;
    out.a_at = position_at(ball.center, motion, best.t);
    out.b_at = best.point;
    out.point = best.point;
    out.normal = best.normal;
    return out;
  }
  out.a_at = ball.center;
  out.b_at = nearest;
  out.point = nearest;
  out.normal = direction_or(nearest - ball.center, nearest * 0.5 - ball.center * 0.5, Vec2{});
  return out;
}

// The ball's contacts with the segment's interior, from either side: the signed distance of its
// centre from the line is a quadratic in time, and each side's gap (distance − radius) closes
// at most once. The side the centre starts on counts a touch at the start; the far side is
// reached only round an end (thrown past it and falling back onto the segment, say).
void segment_interior(const StaticQuery& query, const Segment& segment, Candidate& best) {
  const Vec2 along = query.scaled_offset(segment.b, segment.a);
  const double length_sq = length_squared(along);
  // A segment this short against the ball or the distance: its ends decide.
  if (!(length_sq > 0x1p-1000)) return;
  const Vec2 normal = left_normal(along) / std::sqrt(length_sq);
  const Path path = query.path_from(segment.a);
  const double radius = query.scaled_radius();
  const double h = dot(path.s, normal);
  if (h == 0.0) {
    // A centre exactly on the line, within the segment: no side to move away to.
    const double fraction = dot(path.s, along) / length_sq;
    if (fraction >= 0.0 && fraction <= 1.0 && query.moves()) {
      keep_earliest(best, 0.0, query.ball().center, query.heading_at(0.0));
    }
    return;
  }
  const double side = h > 0.0 ? 1.0 : -1.0;
  for (const double facing : {side, -side}) {
    GapPolynomial gap;
    gap.c[0] = facing * h - radius;
    gap.weight[0] = abs_dot(path.s, normal) + radius;
    gap.c[1] = facing * dot(path.u, normal) - query.scaled_growth();
    gap.weight[1] = abs_dot(path.u, normal) + query.scaled_growth();
    gap.c[2] = facing * 0.5 * dot(path.a, normal);
    gap.weight[2] = 0.5 * abs_dot(path.a, normal);
    const GapClosings closings =
        query.closings(gap, facing == side ? AtStart::counts : AtStart::ignored);
    if (closings.count == 0) continue;
    const double scaled_t = closings.t[0];
    const double fraction = dot(path.at(scaled_t), along) / length_sq;
    if (!(fraction >= 0.0 && fraction <= 1.0)) continue;  // past an end: the end decides
    const double t = query.real_time(scaled_t);
    const Vec2 outward = normal * facing;  // from the line towards the centre
    keep_earliest(best, t, point_on_segment(segment, fraction), -outward);
  }
}

// The ball's contacts with an arc's interior (its ends are points): the centre enters the circle
// of radius arc + ball from outside, or reaches the circle of radius arc − ball from inside (a
// ball in a bowl), or, for a ball larger than the arc's radius, enters the circle of radius
// ball − arc and touches the arc across its centre; each where the touched point lies within the
// span. A quartic closes at most twice, and the first closing within the span counts.
void arc_interior(const StaticQuery& query, const ArcFrame& arc, Candidate& best) {
  const Path path = query.path_from(arc.center);
  const double arc_radius = query.distance(arc.radius);
  const double radius = query.scaled_radius();
  // side: +1 where the touched point lies on the ball's side of the arc's centre, −1 across it.
  const auto consider = [&](const GapClosings& closings, double side) {
    for (std::size_t k = 0; k < closings.count; ++k) {
      const Vec2 offset = path.at(closings.t[k]);  // from the arc's centre, scaled
      const double t = query.real_time(closings.t[k]);
      const Vec2 direction = direction_or(offset, query.heading_at(t), Vec2{1.0, 0.0}) * side;
      if (!arc.contains(direction)) continue;
      const Vec2 point = arc.center + direction * arc.radius;
      const Vec2 center = query.center_at(t);
      keep_earliest(best, t, point, direction_or(point - center, -direction * side, direction));
      return;
    }
  };
  // A start beyond a circle, on its other side, is no contact with the arc (`touching`), unless
  // the centre lies nearer that circle than the other: the ball then overlaps the arc's circle
  // from that side (placed against it, to a rounding), and pressing on counts at once, as it does
  // on a straight line. The circles' middle is arc_radius for a ball smaller than the arc, and
  // the ball's radius for a larger one.
  const double growth = query.scaled_growth();
  const double middle = std::max(arc_radius, radius);
  const bool nearer_outside = dot(path.s, path.s) >= middle * middle;
  const auto start = [](bool nearer) { return nearer ? AtStart::counts : AtStart::touching; };
  consider(query.closings(outside_circle(path, arc_radius + radius, growth), start(nearer_outside)),
           1.0);
  const double inner = arc_radius - radius;
  if (inner > 0.0) {
    // (The inner circle shrinks as the ball grows.)
    consider(query.closings(inside_circle(path, inner, -growth), start(!nearer_outside)), 1.0);
  } else if (inner < 0.0) {
    consider(query.closings(outside_circle(path, -inner, growth), start(!nearer_outside)), -1.0);
  } else if (query.moves() && within_distance(path.s, std::ldexp(arc_radius, -40))) {
    // A ball exactly as large as the arc's circle, its centre on the arc's centre (or a rounding
    // off it): it fills the circle, and any motion presses it into the wall where it moves to.
    const Vec2 direction = query.heading_at(0.0);
    if (arc.contains(direction))
      keep_earliest(best, 0.0, arc.center + direction * arc.radius, direction);
  }
}

}  // namespace

Vec2 position_at(Vec2 p, const Motion& motion, double t) {
  // (½·t first, then t: t² alone may overflow where the product does not, and a zero component
  // times an overflowed t² would be NaN.)
  const Vec2 at = p + motion.velocity * t + (motion.acceleration * (0.5 * t)) * t;
  if (is_finite(at)) [[likely]]
    return at;
  const Vec2 halves =
      (p * 0.5 + motion.velocity * (0.5 * t) + (motion.acceleration * (0.25 * t)) * t) * 2.0;
  // Beyond the double range: the term of the highest power that overflowed decides the sign
  // (where two terms overflowed with opposite signs their sum is NaN).
  const auto beyond = [](double value, double acceleration, double velocity) {
    if (!std::isnan(value)) return value;
    return std::copysign(HUGE_VAL, acceleration != 0.0 ? acceleration : velocity);
  };
  return {beyond(halves.x, motion.acceleration.x, motion.velocity.x),
          beyond(halves.y, motion.acceleration.y, motion.velocity.y)};
}

Impact accelerated_ball_point(const Ball& a, const Motion& motion_a, Vec2 point, double horizon) {
  const StaticQuery query(a, motion_a, horizon, offset_exponent(a.center, point));
  Candidate best;
  point_contact(query, point, best);
  return finish_static(a, motion_a, point, best);
}

Impact accelerated_ball_segment(const Ball& a, const Motion& motion_a, const Segment& segment,
                                double horizon) {
  const int length =
      std::max({offset_exponent(a.center, segment.a), offset_exponent(a.center, segment.b),
                offset_exponent(segment.b, segment.a)});
  const StaticQuery query(a, motion_a, horizon, length);
  Candidate best;
  if (segment.a != segment.b) segment_interior(query, segment, best);
  point_contact(query, segment.a, best);
  if (segment.b != segment.a) point_contact(query, segment.b, best);
  return finish_static(a, motion_a, nearest_on_segment(segment, a.center), best);
}

Impact accelerated_ball_arc(const Ball& a, const Motion& motion_a, const ArcFrame& arc,
                            double horizon) {
  const int length = std::max({offset_exponent(a.center, arc.center), exponent_of(arc.radius) + 1,
                               offset_exponent(a.center, arc.start_point),
                               offset_exponent(a.center, arc.end_point)});
  const StaticQuery query(a, motion_a, horizon, length);
  Candidate best;
  if (arc.span > 0.0) arc_interior(query, arc, best);
  point_contact(query, arc.start_point, best);
  if (arc.end_point != arc.start_point) point_contact(query, arc.end_point, best);
  return finish_static(a, motion_a, arc.nearest(a.center), best);
}

Impact accelerated_ball_ball(const Ball& a, const Motion& motion_a, const Ball& b,
                             const Motion& motion_b, double horizon) {
  // Relative motion: A moves by the difference of the motions, B stands still.
  const Exact velocity = difference(motion_a.velocity, motion_b.velocity);
  const Exact acceleration = difference(motion_a.acceleration, motion_b.acceleration);
  const Growth growth = sum_of(motion_a.growth, motion_b.growth);
  const int length =
      std::max(offset_exponent(a.center, b.center), exponent_of(std::max(a.radius, b.radius)) + 1);
  const Scale scale = make_scale(length, fastest(velocity, growth), acceleration);
  const Path path{scale.offset(a.center, b.center), scale.velocity(velocity),
                  scale.acceleration(acceleration)};
  const double reach = scale.distance(a.radius) + scale.distance(b.radius);
  const bool moving = velocity.v != Vec2{} || acceleration.v != Vec2{} || growth.value != 0.0;
  Impact out;
  out.overlapping = strictly_within_distance(path.s, reach);
  double scaled_t = 0.0;
  if (path.s == Vec2{}) {
    // Coincident centres: no line of centres and no side to separate to.
    out.hit = moving;
  } else {
    const GapClosings closings = gap_closings(outside_circle(path, reach, scale.speed(growth)),
                                              scale.to_scaled_time(horizon), AtStart::counts);
    out.hit = closings.count > 0;
    if (out.hit) scaled_t = closings.t[0];
  }
  out.t = out.hit ? std::min(scale.from_scaled_time(scaled_t), horizon) : 0.0;
  out.a_at = position_at(a.center, motion_a, out.t);
  out.b_at = position_at(b.center, motion_b, out.t);
  const Vec2 at = path.at(scaled_t);  // A's centre from B's, scaled
  out.normal = direction_or(-at, -(path.u + path.a * scaled_t), -path.a);
  const double radius_a = a.radius + motion_a.growth * out.t;
  const double grown_share = radius_a / (radius_a + b.radius + motion_b.growth * out.t);
  const double share = std::isfinite(grown_share) ? grown_share : a.radius / (a.radius + b.radius);
  const Vec2 between = out.b_at - out.a_at;
  out.point = is_finite(between) ? out.a_at + between * share : out.a_at + out.normal * a.radius;
  return out;
}

}  // namespace detail

namespace {

void validate_motion(const char* function, const Ball& a, const Motion& motion, double horizon) {
  detail::require_finite(function, "a.center", a.center);
  detail::require_positive(function, "a.radius", a.radius);
  detail::require_finite(function, "motion_a.velocity", motion.velocity);
  detail::require_finite(function, "motion_a.acceleration", motion.acceleration);
  detail::require_finite(function, "motion_a.growth", motion.growth);
  detail::require_non_negative(function, "motion_a.growth", motion.growth);
  detail::require_non_negative(function, "horizon", horizon);
}

}  // namespace

Impact time_of_impact_ball_ball(const Ball& a, const Motion& motion_a, const Ball& b,
                                const Motion& motion_b, double horizon) {
  constexpr const char* kFunction = "time_of_impact_ball_ball";
  validate_motion(kFunction, a, motion_a, horizon);
  detail::require_finite(kFunction, "b.center", b.center);
  detail::require_positive(kFunction, "b.radius", b.radius);
  detail::require_finite(kFunction, "motion_b.velocity", motion_b.velocity);
  detail::require_finite(kFunction, "motion_b.acceleration", motion_b.acceleration);
  detail::require_finite(kFunction, "motion_b.growth", motion_b.growth);
  detail::require_non_negative(kFunction, "motion_b.growth", motion_b.growth);
  if (motion_a.acceleration == Vec2{} && motion_b.acceleration == Vec2{} &&
      motion_a.growth == 0.0 && motion_b.growth == 0.0) {
    return time_of_impact_ball_ball(a, motion_a.velocity, b, motion_b.velocity, horizon);
  }
  return detail::accelerated_ball_ball(a, motion_a, b, motion_b, horizon);
}

Impact time_of_impact_ball_point(const Ball& a, const Motion& motion_a, Vec2 point,
                                 double horizon) {
  constexpr const char* kFunction = "time_of_impact_ball_point";
  validate_motion(kFunction, a, motion_a, horizon);
  detail::require_finite(kFunction, "point", point);
  if (motion_a.acceleration == Vec2{} && motion_a.growth == 0.0) {
    return time_of_impact_ball_point(a, motion_a.velocity, point, horizon);
  }
  return detail::accelerated_ball_point(a, motion_a, point, horizon);
}

Impact time_of_impact_ball_segment(const Ball& a, const Motion& motion_a, const Segment& segment,
                                   double horizon) {
  constexpr const char* kFunction = "time_of_impact_ball_segment";
  validate_motion(kFunction, a, motion_a, horizon);
  detail::require_finite(kFunction, "segment.a", segment.a);
  detail::require_finite(kFunction, "segment.b", segment.b);
  if (motion_a.acceleration == Vec2{} && motion_a.growth == 0.0) {
    return time_of_impact_ball_segment(a, motion_a.velocity, segment, horizon);
  }
  return detail::accelerated_ball_segment(a, motion_a, segment, horizon);
}

Impact time_of_impact_ball_arc(const Ball& a, const Motion& motion_a, const Arc& arc,
                               double horizon) {
  constexpr const char* kFunction = "time_of_impact_ball_arc";
  validate_motion(kFunction, a, motion_a, horizon);
  const detail::ArcFrame frame = detail::make_arc_frame(kFunction, arc);
  if (motion_a.acceleration == Vec2{} && motion_a.growth == 0.0) {
    return time_of_impact_ball_arc(a, motion_a.velocity, arc, horizon);
  }
  return detail::accelerated_ball_arc(a, motion_a, frame, horizon);
}

}  // namespace carom
