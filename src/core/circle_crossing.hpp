// carom internal: when does a point moving as s + u·t cross a circle of radius R centred at the
// origin? The two closed-form roots of |s + u·t| = R, each taken in its cancellation-free form.
// The derivation, and why the discriminant is written as a·R² − (s×u)², is in docs/derivation.md;
// why and how magnitudes outside exact_range.hpp's window are rescaled is in its last section.
#pragma once

#include <cmath>

#include "carom/vec2.hpp"
#include "exact_range.hpp"

namespace carom::detail {

struct Crossing {
  bool found = false;
  double t = 0.0;
};

// A relative motion whose true values are s·2^length_exponent, u·2^velocity_exponent and
// radius·2^length_exponent. A caller whose difference of positions (or velocities, or sum of
// radii) overflowed passes the halved values with exponent 1; every other caller passes 0.
struct ScaledMotion {
  Vec2 s;
  Vec2 u;
  double radius = 0.0;
  int length_exponent = 0;
  int velocity_exponent = 0;
};

// The rescaled forms of the two functions below, for any finite motion: the lengths and the
// velocity are each brought near 1 by a power of two (which changes no rounding), the root is
// taken there, and t is scaled back.
[[nodiscard]] Crossing entry_crossing_rescaled(const ScaledMotion& motion, double horizon) noexcept;
[[nodiscard]] Crossing exit_crossing_rescaled(const ScaledMotion& motion, double horizon) noexcept;

// The unit vector along the true s + u·t, without forming it (it may overflow where the unit
// vector does not). Zero when s + u·t is zero.
[[nodiscard]] Vec2 direction_at(const ScaledMotion& motion, double t) noexcept;

// offset_motion's case for a difference or sum that overflowed: the same of halved operands.
[[nodiscard]] ScaledMotion halved_offset_motion(Vec2 p, Vec2 q, Vec2 velocity, double r1,
                                                double r2) noexcept;

// s = p − q, u = velocity, R = r1 + r2, halved together (exponent 1) when the difference or the
// sum overflows. Halving such huge values is exact.
[[nodiscard]] inline ScaledMotion offset_motion(Vec2 p, Vec2 q, Vec2 velocity, double r1,
                                                double r2) noexcept {
  const Vec2 s = p - q;
  const double radius = r1 + r2;
  if (is_finite(s) && std::isfinite(radius)) return {s, velocity, radius, 0, 0};
  return halved_offset_motion(p, q, velocity, r1, r2);
}

// Whether the plain formulas below are exact to their rounding for this motion (see
// exact_range.hpp). The batch kernel evaluates the same test.
[[nodiscard]] inline bool in_exact_range(Vec2 s, Vec2 u, double radius) noexcept {
  return vector_in_range(s) && vector_in_range(u) && square_in_range(radius * radius);
}

// The first time the point enters the circle while moving inwards, in [0, horizon]. A point
// already inside (or on) the circle and moving inwards crosses at t = 0. A tangential graze,
// where the discriminant is zero, is no crossing: the point never gets inside.
[[nodiscard]] inline Crossing entry_crossing_in_range(Vec2 s, Vec2 u, double radius,
                                                      double horizon) {
  const double b = dot(s, u);  // half the linear coefficient; < 0 means moving inwards
  if (!(b < 0.0)) return {};
  const double c = dot(s, s) - radius * radius;
  if (c <= 0.0) return {true, 0.0};
  const double h = cross(s, u);
  const double discriminant = dot(u, u) * (radius * radius) - h * h;
  if (!(discriminant > 0.0)) return {};
  const double t = c / (std::sqrt(discriminant) - b);
  if (!(t <= horizon)) return {};
  return {true, t};
}

// The same for any finite motion: the formulas above in the exact range, rescaled outside it.
[[nodiscard]] inline Crossing entry_crossing(Vec2 s, Vec2 u, double radius, double horizon) {
  if (!in_exact_range(s, u, radius)) [[unlikely]] {
    return entry_crossing_rescaled({s, u, radius}, horizon);
  }
  return entry_crossing_in_range(s, u, radius, horizon);
}

// The time the point leaves the circle while moving outwards, in (0, horizon]: the larger root.
// A point outside the circle that will pass through it leaves at that root too.
[[nodiscard]] inline Crossing exit_crossing(Vec2 s, Vec2 u, double radius, double horizon) {
  if (!in_exact_range(s, u, radius)) return exit_crossing_rescaled({s, u, radius}, horizon);
  const double a = dot(u, u);
  if (!(a > 0.0)) return {};
  const double b = dot(s, u);
  const double c = dot(s, s) - radius * radius;
  const double h = cross(s, u);
  const double discriminant = a * (radius * radius) - h * h;
  if (!(discriminant > 0.0)) return {};
  const double root = std::sqrt(discriminant);
  const double t = b <= 0.0 ? (root - b) / a : c / (-b - root);
  if (!(t > 0.0 && t <= horizon)) return {};
  return {true, t};
}

// The same for a motion that may carry exponents.
[[nodiscard]] inline Crossing entry_crossing(const ScaledMotion& motion, double horizon) {
  if (motion.length_exponent != 0 || motion.velocity_exponent != 0) {
    return entry_crossing_rescaled(motion, horizon);
  }
  return entry_crossing(motion.s, motion.u, motion.radius, horizon);
}

[[nodiscard]] inline Crossing exit_crossing(const ScaledMotion& motion, double horizon) {
  if (motion.length_exponent != 0 || motion.velocity_exponent != 0) {
    return exit_crossing_rescaled(motion, horizon);
  }
  return exit_crossing(motion.s, motion.u, motion.radius, horizon);
}

// The relative motion of two balls (A at pa moving with va, B likewise; A against a still B),
// halved where it overflows.
[[nodiscard]] inline ScaledMotion ball_pair_motion(Vec2 pa, Vec2 va, double ra, Vec2 pb, Vec2 vb,
                                                   double rb) noexcept {
  ScaledMotion motion = offset_motion(pa, pb, va - vb, ra, rb);
  if (!is_finite(motion.u)) {
    motion.u = va * 0.5 - vb * 0.5;
    motion.velocity_exponent = 1;
  }
  return motion;
}

// Their first approaching contact, in [0, horizon], as sweep_ball_ball's t. Coincident centres
// with any relative motion count as approaching, at t = 0: they have no line of centres and no
// side to separate to, so any relative motion deepens the overlap. Safe for any finite inputs.
[[nodiscard]] inline Crossing ball_pair_crossing(const ScaledMotion& motion, double horizon) {
  if (motion.s == Vec2{}) return {motion.u != Vec2{}, 0.0};
  return entry_crossing(motion, horizon);
}

// The same from the balls (the batch kernel's fallback).
[[nodiscard]] inline Crossing ball_pair_crossing(Vec2 pa, Vec2 va, double ra, Vec2 pb, Vec2 vb,
                                                 double rb, double horizon) {
  return ball_pair_crossing(ball_pair_motion(pa, va, ra, pb, vb, rb), horizon);
}

}  // namespace carom::detail
