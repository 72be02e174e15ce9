// Time of impact of a moving ball. Derivations: docs/derivation.md.
#include "carom/sweep.hpp"

#include <algorithm>
#include <numbers>

#include "arc_frame.hpp"
#include "circle_crossing.hpp"
#include "validate.hpp"

namespace carom {
namespace {

using detail::ArcFrame;
using detail::entry_crossing;
using detail::exit_crossing;

// Argument names differ between the time form and the step form; messages use the caller's.
struct Names {
  const char* function;
  const char* velocity_a;
  const char* velocity_b;
};

constexpr Names kTimeBallBall{"time_of_impact_ball_ball", "velocity_a", "velocity_b"};
constexpr Names kTimeBallPoint{"time_of_impact_ball_point", "velocity_a", ""};
constexpr Names kTimeBallSegment{"time_of_impact_ball_segment", "velocity_a", ""};
constexpr Names kTimeBallArc{"time_of_impact_ball_arc", "velocity_a", ""};
constexpr Names kStepBallBall{"sweep_ball_ball", "move_a", "move_b"};
constexpr Names kStepBallPoint{"sweep_ball_point", "move_a", ""};
constexpr Names kStepBallSegment{"sweep_ball_segment", "move_a", ""};
constexpr Names kStepBallArc{"sweep_ball_arc", "move_a", ""};

void validate_moving_ball(const Names& names, const Ball& a, Vec2 velocity_a, double horizon) {
  detail::require_finite(names.function, "a.center", a.center);
  detail::require_positive(names.function, "a.radius", a.radius);
  detail::require_finite(names.function, names.velocity_a, velocity_a);
  detail::require_non_negative(names.function, "horizon", horizon);
}

// The earliest approaching contact found so far with a static shape.
struct Candidate {
  bool found = false;
  double t = 0.0;
  Vec2 point;   // the touched point of the shape
  Vec2 normal;  // unit, from the ball's centre towards point
};

void keep_earliest(Candidate& best, double t, Vec2 point, Vec2 normal) {
  if (!best.found || t < best.t) best = {true, t, point, normal};
}

// A ball touching or overlapping the shape at its nearest point and moving towards it is in
// contact now (t = 0). Moving away from that point, it may still meet another part later.
// `gap` runs from the centre to the nearest point; callers that know its direction exactly (the
// normal of a segment's interior) pass it computed from that, so that a ball sliding along a
// wall is not seen approaching it by a rounding of the nearest point.
void contact_at_start(const Ball& ball, Vec2 velocity, Vec2 nearest, Vec2 gap, Candidate& best) {
  const double gap_sq = length_squared(gap);
  if (gap_sq > ball.radius * ball.radius) return;
  // A centre exactly on the shape has no side to move away to: any motion deepens the contact.
  if (gap_sq == 0.0) {
    if (velocity != Vec2{}) keep_earliest(best, 0.0, nearest, normalized(velocity));
    return;
  }
  if (dot(velocity, gap) > 0.0) keep_earliest(best, 0.0, nearest, normalized(gap));
}

// The ball's first approaching contact with a fixed point, in [0, horizon].
void contact_with_point(const Ball& ball, Vec2 velocity, Vec2 point, double horizon,
                        Candidate& best) {
  const detail::Crossing crossing =
      entry_crossing(ball.center - point, velocity, ball.radius, horizon);
  if (!crossing.found) return;
  const Vec2 center_at = ball.center + velocity * crossing.t;
  keep_earliest(best, crossing.t, point, normalized(point - center_at));
}

// The ball's first contact with the segment's interior, from the side its centre is on.
void contact_with_segment_side(const Ball& ball, Vec2 velocity, const Segment& segment,
                               double horizon, Candidate& best) {
  const Vec2 along = segment.b - segment.a;
  const double length_sq = length_squared(along);
  const double len = length(along);
  Vec2 outward = left_normal(along) / len;  // unit normal pointing to the ball's side
  double distance = cross(along, ball.center - segment.a) / len;
  if (distance < 0.0) {
    outward = -outward;
    distance = -distance;
  }
  const double normal_speed = dot(velocity, outward);
  if (!(distance > ball.radius && normal_speed < 0.0)) return;
  const double t = (distance - ball.radius) / -normal_speed;
  if (!(t <= horizon)) return;
  const Vec2 point = ball.center + velocity * t - outward * ball.radius;
  const double along_fraction = dot(point - segment.a, along) / length_sq;
  if (along_fraction < 0.0 || along_fraction > 1.0) return;
  keep_earliest(best, t, point, -outward);
}

Vec2 nearest_on_segment(const Segment& segment, Vec2 p) {
  const Vec2 along = segment.b - segment.a;
  const double length_sq = length_squared(along);
  if (length_sq == 0.0) return segment.a;
  const double fraction = std::clamp(dot(p - segment.a, along) / length_sq, 0.0, 1.0);
  return segment.a + along * fraction;
}

// From p to the segment's nearest point. For an interior nearest point the direction is the
// segment's exact normal (a rounding of the nearest point would tilt it).
Vec2 gap_to_segment(const Segment& segment, Vec2 p, Vec2 nearest) {
  const Vec2 along = segment.b - segment.a;
  const double length_sq = length_squared(along);
  const double fraction = length_sq > 0.0 ? dot(p - segment.a, along) / length_sq : 0.0;
  if (!(fraction > 0.0 && fraction < 1.0)) return nearest - p;
  const Vec2 normal = left_normal(along) / length(along);
  return normal * -dot(p - segment.a, normal);
}

// Contacts with the arc's interior: the centre crosses the circle of radius arc + ball from
// outside, or the circle of radius |arc − ball| from inside (or, for a ball larger than the
// arc's radius, enters it from the far side of the arc's centre), with the touched point within
// the arc's span.
void contact_with_arc_interior(const Ball& ball, Vec2 velocity, const ArcFrame& arc, double horizon,
                               Candidate& best) {
  const Vec2 s = ball.center - arc.center;
  auto consider = [&](detail::Crossing crossing, double side) {
    if (!crossing.found) return;
    const Vec2 center_at = ball.center + velocity * crossing.t;
    const Vec2 direction = normalized(center_at - arc.center) * side;
    if (!arc.contains(direction)) return;
    const Vec2 point = arc.center + direction * arc.radius;
    keep_earliest(best, crossing.t, point, normalized(point - center_at));
  };
  const double outer = arc.radius + ball.radius;
  if (length_squared(s) > outer * outer) {
    consider(entry_crossing(s, velocity, outer, horizon), 1.0);
  }
  const double inner = arc.radius - ball.radius;
  if (inner > 0.0) {
    consider(exit_crossing(s, velocity, inner, horizon), 1.0);
  } else if (inner < 0.0) {
    consider(entry_crossing(s, velocity, -inner, horizon), -1.0);
  }
}

Impact finish_static(const Ball& ball, Vec2 velocity, Vec2 nearest, const Candidate& best) {
  Impact out;
  out.overlapping = length_squared(nearest - ball.center) < ball.radius * ball.radius;
  if (best.found) {
    out.hit = true;
    out.t = best.t;
    out.a_at = ball.center + velocity * best.t;
    out.b_at = best.point;
    out.point = best.point;
    out.normal = best.normal;
    return out;
  }
  out.a_at = ball.center;
  out.b_at = nearest;
  out.point = nearest;
  out.normal = normalized(nearest - ball.center);
  return out;
}

Impact ball_ball(const Names& names, const Ball& a, Vec2 velocity_a, const Ball& b, Vec2 velocity_b,
                 double horizon) {
  validate_moving_ball(names, a, velocity_a, horizon);
  detail::require_finite(names.function, "b.center", b.center);
  detail::require_positive(names.function, "b.radius", b.radius);
  detail::require_finite(names.function, names.velocity_b, velocity_b);

  // Relative motion (the tutorial's v3): A moves by velocity_a − velocity_b, B stands still.
  const Vec2 s = a.center - b.center;
  const Vec2 u = velocity_a - velocity_b;
  const double reach = a.radius + b.radius;
  // Coincident centres have no line of centres and no side to separate to: any relative
  // motion deepens the overlap, so it counts as approaching.
  const detail::Crossing crossing =
      s == Vec2{} ? detail::Crossing{u != Vec2{}, 0.0} : entry_crossing(s, u, reach, horizon);

  Impact out;
  out.overlapping = length_squared(s) < reach * reach;
  out.hit = crossing.found;
  out.t = crossing.found ? crossing.t : 0.0;
  out.a_at = a.center + velocity_a * out.t;
  out.b_at = b.center + velocity_b * out.t;
  const Vec2 between = out.b_at - out.a_at;
  out.normal = between == Vec2{} ? normalized(u) : normalized(between);
  out.point = out.a_at + between * (a.radius / reach);
  return out;
}

Impact ball_point(const Names& names, const Ball& a, Vec2 velocity_a, Vec2 point, double horizon) {
  validate_moving_ball(names, a, velocity_a, horizon);
  detail::require_finite(names.function, "point", point);
  Candidate best;
  contact_with_point(a, velocity_a, point, horizon, best);
  return finish_static(a, velocity_a, point, best);
}

Impact ball_segment(const Names& names, const Ball& a, Vec2 velocity_a, const Segment& segment,
                    double horizon) {
  validate_moving_ball(names, a, velocity_a, horizon);
  detail::require_finite(names.function, "segment.a", segment.a);
  detail::require_finite(names.function, "segment.b", segment.b);
  const Vec2 nearest = nearest_on_segment(segment, a.center);
  Candidate best;
  contact_at_start(a, velocity_a, nearest, gap_to_segment(segment, a.center, nearest), best);
  if (segment.a != segment.b) contact_with_segment_side(a, velocity_a, segment, horizon, best);
  contact_with_point(a, velocity_a, segment.a, horizon, best);
  contact_with_point(a, velocity_a, segment.b, horizon, best);
  return finish_static(a, velocity_a, nearest, best);
}

Impact ball_arc(const Names& names, const Ball& a, Vec2 velocity_a, const Arc& arc,
                double horizon) {
  validate_moving_ball(names, a, velocity_a, horizon);
  const ArcFrame frame = detail::make_arc_frame(names.function, arc);
  const Vec2 nearest = frame.nearest(a.center);
  Candidate best;
  contact_at_start(a, velocity_a, nearest, nearest - a.center, best);
  if (frame.span > 0.0) contact_with_arc_interior(a, velocity_a, frame, horizon, best);
  contact_with_point(a, velocity_a, frame.start_point, horizon, best);
  contact_with_point(a, velocity_a, frame.end_point, horizon, best);
  return finish_static(a, velocity_a, nearest, best);
}

}  // namespace

Impact time_of_impact_ball_ball(const Ball& a, Vec2 velocity_a, const Ball& b, Vec2 velocity_b,
                                double horizon) {
  return ball_ball(kTimeBallBall, a, velocity_a, b, velocity_b, horizon);
}

Impact time_of_impact_ball_point(const Ball& a, Vec2 velocity_a, Vec2 point, double horizon) {
  return ball_point(kTimeBallPoint, a, velocity_a, point, horizon);
}

Impact time_of_impact_ball_segment(const Ball& a, Vec2 velocity_a, const Segment& segment,
                                   double horizon) {
  return ball_segment(kTimeBallSegment, a, velocity_a, segment, horizon);
}

Impact time_of_impact_ball_arc(const Ball& a, Vec2 velocity_a, const Arc& arc, double horizon) {
  return ball_arc(kTimeBallArc, a, velocity_a, arc, horizon);
}

Impact sweep_ball_ball(const Ball& a, Vec2 move_a, const Ball& b, Vec2 move_b) {
  return ball_ball(kStepBallBall, a, move_a, b, move_b, 1.0);
}

Impact sweep_ball_point(const Ball& a, Vec2 move_a, Vec2 point) {
  return ball_point(kStepBallPoint, a, move_a, point, 1.0);
}

Impact sweep_ball_segment(const Ball& a, Vec2 move_a, const Segment& segment) {
  return ball_segment(kStepBallSegment, a, move_a, segment, 1.0);
}

Impact sweep_ball_arc(const Ball& a, Vec2 move_a, const Arc& arc) {
  return ball_arc(kStepBallArc, a, move_a, arc, 1.0);
}

}  // namespace carom
