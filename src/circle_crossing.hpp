// carom internal: when does a point moving as s + u·t cross a circle of radius R centred at the
// origin? The two closed-form roots of |s + u·t| = R, each taken in its cancellation-free form.
// The derivation, and why the discriminant is written as a·R² − (s×u)², is in docs/derivation.md.
#pragma once

#include <cmath>

#include "carom/vec2.hpp"

namespace carom::detail {

struct Crossing {
  bool found = false;
  double t = 0.0;
};

// The first time the point enters the circle while moving inwards, in [0, horizon]. A point
// already inside (or on) the circle and moving inwards crosses at t = 0. A tangential graze,
// where the discriminant is zero, is no crossing: the point never gets inside.
[[nodiscard]] inline Crossing entry_crossing(Vec2 s, Vec2 u, double radius, double horizon) {
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

// The time the point leaves the circle while moving outwards, in (0, horizon]: the larger root.
// A point outside the circle that will pass through it leaves at that root too.
[[nodiscard]] inline Crossing exit_crossing(Vec2 s, Vec2 u, double radius, double horizon) {
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

}  // namespace carom::detail
