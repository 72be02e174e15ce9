// carom internal: the closed form for two balls in straight-line motion whose sum of radii grows
// at a constant speed (the Lubachevsky–Stillinger pair equation), for the generic case only:
//   |s + u·t|² = (R + g·t)²,  gap(t) = A·t² + 2·B·t + C,
//   A = u·u − g², B = s·u − R·g, C = s·s − R².
// Where a coefficient lies within the rounding of its terms (touching, parting as fast as the
// radii grow, a graze) the answer is `undecided`, and the caller takes the certified isolation of
// the Motion queries instead (docs/derivation.md, section 8), which reads those cases by their
// rounding bounds. Every decided root is taken in its cancellation-free form.
#pragma once

#include <cmath>

#include "carom/vec2.hpp"

namespace carom::detail {

struct GrowingPairClosing {
  bool decided = false;
  bool found = false;
  double t = 0.0;  // the first closing, from now (found only)
};

// s: the first centre from the second; u: its velocity relative to the second's; reach: the sum
// of the radii now; growth: the sum of their growth speeds (> 0).
[[nodiscard]] inline GrowingPairClosing growing_pair_closing(Vec2 s, Vec2 u, double reach,
                                                             double growth) {
  // Far below the rounding of any of the three (2⁻⁵³ of each term, times a few operations).
  constexpr double kUndecided = 0x1p-40;
  const double a = dot(u, u) - growth * growth;
  const double b = dot(s, u) - reach * growth;
  const double c = dot(s, s) - reach * reach;
  GrowingPairClosing out;
  if (!(std::abs(c) > kUndecided * (dot(s, s) + reach * reach)) ||
      !(std::abs(b) > kUndecided * (std::abs(s.x * u.x) + std::abs(s.y * u.y) + reach * growth)) ||
      !(std::abs(a) > kUndecided * (dot(u, u) + growth * growth))) {
    return out;  // touching, parting at the growth's pace, or sliding at it: undecided
  }
  if (c < 0.0) return out;  // overlapping beyond the rounding: the certified path says what
  const double d = b * b - a * c;
  if (!(std::abs(d) > kUndecided * (b * b + std::abs(a * c)))) return out;  // a graze
  out.decided = true;
  if (b < 0.0) {
    // Closing now: the first root, if the gap reaches 0 (always when the growth outruns the
    // relative speed, a < 0).
    if (d < 0.0) return out;
    out.found = true;
    out.t = c / (std::sqrt(d) - b);
    return out;
  }
  // Opening now: it closes again only where the growth outruns the relative speed (a < 0), at
  // the positive root (b + √d) / −a.
  if (a > 0.0) return out;
  out.found = true;
  out.t = (b + std::sqrt(d)) / -a;
  return out;
}

}  // namespace carom::detail
