// The rescaled circle crossings: any finite motion, brought near 1 by powers of two.
// Why powers of two and how far: docs/derivation.md, "Any finite input".
#include "circle_crossing.hpp"

#include <algorithm>
#include <cmath>

namespace carom::detail {
namespace {

// The lengths (s and R) share one scale. When they differ greatly (a tiny ball far away), the
// scale sits between them, so that neither s·s nor R² leaves the normal range; but the larger
// is kept within 2^kLengthSpread of 1, so that the degree-four products (|s|²·|u|²) stay below
// 2^1010 with |u| near 1.
constexpr int kLengthSpread = 500;

struct Normalised {
  Vec2 s;
  Vec2 u;
  double radius = 0.0;
  int time_exponent = 0;  // t = (root of the normalised problem)·2^time_exponent
};

Normalised normalise(const ScaledMotion& m) noexcept {
  const int length_s = exponent_of(m.s);
  const int length_r = exponent_of(m.radius);
  const int high = std::max(length_s, length_r);
  const int low = std::min(length_s, length_r);
  // A zero offset or radius has no scale of its own: the other one sets it.
  const int length = low == kZeroExponent ? high : std::max(high - kLengthSpread, (high + low) / 2);
  const int velocity = m.u == Vec2{} ? 0 : exponent_of(m.u);
  return {scaled(m.s, -length), scaled(m.u, -velocity), std::ldexp(m.radius, -length),
          (length + m.length_exponent) - (velocity + m.velocity_exponent)};
}

// Below this normalised radius R² is no longer exact (it nears the subnormal range); that
// happens only when the offset exceeds the radius by more than 2^1000.
constexpr double kTinyRadius = 0x1p-500;

// For such a tiny circle far away, the squares of the discriminant cannot tell whether the
// path passes through it, but the path's distance from the centre, |s×u| / |u|, against R can
// (exactly so for a head-on path, h = 0). √D is then negligible against −b.
bool passes_through_tiny_circle(const ScaledMotion& motion, const Normalised& n, double h) {
  if (!(n.radius < kTinyRadius && motion.radius > 0.0)) return false;
  return h == 0.0 || std::abs(h) < std::sqrt(dot(n.u, n.u)) * n.radius;
}

bool finite_motion(const ScaledMotion& m) noexcept {
  return is_finite(m.s) && is_finite(m.u) && std::isfinite(m.radius);
}

}  // namespace

Crossing entry_crossing_rescaled(const ScaledMotion& motion, double horizon) noexcept {
  if (!finite_motion(motion)) return {};  // callers pass overflowed differences halved
  const Normalised n = normalise(motion);
  // The same formulas as entry_crossing, on the normalised problem.
  const double b = dot(n.s, n.u);
  if (!(b < 0.0)) return {};
  const double c = dot(n.s, n.s) - n.radius * n.radius;
  if (c <= 0.0) return {true, 0.0};
  const double h = cross(n.s, n.u);
  double discriminant = dot(n.u, n.u) * (n.radius * n.radius) - h * h;
  if (!(discriminant > 0.0)) {
    if (!passes_through_tiny_circle(motion, n, h)) return {};
    discriminant = 0.0;
  }
  const double t = std::ldexp(c / (std::sqrt(discriminant) - b), n.time_exponent);
  if (!(t <= horizon)) return {};
  return {true, t};
}

Crossing exit_crossing_rescaled(const ScaledMotion& motion, double horizon) noexcept {
  if (!finite_motion(motion)) return {};
  const Normalised n = normalise(motion);
  const double a = dot(n.u, n.u);
  if (!(a > 0.0)) return {};
  const double b = dot(n.s, n.u);
  const double c = dot(n.s, n.s) - n.radius * n.radius;
  const double h = cross(n.s, n.u);
  double discriminant = a * (n.radius * n.radius) - h * h;
  if (!(discriminant > 0.0)) {
    if (!passes_through_tiny_circle(motion, n, h)) return {};
    discriminant = 0.0;
  }
  const double root = std::sqrt(discriminant);
  const double scaled_t = b <= 0.0 ? (root - b) / a : c / (-b - root);
  const double t = std::ldexp(scaled_t, n.time_exponent);
  if (!(t > 0.0 && t <= horizon)) return {};
  return {true, t};
}

Vec2 direction_at(const ScaledMotion& motion, double t) noexcept {
  // In units of 2^(length + length_exponent): s is near 1, and so is u·t wherever s + u·t is a
  // contact (|u·t| <= |s| + R). t's exponent is folded into u's scale so that neither u·2^k
  // nor the product overflows on its way.
  if (t == 0.0) return normalized(motion.s);
  const int length = std::max(exponent_of(motion.s), exponent_of(motion.radius));
  int t_exponent = 0;
  const double t_mantissa = std::frexp(t, &t_exponent);
  const Vec2 travelled =
      scaled(motion.u, motion.velocity_exponent - motion.length_exponent - length + t_exponent) *
      t_mantissa;
  return normalized(scaled(motion.s, -length) + travelled);
}

ScaledMotion halved_offset_motion(Vec2 p, Vec2 q, Vec2 velocity, double r1, double r2) noexcept {
  return {p * 0.5 - q * 0.5, velocity, r1 * 0.5 + r2 * 0.5, 1, 0};
}

}  // namespace carom::detail
