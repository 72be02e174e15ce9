// carom internal: the range of magnitudes in which the time-of-impact arithmetic needs no
// rescaling, and the power-of-two rescaling used outside it. Why and how: docs/derivation.md,
// section "Any finite input: rescaling by powers of two".
#pragma once

#include <algorithm>
#include <cmath>

#include "carom/vec2.hpp"

namespace carom::detail {

// Squared lengths and squared speeds between these bounds keep every product of the quadratic
// (up to degree four in lengths and speeds: |s|²·|u|², |u|²·R²) between 2⁻¹⁰⁰⁰ and 2¹⁰⁰⁰, far
// from overflow (2¹⁰²⁴) and from the subnormal range (below 2⁻¹⁰²²), so the plain formulas are
// exact to their rounding. Outside, the problem is rescaled.
inline constexpr double kSquareLow = 0x1p-500;
inline constexpr double kSquareHigh = 0x1p+500;

[[nodiscard]] inline bool square_in_range(double square) noexcept {
  return square >= kSquareLow && square <= kSquareHigh;  // false for NaN
}

// A vector is in range when its squared length is, or when it is exactly zero (a zero offset or
// a zero velocity needs no scale: the formulas treat it exactly).
[[nodiscard]] inline bool vector_in_range(Vec2 v) noexcept {
  return square_in_range(dot(v, v)) || v == Vec2{};
}

// Stands for the exponent of zero: below every finite double's (the least is -1074), so that
// the largest of several exponents ignores zeros.
inline constexpr int kZeroExponent = -1100;

// The binary exponent of the largest component: 2^e <= max(|x|, |y|) < 2^(e+1);
// kZeroExponent for a zero vector.
[[nodiscard]] inline int exponent_of(Vec2 v) noexcept {
  const double largest = std::max(std::abs(v.x), std::abs(v.y));
  return largest > 0.0 ? std::ilogb(largest) : kZeroExponent;
}

[[nodiscard]] inline int exponent_of(double x) noexcept {
  return x != 0.0 ? std::ilogb(x) : kZeroExponent;
}

// v·2^e, exact unless the result leaves the normal range.
[[nodiscard]] inline Vec2 scaled(Vec2 v, int e) noexcept {
  return {std::ldexp(v.x, e), std::ldexp(v.y, e)};
}

// Whether |v| <= r (touching or overlapping), for any finite v and r >= 0, without the
// overflow or underflow of squaring huge or tiny values: both are scaled by a common power of
// two first, which changes no comparison.
[[nodiscard]] inline bool within_distance(Vec2 v, double r) noexcept {
  if (vector_in_range(v) && square_in_range(r * r)) return dot(v, v) <= r * r;
  const int e = std::max(exponent_of(v), exponent_of(r));
  const Vec2 v_scaled = scaled(v, -e);
  const double r_scaled = std::ldexp(r, -e);
  return dot(v_scaled, v_scaled) <= r_scaled * r_scaled;
}

// Whether |v| < r (overlapping), with the same care.
[[nodiscard]] inline bool strictly_within_distance(Vec2 v, double r) noexcept {
  if (vector_in_range(v) && square_in_range(r * r)) return dot(v, v) < r * r;
  const int e = std::max(exponent_of(v), exponent_of(r));
  const Vec2 v_scaled = scaled(v, -e);
  const double r_scaled = std::ldexp(r, -e);
  return dot(v_scaled, v_scaled) < r_scaled * r_scaled;
}

// Whether |a| <= |b|, for any finite a and b, with the same care.
[[nodiscard]] inline bool not_longer(Vec2 a, Vec2 b) noexcept {
  if (vector_in_range(a) && vector_in_range(b)) return dot(a, a) <= dot(b, b);
  const int e = std::max(exponent_of(a), exponent_of(b));
  const Vec2 a_scaled = scaled(a, -e);
  const Vec2 b_scaled = scaled(b, -e);
  return dot(a_scaled, a_scaled) <= dot(b_scaled, b_scaled);
}

// The sign of dot(a, b) > 0 for any finite a and b: each is scaled by its own power of two
// first (the sign is unchanged), so that the products can neither overflow nor all underflow.
[[nodiscard]] inline bool dot_positive(Vec2 a, Vec2 b) noexcept {
  if (vector_in_range(a) && vector_in_range(b)) return dot(a, b) > 0.0;
  return dot(scaled(a, -exponent_of(a)), scaled(b, -exponent_of(b))) > 0.0;
}

}  // namespace carom::detail
