#include "rigid_sweep.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "accelerated_sweep.hpp"
#include "carom/geometry.hpp"

namespace carom::detail {

namespace {
// (Named within: the core compiles as unity files, whose other parts have helpers of these names.)
namespace rigid_parts {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// d turned by the angle whose cosine and sine are c and s.
Vec2 turn(Vec2 d, double c, double s) { return {c * d.x - s * d.y, s * d.x + c * d.y}; }

// The contact found by a query of the ball's motion relative to a wall that only translates,
// carried back to the world: the ball's centre, the touched point and the wall all move on.
Impact carried_back(Impact impact, const Ball& ball, const Motion& motion, Vec2 velocity) {
  if (!impact.hit) return impact;
  const Vec2 shift = velocity * impact.t;
  impact.a_at = position_at(ball.center, motion, impact.t);
  impact.b_at += shift;
  impact.point += shift;
  return impact;
}

// ---- certified advancement for a wall that turns -------------------------------------------

// The ball in the wall's frame, relative to the pivot: w(τ) = p(τ) − pivot(τ) (a quadratic),
// turned back by −ω·τ, so that the wall stands still; its radius r₀ + γ·τ.
struct BodyPath {
  Vec2 w0;
  Vec2 w1;
  Vec2 acceleration;
  double omega = 0.0;
  double r0 = 0.0;
  double growth = 0.0;

  struct State {
    Vec2 q;   // the centre in the wall's frame
    Vec2 q1;  // its velocity there
    double r = 0.0;
  };
  [[nodiscard]] State at(double tau) const {
    const Vec2 w = w0 + w1 * tau + acceleration * (0.5 * tau * tau);
    const Vec2 dw = w1 + acceleration * tau;
    const double angle = -omega * tau;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    // d/dτ R(−ωτ)·w = R(−ωτ)(w′ − ω·J·w), J the quarter turn.
    const Vec2 spin{omega * w.y, -omega * w.x};
    return {turn(w, c, s), turn(dw + spin, c, s), r0 + growth * tau};
  }

  // Over [tau, tau + delta]: bounds on the speed and the acceleration of the centre in the
  // wall's frame and on its distance from the pivot. The acceleration there is
  // R(−ωτ)(a − 2ω·J·w′ − ω²·w) (Coriolis and centrifugal terms).
  struct Bounds {
    double speed = 0.0;
    double acceleration = 0.0;
    double reach = 0.0;
  };
  [[nodiscard]] Bounds bounds(double tau, double delta) const {
    const Vec2 w = w0 + w1 * tau + acceleration * (0.5 * tau * tau);
    const Vec2 dw = w1 + acceleration * tau;
    const double a = length(acceleration);
    const double reach = length(w) + length(dw) * delta + 0.5 * a * delta * delta;
    const double speed = length(dw) + a * delta;
    const double spin = std::abs(omega);
    // A relative 2^-40 covers the rounding of these sums of products.
    constexpr double kUp = 1.0 + 0x1p-40;
    return {(speed + spin * reach) * kUp, (a + 2.0 * spin * speed + spin * spin * reach) * kUp,
            reach * kUp};
  }
};

// The first s > 0 at which g + g1·s − ½·m·s² falls to zero (g > 0, m ≥ 0): a function whose
// value and slope are g and g1 at 0 and whose second derivative is at least −m stays positive
// until then.
double safe_step(double g, double g1, double m) {
  if (!(g > 0.0)) return 0.0;
  if (!(m > 0.0)) return g1 >= 0.0 ? kInfinity : g / -g1;
  const double root = std::sqrt(g1 * g1 + 2.0 * m * g);
  const double s = g1 < 0.0 ? 2.0 * g / (root - g1) : (g1 + root) / m;
  return s * (1.0 - 0x1p-30);
}

// One gap of the wall's pieces, at the step's start: its value, its slope, the bound on the
// fall of its slope, and the step before which it cannot be a contact because the ball lies
// where another piece is nearer (0 when this piece is the one that counts now).
struct Gap {
  double value = kInfinity;
  double slope = 0.0;
  double curvature = 0.0;
  double valid_after = 0.0;
  double tolerance = 0.0;
};

// What a gap says of the step: a contact now (closing, within its rounding of zero), or how far
// the advance may go.
struct Verdict {
  bool contact = false;
  double step = kInfinity;
};
Verdict judge(const Gap& gap) {
  if (gap.valid_after > 0.0) {
    // Another piece holds the nearest point now: this one counts only from valid_after on, and
    // only once its gap has closed, whichever comes later.
    return {false, std::max(gap.valid_after, safe_step(gap.value, gap.slope, gap.curvature))};
  }
  if (gap.value <= gap.tolerance) {
    if (gap.slope < 0.0) return {true, 0.0};
    // Touching within the rounding and not closing: the slope cannot turn negative before
    // slope / curvature; where it is zero, a graze within the rounding is passed as the
    // world passes grazes, by the time the curvature takes to close the rounding.
    const double opening = gap.curvature > 0.0 ? gap.slope / gap.curvature : kInfinity;
    const double graze =
        gap.curvature > 0.0 ? std::sqrt(2.0 * gap.tolerance / gap.curvature) : kInfinity;
    return {false, std::max(opening, graze)};
  }
  return {false, safe_step(gap.value, gap.slope, gap.curvature)};
}

// A point of the wall, x (relative to the pivot): the squared gap |q − x|² − r².
Gap point_gap(const BodyPath::State& at, const BodyPath::Bounds& b, double growth, double delta,
              Vec2 x, double tolerance) {
  const Vec2 d = at.q - x;
  const double far = length(d) + b.speed * delta;
  Gap gap;
  gap.value = length_squared(d) - at.r * at.r;
  gap.slope = 2.0 * dot(d, at.q1) - 2.0 * at.r * growth;
  // (|q − x|²)″ = 2|q′|² + 2(q − x)·q″, the first term never negative; (r²)″ = 2γ².
  gap.curvature = (2.0 * far * b.acceleration + 2.0 * growth * growth) * (1.0 + 0x1p-40);
  gap.tolerance = tolerance * (at.r + length(d)) * 2.0;
  return gap;
}

// A segment's line from a to b (relative to the pivot): the distance to the line less r, on the
// ball's side, counting where the centre projects within the segment.
Gap line_gap(const BodyPath::State& at, const BodyPath::Bounds& b, double growth, Vec2 a, Vec2 e,
             double tolerance) {
  const double length_e = length(e);
  const Vec2 along = e / length_e;
  const Vec2 normal = left_normal(along);
  const Vec2 d = at.q - a;
  const double lambda = dot(d, along);
  const double lambda1 = dot(at.q1, along);
  const double h = dot(d, normal);
  const double side = h >= 0.0 ? 1.0 : -1.0;
  Gap gap;
  gap.value = side * h - at.r;
  gap.slope = side * dot(at.q1, normal) - growth;
  gap.curvature = b.acceleration;
  gap.tolerance = tolerance;
  // Off the segment's ends the end points are nearer: the line counts once λ may be back in
  // [0, L], λ″ bounded by the centre's acceleration.
  if (lambda < 0.0) {
    gap.valid_after = std::max(safe_step(-lambda, -lambda1, b.acceleration), 0x1p-1074);
  } else if (lambda > length_e) {
    gap.valid_after = std::max(safe_step(lambda - length_e, lambda1, b.acceleration), 0x1p-1074);
  }
  return gap;
}

// An arc's circle (centre c, radius R, relative to the pivot): from outside |q − c|² − (R + r)²,
// from inside (R − r)² − |q − c|², counting where the direction from the centre lies within the
// span.
Gap circle_gap(const BodyPath::State& at, const BodyPath::Bounds& b, double growth, double delta,
               const ArcFrame& arc, Vec2 c, double tolerance) {
  const Vec2 d = at.q - c;
  const double rho = length(d);
  const double far = rho + b.speed * delta;
  const double radius = arc.radius;
  Gap gap;
  gap.tolerance = tolerance * (radius + at.r + rho) * 2.0;
  if (rho >= radius) {
    const double reach = radius + at.r;
    gap.value = rho * rho - reach * reach;
    gap.slope = 2.0 * dot(d, at.q1) - 2.0 * reach * growth;
    gap.curvature = (2.0 * far * b.acceleration + 2.0 * growth * growth) * (1.0 + 0x1p-40);
  } else {
    const double room = radius - at.r;
    if (!(room > 0.0)) return Gap{};  // a ball as large as the circle: its ends meet it first
    gap.value = room * room - rho * rho;
    gap.slope = -2.0 * room * growth - 2.0 * dot(d, at.q1);
    gap.curvature = (2.0 * b.speed * b.speed + 2.0 * far * b.acceleration) * (1.0 + 0x1p-40);
  }
  if (rho > 0.0 && !arc.contains(d / rho)) {
    // The direction turns at most speed / ρ_min radians per unit of time; it must turn through
    // the angle to the nearer end before the circle counts.
    const Vec2 u = d / rho;
    const double from_start =
        std::atan2(cross(arc.start_direction, u), dot(arc.start_direction, u));
    const double past_start =
        from_start < 0.0 ? from_start + 2.0 * std::numbers::pi : from_start;  // in [0, 2π)
    const double to_span = std::min(past_start - arc.span, 2.0 * std::numbers::pi - past_start);
    if (!(b.speed > 0.0)) {
      gap.valid_after = kInfinity;
    } else {
      // Within `limit` the centre stays at least `low` (half of ρ or more) from the circle's
      // centre.
      const double limit = std::min(delta, 0.5 * rho / b.speed);
      const double low = rho - b.speed * limit;
      gap.valid_after =
          std::max(std::min(limit, to_span * low / b.speed) * (1.0 - 0x1p-30), 0x1p-1074);
    }
    if (to_span <= 0.0) gap.valid_after = 0.0;  // within a rounding of an end
  }
  return gap;
}

// The longest step taken at once, in radians the wall turns: the bounds grow with the step.
constexpr double kLongestTurn = 0.5;
// Steps one search takes at most before it reports how far it got.
constexpr int kMostSteps = 4000;

// Advances from the time the ball may first reach the wall's envelope (the disc about the pivot
// that holds every point of the wall, `envelope` its radius), step by certified step, until a
// gap closes or the horizon is reached.
template <typename Gaps, typename Finish>
RigidContact advance(const Ball& ball, const Motion& motion, const RigidMotion& rigid,
                     double horizon, double envelope, double scale, const Gaps& gaps_at,
                     const Finish& finish) {
  RigidContact out;
  const Motion relative{motion.velocity - rigid.velocity, motion.acceleration, motion.growth};
  // (An envelope of radius 0 — a point at the pivot, or one the rounding of huge coordinates puts
  // there — is given the least positive radius; one that is not finite rejects nothing.)
  Impact reach;
  reach.overlapping = true;
  if (std::isfinite(envelope)) {
    const double radius = std::max(envelope * (1.0 + 0x1p-30), std::numeric_limits<double>::min());
    reach = time_of_impact_ball_ball(ball, relative, Ball{rigid.pivot, radius}, Motion{{}, {}},
                                     horizon);
  }
  if (!reach.hit && !reach.overlapping) {
    out.checked = horizon;
    return out;
  }
  BodyPath path;
  path.w0 = ball.center - rigid.pivot;
  path.w1 = relative.velocity;
  path.acceleration = motion.acceleration;
  path.omega = rigid.angular_velocity;
  path.r0 = ball.radius;
  path.growth = motion.growth;
  const double tolerance = 0x1p-44 * scale;
  const double longest = kLongestTurn / std::abs(path.omega);
  double tau = reach.overlapping ? 0.0 : reach.t;
  double delta = std::min(longest, horizon - tau);
  for (int steps = 0; steps < kMostSteps; ++steps) {
    const BodyPath::State at = path.at(tau);
    const BodyPath::Bounds bounds = path.bounds(tau, delta);
    double free_step = kInfinity;  // what the gaps allow, the window aside
    bool contact = false;
    gaps_at(at, bounds, delta, tolerance, [&](const Gap& gap) {
      const Verdict verdict = judge(gap);
      contact |= verdict.contact;
      free_step = std::min(free_step, verdict.step);
    });
    const double step = std::min(delta, free_step);
    if (contact) {
      out.impact = finish(tau);
      out.checked = tau;
      return out;
    }
    const double next = std::max(tau + step, std::nextafter(tau, kInfinity));
    if (next >= horizon) {
      out.checked = horizon;
      return out;
    }
    // The next window: as long as the gaps allowed over this one (the bounds over it were that
    // tight), and at least twice the step taken.
    tau = next;
    delta = std::min({longest, horizon - tau, std::max({2.0 * step, free_step, 0x1p-1074})});
  }
  out.checked = tau;
  return out;
}

// The contact at τ (the ball's centre then, the wall carried there).
Impact contact_at(const Ball& ball, const Motion& motion, double tau, Vec2 point) {
  Impact impact;
  impact.hit = true;
  impact.t = tau;
  impact.a_at = position_at(ball.center, motion, tau);
  impact.b_at = point;
  impact.point = point;
  const Vec2 gap = point - impact.a_at;
  impact.normal = gap == Vec2{} ? normalized(-motion.velocity) : normalized(gap);
  return impact;
}

double magnitude(Vec2 v) { return std::max(std::abs(v.x), std::abs(v.y)); }

}  // namespace rigid_parts
}  // namespace

using namespace rigid_parts;  // NOLINT(google-build-using-namespace): this file's own helpers

Vec2 carried_point(Vec2 x, const RigidMotion& motion, double t) {
  const Vec2 d = x - motion.pivot;
  const double angle = motion.angular_velocity * t;
  return x + motion.velocity * t + (turn(d, std::cos(angle), std::sin(angle)) - d);
}

Vec2 carried_direction(Vec2 d, const RigidMotion& motion, double t) {
  const double angle = motion.angular_velocity * t;
  return turn(d, std::cos(angle), std::sin(angle));
}

Segment carried_segment(const Segment& segment, const RigidMotion& motion, double t) {
  return {carried_point(segment.a, motion, t), carried_point(segment.b, motion, t)};
}

void carry_arc(Arc& arc, ArcFrame& frame, const RigidMotion& motion, double t) {
  const double angle = motion.angular_velocity * t;
  arc.center = carried_point(arc.center, motion, t);
  if (angle != 0.0) {
    const double span = arc.end_angle - arc.start_angle;
    arc.start_angle = std::remainder(arc.start_angle + angle, 2.0 * std::numbers::pi);
    arc.end_angle = arc.start_angle + span;
  }
  frame.center = carried_point(frame.center, motion, t);
  frame.start_direction = carried_direction(frame.start_direction, motion, t);
  frame.end_direction = carried_direction(frame.end_direction, motion, t);
  frame.start_point = carried_point(frame.start_point, motion, t);
  frame.end_point = carried_point(frame.end_point, motion, t);
}

RigidContact rigid_ball_segment(const Ball& ball, const Motion& motion, const Segment& segment,
                                const RigidMotion& rigid, double horizon) {
  if (rigid.angular_velocity == 0.0) {
    const Motion relative{motion.velocity - rigid.velocity, motion.acceleration, motion.growth};
    return {carried_back(time_of_impact_ball_segment(ball, relative, segment, horizon), ball,
                         motion, rigid.velocity),
            horizon};
  }
  const Vec2 a = segment.a - rigid.pivot;
  const Vec2 e = segment.b - segment.a;
  const Vec2 b = segment.b - rigid.pivot;
  const double scale =
      ball.radius + magnitude(a) + magnitude(b) + magnitude(ball.center - rigid.pivot);
  const auto gaps = [&](const BodyPath::State& at, const BodyPath::Bounds& bounds, double delta,
                        double tolerance, const auto& take) {
    take(point_gap(at, bounds, motion.growth, delta, a, tolerance));
    if (e != Vec2{}) {
      take(point_gap(at, bounds, motion.growth, delta, b, tolerance));
      take(line_gap(at, bounds, motion.growth, a, e, tolerance));
    }
  };
  const auto finish = [&](double tau) {
    const Vec2 p = position_at(ball.center, motion, tau);
    return contact_at(ball, motion, tau, nearest_point(carried_segment(segment, rigid, tau), p));
  };
  const double envelope = std::max(length(a), length(b));
  return advance(ball, motion, rigid, horizon, envelope, scale, gaps, finish);
}

RigidContact rigid_ball_arc(const Ball& ball, const Motion& motion, const Arc& arc,
                            const ArcFrame& frame, const RigidMotion& rigid, double horizon) {
  if (rigid.angular_velocity == 0.0) {
    const Motion relative{motion.velocity - rigid.velocity, motion.acceleration, motion.growth};
    return {carried_back(time_of_impact_ball_arc(ball, relative, arc, horizon), ball, motion,
                         rigid.velocity),
            horizon};
  }
  const Vec2 c = frame.center - rigid.pivot;
  const Vec2 start = frame.start_point - rigid.pivot;
  const Vec2 end = frame.end_point - rigid.pivot;
  const double scale =
      ball.radius + magnitude(c) + frame.radius + magnitude(ball.center - rigid.pivot);
  const auto gaps = [&](const BodyPath::State& at, const BodyPath::Bounds& bounds, double delta,
                        double tolerance, const auto& take) {
    take(point_gap(at, bounds, motion.growth, delta, start, tolerance));
    if (end != start) take(point_gap(at, bounds, motion.growth, delta, end, tolerance));
    if (frame.span > 0.0) take(circle_gap(at, bounds, motion.growth, delta, frame, c, tolerance));
  };
  const auto finish = [&](double tau) {
    Arc carried = arc;
    ArcFrame carried_frame = frame;
    carry_arc(carried, carried_frame, rigid, tau);
    return contact_at(ball, motion, tau,
                      carried_frame.nearest(position_at(ball.center, motion, tau)));
  };
  const double envelope = length(c) + frame.radius;
  return advance(ball, motion, rigid, horizon, envelope, scale, gaps, finish);
}

}  // namespace carom::detail
