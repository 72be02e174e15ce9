// carom internal: one ball's motion against static shapes as the polynomial gaps see it:
// lengths and times scaled by powers of two so that every term of a gap is below 1 over a unit of
// scaled time (no rounding changes), the centre's path relative to a fixed point, and the gaps to
// circles. Shared by the time of impact (accelerated_sweep.cpp) and the sensors' overlap times
// (sensor_overlap.cpp). Derivation: docs/derivation.md, "Gaps that are polynomials in time".
#pragma once

#include <algorithm>
#include <cmath>

#include "accelerated_sweep.hpp"
#include "carom/sweep.hpp"
#include "exact_range.hpp"
#include "gap_polynomial.hpp"

namespace carom::detail {

// The exponent of p − q's largest component, taken of halves where the difference overflows.
inline int offset_exponent(Vec2 p, Vec2 q) {
  const Vec2 d = p - q;
  if (is_finite(d)) return exponent_of(d);
  return exponent_of(p * 0.5 - q * 0.5) + 1;
}

// A vector whose true value is v·2^extra (a difference of velocities that overflowed is kept
// halved, with extra 1).
struct Exact {
  Vec2 v;
  int extra = 0;

  [[nodiscard]] int exponent() const {
    return v == Vec2{} ? kZeroExponent : exponent_of(v) + extra;
  }
};

inline Exact difference(Vec2 p, Vec2 q) {
  const Vec2 d = p - q;
  if (is_finite(d)) return {d, 0};
  return {p * 0.5 - q * 0.5, 1};
}

// A growth (>= 0) whose true value is value·2^extra (two growths whose sum overflowed are kept
// halved, with extra 1).
struct Growth {
  double value = 0.0;
  int extra = 0;
};

inline Growth sum_of(double g, double h) {
  const double sum = g + h;
  if (std::isfinite(sum)) return {sum, 0};
  return {0.5 * g + 0.5 * h, 1};
}

// The scales of one problem: lengths by 2^-length and times by 2^-time, so that every offset and
// radius is below 1 in magnitude and so are velocity·t and ½·acceleration·t² over a unit of
// scaled time. Powers of two change no rounding.
struct Scale {
  int length = 0;
  int time = 0;

  [[nodiscard]] Vec2 offset(Vec2 p, Vec2 q) const {
    const Exact d = difference(p, q);
    return scaled(d.v, d.extra - length);
  }
  [[nodiscard]] double distance(double r) const { return std::ldexp(r, -length); }
  [[nodiscard]] Vec2 velocity(const Exact& v) const { return scaled(v.v, v.extra + time - length); }
  [[nodiscard]] double speed(const Growth& g) const {
    return std::ldexp(g.value, g.extra + time - length);
  }
  [[nodiscard]] Vec2 acceleration(const Exact& a) const {
    return scaled(a.v, a.extra + 2 * time - length);
  }
  [[nodiscard]] double to_scaled_time(double t) const { return std::ldexp(t, -time); }
  [[nodiscard]] double from_scaled_time(double t) const { return std::ldexp(t, time); }
};

// velocity: the larger of the velocity and a radius's growth, each a speed.
inline Scale make_scale(int largest_length_exponent, const Exact& velocity,
                        const Exact& acceleration) {
  Scale scale;
  scale.length = largest_length_exponent + 1;
  const bool moving = velocity.v != Vec2{};
  const bool accelerating = acceleration.v != Vec2{};
  if (moving) scale.time = scale.length - velocity.exponent() - 1;
  if (accelerating) {
    // floor((length − e − 1) / 2), for either sign (>> of a negative int is arithmetic in C++20).
    const int by_acceleration = (scale.length - acceleration.exponent() - 1) >> 1;
    scale.time = moving ? std::min(scale.time, by_acceleration) : by_acceleration;
  }
  return scale;
}

// The speed that sets a problem's time scale: the velocity's, or a growth larger than it.
inline Exact fastest(const Exact& velocity, const Growth& growth) {
  if (growth.value == 0.0) return velocity;
  const Exact as_speed{{growth.value, 0.0}, growth.extra};
  if (velocity.v == Vec2{} || as_speed.exponent() > velocity.exponent()) return as_speed;
  return velocity;
}

// A centre moving as s + u·t + ½·a·t² relative to a fixed point, in scaled units.
struct Path {
  Vec2 s;
  Vec2 u;
  Vec2 a;

  [[nodiscard]] Vec2 at(double t) const { return s + u * t + (a * (0.5 * t)) * t; }
};

inline double abs_dot(Vec2 x, Vec2 y) { return std::abs(x.x * y.x) + std::abs(x.y * y.y); }

// |s + u·t + ½·a·t²|² − (R + g·t)²: positive while the centre is outside the circle of radius
// R + g·t (g, a growth, 0 for a circle that keeps its size).
inline GapPolynomial outside_circle(const Path& path, double radius, double growth = 0.0) {
  const Vec2 s = path.s;
  const Vec2 u = path.u;
  const Vec2 a = path.a;
  GapPolynomial p;
  p.c[0] = dot(s, s) - radius * radius;
  p.weight[0] = dot(s, s) + radius * radius;
  p.c[1] = 2.0 * dot(s, u);
  p.weight[1] = 2.0 * abs_dot(s, u);
  p.c[2] = dot(u, u) + dot(s, a);
  p.weight[2] = dot(u, u) + abs_dot(s, a);
  p.c[3] = dot(u, a);
  p.weight[3] = abs_dot(u, a);
  p.c[4] = 0.25 * dot(a, a);
  p.weight[4] = p.c[4];
  if (growth != 0.0) {
    p.c[1] -= 2.0 * radius * growth;
    p.weight[1] += 2.0 * std::abs(radius * growth);
    p.c[2] -= growth * growth;
    p.weight[2] += growth * growth;
  }
  return p;
}

// (R + g·t)² − |s + u·t + ½·a·t²|²: positive while the centre is inside the circle of radius
// R + g·t.
inline GapPolynomial inside_circle(const Path& path, double radius, double growth = 0.0) {
  GapPolynomial p = outside_circle(path, radius, growth);
  for (double& c : p.c) c = -c;
  return p;
}

// The unit vector along `preferred`, or along the first non-zero fallback; +x where all three
// are zero (a ball that only grows, its centre on a point or a line: every direction is as
// good).
inline Vec2 direction_or(Vec2 preferred, Vec2 fallback, Vec2 last_resort) {
  if (preferred != Vec2{} && is_finite(preferred)) return normalized(preferred);
  if (fallback != Vec2{} && is_finite(fallback)) return normalized(fallback);
  if (last_resort == Vec2{}) return {1.0, 0.0};
  return normalized(last_resort);
}

// A moving ball against static shapes: its own frame of scales, and the queries on its parts.
class StaticQuery {
 public:
  StaticQuery(const Ball& ball, const Motion& motion, double horizon, int largest_length_exponent)
      : ball_(ball),
        motion_(motion),
        horizon_(horizon),
        scale_(make_scale(std::max(largest_length_exponent, exponent_of(ball.radius)),
                          fastest({motion.velocity, 0}, {motion.growth, 0}),
                          {motion.acceleration, 0})),
        u_(scale_.velocity({motion.velocity, 0})),
        a_(scale_.acceleration({motion.acceleration, 0})),
        scaled_horizon_(scale_.to_scaled_time(horizon)),
        radius_(scale_.distance(ball.radius)),
        growth_(scale_.speed({motion.growth, 0})) {}

  [[nodiscard]] Vec2 center_at(double t) const { return position_at(ball_.center, motion_, t); }
  // The path of the ball's centre relative to `origin`, scaled.
  [[nodiscard]] Path path_from(Vec2 origin) const {
    return {scale_.offset(ball_.center, origin), u_, a_};
  }
  [[nodiscard]] const Ball& ball() const { return ball_; }
  [[nodiscard]] double scaled_radius() const { return radius_; }
  [[nodiscard]] double scaled_growth() const { return growth_; }
  [[nodiscard]] double distance(double r) const { return scale_.distance(r); }
  [[nodiscard]] Vec2 scaled_offset(Vec2 p, Vec2 q) const { return scale_.offset(p, q); }

  // The closings of a scaled gap, in scaled time.
  [[nodiscard]] GapClosings closings(const GapPolynomial& gap, AtStart at_start) const {
    return gap_closings(gap, scaled_horizon_, at_start);
  }
  [[nodiscard]] double scaled_horizon() const { return scaled_horizon_; }
  // A scaled time back in real time, within the horizon.
  [[nodiscard]] double real_time(double scaled_t) const {
    return std::min(scale_.from_scaled_time(scaled_t), horizon_);
  }
  // The direction the ball moves in at t (its velocity's, else its acceleration's).
  [[nodiscard]] Vec2 heading_at(double t) const {
    return direction_or(motion_.velocity + motion_.acceleration * t, motion_.velocity,
                        motion_.acceleration);
  }
  [[nodiscard]] bool moves() const {
    return motion_.velocity != Vec2{} || motion_.acceleration != Vec2{} || motion_.growth != 0.0;
  }

 private:
  Ball ball_;
  Motion motion_;
  double horizon_;
  Scale scale_;
  Vec2 u_;
  Vec2 a_;
  double scaled_horizon_;
  double radius_;
  double growth_;
};

}  // namespace carom::detail
