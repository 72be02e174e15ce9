// Time of impact of a moving ball. Derivations: docs/derivation.md.
#include "carom/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arc_frame.hpp"
#include "circle_crossing.hpp"
#include "exact_range.hpp"
#include "segment_frame.hpp"
#include "validate.hpp"

namespace carom {
namespace {

using detail::ArcFrame;
using detail::direction_at;
using detail::entry_crossing;
using detail::exit_crossing;
using detail::nearest_on_segment;
using detail::offset_motion;
using detail::ScaledMotion;
using detail::segment_fraction;
using detail::segment_frame;
using detail::SegmentFrame;

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

// p + v·t. Where v·t overflows but the sum is representable, it is taken of halves (exact for
// such huge values); ±inf only when the true position lies beyond the double range.
[[gnu::noinline, gnu::cold]] Vec2 advance_halved(Vec2 p, Vec2 v, double t) {
  return (p * 0.5 + (v * 0.5) * t) * 2.0;
}

Vec2 advance(Vec2 p, Vec2 v, double t) {
  const Vec2 at = p + v * t;
  if (is_finite(at)) [[likely]]
    return at;
  return advance_halved(p, v, t);
}

// The unit vector from one finite point to another, even where their difference overflows.
Vec2 direction_between(Vec2 from, Vec2 to) {
  const Vec2 difference = to - from;
  if (is_finite(difference)) return normalized(difference);
  return normalized(to * 0.5 - from * 0.5);
}

// A normal computed from positions, or, where those overflowed, the fallback from the motion.
Vec2 finite_or(Vec2 normal, Vec2 fallback) {
  return is_finite(normal) && normal != Vec2{} ? normal : fallback;
}

// A ball touching or overlapping the shape at its nearest point and moving towards it is in
// contact now (t = 0). Moving away from that point, it may still meet another part later.
// `gap` runs from the centre to the nearest point; callers that know its direction exactly (the
// normal of a segment's interior) pass it computed from that, so that a ball sliding along a
// wall is not seen approaching it by a rounding of the nearest point.
void contact_at_start(const Ball& ball, Vec2 velocity, Vec2 nearest, Vec2 gap, Candidate& best) {
  if (!detail::within_distance(gap, ball.radius)) return;
  // A centre exactly on the shape has no side to move away to: any motion deepens the contact.
  if (gap == Vec2{}) {
    if (velocity != Vec2{}) keep_earliest(best, 0.0, nearest, normalized(velocity));
    return;
  }
  if (detail::dot_positive(velocity, gap)) keep_earliest(best, 0.0, nearest, normalized(gap));
}

// The ball's first approaching contact with a fixed point, in [0, horizon].
void contact_with_point(const Ball& ball, Vec2 velocity, Vec2 point, double horizon,
                        Candidate& best) {
  const ScaledMotion motion = offset_motion(ball.center, point, velocity, ball.radius, 0.0);
  const detail::Crossing crossing = entry_crossing(motion, horizon);
  if (!crossing.found) return;
  const Vec2 center_at = ball.center + velocity * crossing.t;
  // Where the contact's offset (the radius) is below the rounding of the positions, neither
  // positions nor the scaled motion resolve it: the ball then meets the point head on.
  keep_earliest(best, crossing.t, point,
                finite_or(normalized(point - center_at),
                          finite_or(-direction_at(motion, crossing.t), normalized(velocity))));
}

// The ball's first contact with the segment's interior, from the side its centre is on.
void contact_with_segment_side_rescaled(const Ball& ball, Vec2 velocity, const Segment& segment,
                                        double horizon, Candidate& best);

void contact_with_segment_side(const Ball& ball, Vec2 velocity, const Segment& segment,
                               double horizon, Candidate& best) {
  const Vec2 along = segment.b - segment.a;
  if (!(detail::vector_in_range(along) && detail::vector_in_range(ball.center - segment.a) &&
        detail::vector_in_range(velocity) && detail::square_in_range(ball.radius * ball.radius))) {
    contact_with_segment_side_rescaled(ball, velocity, segment, horizon, best);
    return;
  }
  const double length_sq = length_squared(along);
  const double len = length(along);
  Vec2 outward = left_normal(along) / len;  // unit normal pointing to the ball's side
  double distance = cross(along, ball.center - segment.a) / len;
  if (distance < 0.0) {
    outward = -outward;
    distance = -distance;
  }
  const double normal_speed = dot(velocity, outward);
  if (!(normal_speed < 0.0)) return;
  if (!(distance > ball.radius)) {
    // Touching the interior by this measure and approaching: a contact now. contact_at_start
    // measures the gap from the nearest point, which rounds differently and can see the ball a
    // rounding clear of the line when this sees it touching; without this both would pass it
    // over and the ball would cross the wall (found by the world fuzzer).
    const double foot = dot(ball.center - segment.a, along) / length_sq;
    if (foot >= 0.0 && foot <= 1.0) {
      keep_earliest(best, 0.0, ball.center - outward * distance, -outward);
    }
    return;
  }
  const double t = (distance - ball.radius) / -normal_speed;
  if (!(t <= horizon)) return;
  const Vec2 point = ball.center + velocity * t - outward * ball.radius;
  const double along_fraction = dot(point - segment.a, along) / length_sq;
  if (!(along_fraction >= 0.0 && along_fraction <= 1.0)) return;  // NaN too: no hit
  keep_earliest(best, t, point, -outward);
}

// The segment's interior for any finite input: the formulas of contact_with_segment_side in the
// scaled frame, t scaled back by the ratio of the length and speed scales.
void contact_with_segment_side_rescaled(const Ball& ball, Vec2 velocity, const Segment& segment,
                                        double horizon, Candidate& best) {
  const SegmentFrame frame = segment_frame(segment, ball.center, ball.radius);
  const int speed_exponent = detail::exponent_of(velocity);
  const Vec2 u = detail::scaled(velocity, -speed_exponent);
  const double len = length(frame.along);
  if (!(len > 0.0)) return;  // negligible against the distance: its end points decide
  Vec2 outward = left_normal(frame.along) / len;
  double distance = cross(frame.along, frame.offset) / len;
  if (distance < 0.0) {
    outward = -outward;
    distance = -distance;
  }
  const double normal_speed = dot(u, outward);
  if (!(distance > frame.radius && normal_speed < 0.0)) return;
  const double scaled_t = (distance - frame.radius) / -normal_speed;
  const double t = std::ldexp(scaled_t, frame.length_exponent - speed_exponent);
  if (!(t <= horizon)) return;
  const Vec2 touched = frame.offset + u * scaled_t - outward * frame.radius;
  const double along_fraction = dot(touched, frame.along) / length_squared(frame.along);
  if (!(along_fraction >= 0.0 && along_fraction <= 1.0)) return;
  const Vec2 point = segment.a + detail::scaled(touched, frame.length_exponent);
  keep_earliest(best, t, point, -outward);
}

// From p to the segment's nearest point. For an interior nearest point the direction is the
// segment's exact normal (a rounding of the nearest point would tilt it).
Vec2 gap_to_segment(const Segment& segment, Vec2 p, Vec2 nearest) {
  const double fraction = segment_fraction(segment, p);
  if (!(fraction > 0.0 && fraction < 1.0)) return nearest - p;
  const Vec2 along = segment.b - segment.a;
  const Vec2 offset = p - segment.a;
  if (is_finite(along) && is_finite(offset)) {
    const Vec2 normal = left_normal(along) / length(along);
    return normal * -dot(offset, normal);
  }
  const Vec2 half_along = segment.b * 0.5 - segment.a * 0.5;
  const Vec2 normal = left_normal(half_along) / length(half_along);
  return (normal * -dot(p * 0.5 - segment.a * 0.5, normal)) * 2.0;
}

// A ball as large as an arc's circle fills it when its centre is within 2^-kFillingExponent of
// the radius from the arc's centre: far more than the rounding of a placement there, far less
// than any overlap worth the name.
constexpr int kFillingExponent = 40;

// Contacts with the arc's interior: the centre crosses the circle of radius arc + ball from
// outside, or the circle of radius |arc − ball| from inside (or, for a ball larger than the
// arc's radius, enters it from the far side of the arc's centre), with the touched point within
// the arc's span.
void contact_with_arc_interior(const Ball& ball, Vec2 velocity, const ArcFrame& arc, double horizon,
                               Candidate& best) {
  // side: +1 where the touched point lies on the ball's side of the arc's centre, −1 where the
  // ball reaches across it. facing: +1 where the normal (ball to point) points away from the
  // arc's centre (the ball inside the bowl), −1 where it points towards it.
  auto consider = [&](const ScaledMotion& motion, detail::Crossing crossing, double side,
                      double facing) {
    if (!crossing.found) return;
    const Vec2 center_at = ball.center + velocity * crossing.t;
    // Arc centre to ball centre; where even the scaled motion cannot resolve it (an arc far
    // below the rounding of the positions), the ball meets it head on.
    const Vec2 outwards =
        finite_or(direction_at(motion, crossing.t), normalized(velocity) * facing);
    const Vec2 direction = finite_or(normalized(center_at - arc.center), outwards) * side;
    if (!arc.contains(direction)) return;
    const Vec2 point = arc.center + direction * arc.radius;
    keep_earliest(best, crossing.t, point,
                  finite_or(normalized(point - center_at), outwards * facing));
  };
  const ScaledMotion outer =
      offset_motion(ball.center, arc.center, velocity, arc.radius, ball.radius);
  if (!detail::within_distance(outer.s, outer.radius)) {
    consider(outer, entry_crossing(outer, horizon), 1.0, -1.0);
  } else if (!detail::strictly_within_distance(outer.s,
                                               std::ldexp(arc.radius, -outer.length_exponent)) &&
             detail::dot_positive(-outer.s, outer.u)) {
    // On or a rounding inside the circle along which the ball touches the arc's outside (where
    // nearest_free stops it, say), its centre outside the arc's circle, and moving inwards: it
    // touches now. entry_crossing's root is at t <= 0, and contact_at_start's gap to the
    // nearest point may round to just beyond the radius, so neither would report it and the
    // ball would pass into the arc.
    consider(outer, {true, 0.0}, 1.0, -1.0);
  }
  ScaledMotion inner = offset_motion(ball.center, arc.center, velocity, arc.radius, -ball.radius);
  if (inner.radius > 0.0) {
    detail::Crossing leaving = exit_crossing(inner, horizon);
    // On or a rounding past the circle along which the ball touches the arc's inside (where
    // set_position's nearest_free stops it, say), its centre still inside the arc's circle,
    // moving, and its path never back inside that circle: it touches now. Moving outwards,
    // exit_crossing's root is at t <= 0, which it does not report; moving along the circle, or
    // inwards by less than the rounding of the position, the path misses the circle (inside a
    // circle the gap closes at second order: the one place where a graze is a contact). Either
    // way the ball would leave through the arc.
    if (!leaving.found && !detail::strictly_within_distance(inner.s, inner.radius) &&
        detail::strictly_within_distance(inner.s, std::ldexp(arc.radius, -inner.length_exponent)) &&
        inner.u != Vec2{} &&
        !exit_crossing(inner, std::numeric_limits<double>::max()).found) {  // beyond horizon
      leaving = {true, 0.0};
    }
    consider(inner, leaving, 1.0, 1.0);
  } else if (inner.radius < 0.0) {
    inner.radius = -inner.radius;
    consider(inner, entry_crossing(inner, horizon), -1.0, -1.0);
  } else if (inner.u != Vec2{} &&
             detail::within_distance(
                 inner.s, std::ldexp(arc.radius, -inner.length_exponent - kFillingExponent))) {
    // A ball exactly as large as the arc's circle, its centre on the arc's centre (or a
    // rounding off it): it fills the circle, and any motion presses it into the wall at once,
    // where it moves to (a jam, which a world refuses). No circle is left for it to cross.
    const bool outwards = inner.s != Vec2{} && detail::dot_positive(inner.s, inner.u);
    const Vec2 direction = outwards ? direction_at(inner, 0.0) : normalized(velocity);
    if (arc.contains(direction)) {
      keep_earliest(best, 0.0, arc.center + direction * arc.radius, direction);
    }
  }
}

Impact finish_static(const Ball& ball, Vec2 velocity, Vec2 nearest, const Candidate& best) {
  Impact out;
  out.overlapping = detail::strictly_within_distance(nearest - ball.center, ball.radius);
  if (best.found) {
    out.hit = true;
    out.t = best.t;
    out.a_at = advance(ball.center, velocity, best.t);
    out.b_at = best.point;
    out.point = best.point;
    out.normal = best.normal;
    return out;
  }
  out.a_at = ball.center;
  out.b_at = nearest;
  out.point = nearest;
  out.normal = direction_between(ball.center, nearest);
  return out;
}

// Positions, their difference or the sum of radii overflowed: the direction comes from the
// scaled motion instead; a contact point beyond the double range stays infinite.
[[gnu::noinline, gnu::cold]] void normal_from_motion(const ScaledMotion& motion, double radius_a,
                                                     Impact& out) {
  const Vec2 towards_b = -direction_at(motion, out.t);
  out.normal = towards_b == Vec2{} ? normalized(motion.u) : towards_b;
  out.point = out.a_at + out.normal * radius_a;
}

Impact ball_ball(const Names& names, const Ball& a, Vec2 velocity_a, const Ball& b, Vec2 velocity_b,
                 double horizon) {
  validate_moving_ball(names, a, velocity_a, horizon);
  detail::require_finite(names.function, "b.center", b.center);
  detail::require_positive(names.function, "b.radius", b.radius);
  detail::require_finite(names.function, names.velocity_b, velocity_b);

  // Relative motion (the tutorial's v3): A moves by velocity_a − velocity_b, B stands still.
  // Coincident centres count as approaching (see ball_pair_crossing).
  // In the exact range (nearly always) the plain formulas, with one range test for all; the test
  // fails for an overflowed (infinite) difference too, and then the motion is taken of halves.
  const ScaledMotion direct{a.center - b.center, velocity_a - velocity_b, a.radius + b.radius, 0,
                            0};
  const bool plain = detail::in_exact_range(direct.s, direct.u, direct.radius);
  const ScaledMotion motion = plain ? direct
                                    : detail::ball_pair_motion(a.center, velocity_a, a.radius,
                                                               b.center, velocity_b, b.radius);
  detail::Crossing crossing;
  if (!plain) {
    crossing = detail::ball_pair_crossing(motion, horizon);
  } else if (motion.s == Vec2{}) {
    crossing = {motion.u != Vec2{}, 0.0};
  } else {
    crossing = detail::entry_crossing_in_range(motion.s, motion.u, motion.radius, horizon);
  }

  Impact out;
  out.overlapping = plain ? length_squared(motion.s) < motion.radius * motion.radius
                          : detail::strictly_within_distance(motion.s, motion.radius);
  out.hit = crossing.found;
  out.t = crossing.found ? crossing.t : 0.0;
  out.a_at = advance(a.center, velocity_a, out.t);
  out.b_at = advance(b.center, velocity_b, out.t);
  const Vec2 between = out.b_at - out.a_at;
  const double reach = a.radius + b.radius;
  out.normal = between == Vec2{} ? normalized(motion.u) : normalized(between);
  out.point = out.a_at + between * (a.radius / reach);
  if (!is_finite(out.normal) || !is_finite(out.point) || !std::isfinite(reach)) [[unlikely]] {
    normal_from_motion(motion, a.radius, out);
  }
  return out;
}

Impact ball_point(const Names& names, const Ball& a, Vec2 velocity_a, Vec2 point, double horizon) {
  validate_moving_ball(names, a, velocity_a, horizon);
  detail::require_finite(names.function, "point", point);
  Candidate best;
  // As for every static shape: a centre exactly on the point and moving is in contact now.
  contact_at_start(a, velocity_a, point, point - a.center, best);
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
