// When a moving ball overlaps a sensor's shape: the region within the ball's radius of the shape
// cut into pieces by polynomial signs (docs/derivation.md, "Sensors").
#include "sensor_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gap_polynomial.hpp"
#include "segment_frame.hpp"
#include "static_query.hpp"

namespace carom::detail {

void TimeSpans::add(double start, double end) {
  if (!(end > start)) return;  // a single instant overlaps nothing
  if (count_ > 0 && start <= bounds_[2 * count_ - 1]) {
    bounds_[2 * count_ - 1] = std::max(bounds_[2 * count_ - 1], end);
    return;
  }
  if (count_ == kCapacity) {
    // (Beyond any region's count of sign changes: kept whole by widening the last span.)
    bounds_[2 * count_ - 1] = end;
    return;
  }
  bounds_[2 * count_] = start;
  bounds_[2 * count_ + 1] = end;
  ++count_;
}

TimeSpans TimeSpans::unite(const TimeSpans& a, const TimeSpans& b) {
  TimeSpans out;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() || j < b.size()) {
    const bool take_a = j == b.size() || (i < a.size() && a.start(i) <= b.start(j));
    if (take_a) {
      out.add(a.start(i), a.end(i));
      ++i;
    } else {
      out.add(b.start(j), b.end(j));
      ++j;
    }
  }
  return out;
}

TimeSpans TimeSpans::intersect(const TimeSpans& a, const TimeSpans& b) {
  TimeSpans out;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    out.add(std::max(a.start(i), b.start(j)), std::min(a.end(i), b.end(j)));
    if (a.end(i) < b.end(j)) {
      ++i;
    } else {
      ++j;
    }
  }
  return out;
}

TimeSpans TimeSpans::complement(double horizon) const {
  TimeSpans out;
  double from = 0.0;
  for (std::size_t k = 0; k < count_; ++k) {
    out.add(from, start(k));
    from = end(k);
  }
  out.add(from, horizon);
  return out;
}

namespace {

// The sign of p just after 0: its value's where that is clear of the rounding, else the first
// derivative's that is, and so on (a polynomial zero within its rounding throughout counts as
// not positive).
bool positive_after_start(const GapPolynomial& p) {
  for (std::size_t k = 0; k < p.c.size(); ++k) {
    const double bound = kGapRounding * p.weight[k];
    if (p.c[k] > bound) return true;
    if (p.c[k] < -bound) return false;
  }
  return false;
}

// The scaled times within [0, scaled horizon] at which p is positive: its falls (closings) and
// its rises (the closings of −p), merged in time order from its sign just after 0. Each sign
// change is one of the two; a pair that rounding reports out of turn is skipped.
TimeSpans positive_times(const StaticQuery& query, const GapPolynomial& p, double horizon) {
  GapPolynomial negated = p;
  for (double& c : negated.c) c = -c;
  const GapClosings falls = query.closings(p, AtStart::ignored);
  const GapClosings rises = query.closings(negated, AtStart::ignored);
  TimeSpans out;
  bool positive = positive_after_start(p);
  double since = 0.0;
  std::size_t f = 0;
  std::size_t r = 0;
  while (f < falls.count || r < rises.count) {
    const bool fall = r == rises.count || (f < falls.count && falls.t[f] <= rises.t[r]);
    const double t = fall ? falls.t[f++] : rises.t[r++];
    if (fall && positive) {
      out.add(since, t);
      positive = false;
    } else if (!fall && !positive) {
      since = t;
      positive = true;
    }
  }
  if (positive) out.add(since, horizon);
  return out;
}

// constant + d·(s + u·t + ½·a·t²) + rate·t: a linear form of the centre's path.
GapPolynomial linear_form(const Path& path, Vec2 d, double constant, double rate) {
  GapPolynomial p;
  p.c[0] = constant + dot(path.s, d);
  p.weight[0] = std::abs(constant) + abs_dot(path.s, d);
  p.c[1] = rate + dot(path.u, d);
  p.weight[1] = std::abs(rate) + abs_dot(path.u, d);
  p.c[2] = 0.5 * dot(path.a, d);
  p.weight[2] = 0.5 * abs_dot(path.a, d);
  return p;
}

// The disc of the ball's (growing) radius about a point: the centre within it.
TimeSpans near_point(const StaticQuery& query, Vec2 point, double horizon) {
  return positive_times(
      query, inside_circle(query.path_from(point), query.scaled_radius(), query.scaled_growth()),
      horizon);
}

TimeSpans segment_times(const StaticQuery& query, const Segment& segment, double horizon) {
  TimeSpans out = near_point(query, segment.a, horizon);
  if (segment.b == segment.a) return out;
  out = TimeSpans::unite(out, near_point(query, segment.b, horizon));
  const Vec2 along = query.scaled_offset(segment.b, segment.a);
  const double length_sq = length_squared(along);
  // A segment this short against the ball: its ends' discs cover its neighbourhood.
  if (!(length_sq > 0x1p-1000)) return out;
  const Vec2 normal = left_normal(along) / std::sqrt(length_sq);
  const Path path = query.path_from(segment.a);
  const double r = query.scaled_radius();
  const double g = query.scaled_growth();
  // The slab: within the radius of the line on either side, between the ends' perpendiculars.
  TimeSpans slab = positive_times(query, linear_form(path, normal, r, g), horizon);
  slab =
      TimeSpans::intersect(slab, positive_times(query, linear_form(path, -normal, r, g), horizon));
  slab = TimeSpans::intersect(slab,
                              positive_times(query, linear_form(path, along, 0.0, 0.0), horizon));
  slab = TimeSpans::intersect(
      slab, positive_times(query, linear_form(path, -along, length_sq, 0.0), horizon));
  return TimeSpans::unite(out, slab);
}

TimeSpans arc_times(const StaticQuery& query, const ArcFrame& arc, double horizon) {
  TimeSpans out = near_point(query, arc.start_point, horizon);
  if (arc.end_point != arc.start_point) {
    out = TimeSpans::unite(out, near_point(query, arc.end_point, horizon));
  }
  if (!(arc.span > 0.0)) return out;
  // The interior: the distance to the arc's circle, | |s| − R |, below the radius, where the
  // centre's direction lies within the span (elsewhere an end point is nearer than any interior
  // point: the distance to the circle's point at angle φ grows with |φ − θ|).
  const Path path = query.path_from(arc.center);
  const double big_r = query.distance(arc.radius);
  const double r = query.scaled_radius();
  const double g = query.scaled_growth();
  TimeSpans band = positive_times(query, inside_circle(path, big_r + r, g), horizon);
  // |s| > R − r: always where the radius has outgrown R, else outside the inner circle.
  const TimeSpans outgrown =
      positive_times(query, linear_form(path, Vec2{}, r - big_r, g), horizon);
  TimeSpans beyond_inner;
  if (big_r > r) beyond_inner = positive_times(query, outside_circle(path, big_r - r, -g), horizon);
  band = TimeSpans::intersect(band, TimeSpans::unite(outgrown, beyond_inner));
  if (band.size() == 0) return out;
  constexpr double kFullTurn = 2.0 * 3.14159265358979323846;
  if (arc.span < kFullTurn) {
    // The wedge: cross(start, s) >= 0 and cross(s, end) >= 0 for a span up to a half turn; for a
    // larger one, outside the gap's wedge (from end to start).
    const Vec2 after_start = left_normal(arc.start_direction);  // cross(start, s) = s·this
    const Vec2 before_end = -left_normal(arc.end_direction);    // cross(s, end) = s·this
    TimeSpans wedge;
    if (arc.span <= 0.5 * kFullTurn) {
      wedge = TimeSpans::intersect(
          positive_times(query, linear_form(path, after_start, 0.0, 0.0), horizon),
          positive_times(query, linear_form(path, before_end, 0.0, 0.0), horizon));
    } else {
      const TimeSpans gap = TimeSpans::intersect(
          positive_times(query, linear_form(path, -before_end, 0.0, 0.0), horizon),
          positive_times(query, linear_form(path, -after_start, 0.0, 0.0), horizon));
      wedge = gap.complement(horizon);
    }
    band = TimeSpans::intersect(band, wedge);
  }
  return TimeSpans::unite(out, band);
}

TimeSpans disc_times(const StaticQuery& query, const Ball& disc, double horizon) {
  return positive_times(
      query,
      inside_circle(query.path_from(disc.center),
                    query.distance(disc.radius) + query.scaled_radius(), query.scaled_growth()),
      horizon);
}

StaticQuery make_query(const Ball& ball, const Motion& motion, const SensorShape& shape,
                       double horizon) {
  int length = 0;
  switch (shape.kind) {
    case SensorShape::Kind::segment:
      length = std::max({offset_exponent(ball.center, shape.segment.a),
                         offset_exponent(ball.center, shape.segment.b),
                         offset_exponent(shape.segment.b, shape.segment.a)});
      break;
    case SensorShape::Kind::arc:
      length = std::max({offset_exponent(ball.center, shape.arc.center),
                         exponent_of(shape.arc.radius) + 1,
                         offset_exponent(ball.center, shape.arc.start_point),
                         offset_exponent(ball.center, shape.arc.end_point)});
      break;
    case SensorShape::Kind::disc:
      length = std::max(offset_exponent(ball.center, shape.disc.center),
                        exponent_of(shape.disc.radius) + 1);
      break;
  }
  return {ball, motion, horizon, length};
}

// overlap_times in the query's scaled time.
TimeSpans scaled_overlap_times(const StaticQuery& query, const SensorShape& shape,
                               double scaled_horizon) {
  switch (shape.kind) {
    case SensorShape::Kind::segment:
      return segment_times(query, shape.segment, scaled_horizon);
    case SensorShape::Kind::arc:
      return arc_times(query, shape.arc, scaled_horizon);
    case SensorShape::Kind::disc:
      return disc_times(query, shape.disc, scaled_horizon);
  }
  return {};
}

// The distance from p to the shape (0 inside a disc).
double distance_to(const SensorShape& shape, Vec2 p) {
  switch (shape.kind) {
    case SensorShape::Kind::segment:
      return length(nearest_on_segment(shape.segment, p) - p);
    case SensorShape::Kind::arc:
      return length(shape.arc.nearest(p) - p);
    case SensorShape::Kind::disc:
      return std::max(0.0, length(p - shape.disc.center) - shape.disc.radius);
  }
  return 0.0;
}

// Whether the ball's overlap cannot change within the horizon: its centre moves by at most
// |v|·H + ½·|a|·H² and its radius grows by g·H, so a distance to the shape that clears the
// radius by more than that (outside), or falls short of it by more (inside), stays on its side.
// The common case of a prediction (a horizon of a cell's exit, a sensor a few cells away) is
// decided by this without the polynomials. The slack of 2^-30 is far above the roundings.
bool cannot_change(const Ball& ball, const Motion& motion, double distance, bool inside,
                   double horizon) {
  if (!std::isfinite(horizon)) return false;
  const double reach =
      (length(motion.velocity) + 0.5 * length(motion.acceleration) * horizon + motion.growth) *
      horizon;
  const double slack = 0x1p-30 * (distance + ball.radius + reach + std::abs(ball.center.x) +
                                  std::abs(ball.center.y));
  if (!std::isfinite(reach) || !std::isfinite(slack)) return false;
  return inside ? distance + reach + slack < ball.radius : distance - reach - slack > ball.radius;
}

// The first time the ball, clear of the shape now, touches it: the enter, by the time of impact's
// closed forms (straight lines) or single closing (gravity, growth), the queries walls use.
Impact first_touch(const Ball& ball, const Motion& motion, const SensorShape& shape,
                   double horizon) {
  switch (shape.kind) {
    case SensorShape::Kind::segment:
      return time_of_impact_ball_segment(ball, motion, shape.segment, horizon);
    case SensorShape::Kind::arc:
      return time_of_impact_ball_arc(ball, motion, shape.arc_as_given, horizon);
    case SensorShape::Kind::disc:
      return time_of_impact_ball_point({ball.center, ball.radius + shape.disc.radius}, motion,
                                       shape.disc.center, horizon);
  }
  return {};
}

// On a straight line, the later root of |s + v·t|² = reach² for a centre inside (c < 0): the time
// it leaves the disc, in the form that does not cancel.
double leave_disc(Vec2 s, Vec2 v, double reach) {
  const double a = dot(v, v);
  const double b = dot(s, v);
  const double c = dot(s, s) - reach * reach;
  const double root = std::sqrt(std::max(b * b - a * c, 0.0));
  return b < 0.0 ? (root - b) / a : -c / (b + root);
}

// [lo, hi] narrowed to the times at which constant + rate·t >= 0.
void keep_non_negative(double constant, double rate, double& lo, double& hi) {
  if (rate > 0.0) {
    lo = std::max(lo, -constant / rate);
  } else if (rate < 0.0) {
    hi = std::min(hi, -constant / rate);
  } else if (constant < 0.0) {
    hi = -std::numeric_limits<double>::infinity();  // never
  }
}

// On a straight line, when a ball now overlapping a segment or a disc stops overlapping it: the
// neighbourhood is convex, so the line's times inside it are one interval, the union of those of
// its convex pieces (the end discs and the slab between them), and it ends at the latest of their
// ends. Nothing (NaN) for an arc, whose neighbourhood is not convex.
double leave_convex(const Ball& ball, Vec2 v, const SensorShape& shape) {
  constexpr double kEndless = std::numeric_limits<double>::infinity();
  const double r = ball.radius;
  if (shape.kind == SensorShape::Kind::disc) {
    return leave_disc(ball.center - shape.disc.center, v, r + shape.disc.radius);
  }
  if (shape.kind != SensorShape::Kind::segment) return std::numeric_limits<double>::quiet_NaN();
  const Segment& segment = shape.segment;
  double latest = -kEndless;
  // (leave_disc's form is the later root whatever the sign of c: a disc the line meets.)
  const auto disc_end = [&](Vec2 point) {
    const Vec2 s = ball.center - point;
    const double b = dot(s, v);
    if (b * b - dot(v, v) * (dot(s, s) - r * r) >= 0.0) {
      latest = std::max(latest, leave_disc(s, v, r));
    }
  };
  disc_end(segment.a);
  disc_end(segment.b);
  const Vec2 along = segment.b - segment.a;
  const double length_sq = length_squared(along);
  if (length_sq > 0.0) {
    const Vec2 normal = left_normal(along) / std::sqrt(length_sq);
    const Vec2 s = ball.center - segment.a;
    double lo = -kEndless;
    double hi = kEndless;
    keep_non_negative(r - dot(s, normal), -dot(v, normal), lo, hi);
    keep_non_negative(r + dot(s, normal), dot(v, normal), lo, hi);
    keep_non_negative(dot(s, along), dot(v, along), lo, hi);
    keep_non_negative(length_sq - dot(s, along), -dot(v, along), lo, hi);
    if (lo <= hi) latest = std::max(latest, hi);
  }
  return latest;
}

}  // namespace

TimeSpans overlap_times(const Ball& ball, const Motion& motion, const SensorShape& shape,
                        double horizon) {
  const StaticQuery query = make_query(ball, motion, shape, horizon);
  const TimeSpans scaled = scaled_overlap_times(query, shape, query.scaled_horizon());
  TimeSpans out;
  for (std::size_t k = 0; k < scaled.size(); ++k) {
    out.add(query.real_time(scaled.start(k)), query.real_time(scaled.end(k)));
  }
  return out;
}

SensorChange next_sensor_change(const Ball& ball, const Motion& motion, const SensorShape& shape,
                                bool inside, double horizon, double now) {
  // The distance from the centre to the shape, which the quick answers below share.
  const double distance = distance_to(shape, ball.center);
  if (cannot_change(ball, motion, distance, inside, horizon)) return {};
  if (!inside && distance > ball.radius) {
    // Clear of it now: the enter is the first touch, where the clock tells it from now (else the
    // spans below decide, as they decide every change at an instant).
    const Impact touch = first_touch(ball, motion, shape, horizon);
    if (!touch.hit) return {};
    if (now + touch.t != now) return {true, touch.t};
  }
  if (inside && motion.acceleration == Vec2{} && motion.growth == 0.0 &&
      motion.velocity != Vec2{} && distance < ball.radius) {
    // Inside it now, on a straight line: the leaving time in closed form, where the clock tells
    // it from now (else the spans below decide).
    const double leave = leave_convex(ball, motion.velocity, shape);
    if (leave > 0.0 && now + leave != now) {
      if (!(leave < horizon)) return {};
      return {true, leave};
    }
  }
  const StaticQuery query = make_query(ball, motion, shape, horizon);
  const double scaled_horizon = query.scaled_horizon();
  const TimeSpans spans = scaled_overlap_times(query, shape, scaled_horizon);
  const auto at_now = [&](double scaled_t) { return now + query.real_time(scaled_t) == now; };
  // A horizon the clock cannot tell from now (the ball has another event at this instant) holds
  // no span to tell inside from outside: it is decided when the ball is predicted again.
  if (at_now(scaled_horizon)) return {};
  // The first span that is more than an instant at now.
  std::size_t first = 0;
  if (spans.size() > 0 && at_now(spans.end(0))) first = 1;
  const bool any = first < spans.size();
  if (inside) {
    // Leaving: at once where no span holds now, else at the end of the one that does, unless
    // it runs to the horizon.
    if (!any || !at_now(spans.start(first))) return {true, 0.0};
    if (!(spans.end(first) < scaled_horizon)) return {};
    return {true, query.real_time(spans.end(first))};
  }
  if (!any) return {};
  return {true, query.real_time(spans.start(first))};
}

}  // namespace carom::detail
