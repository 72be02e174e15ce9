// carom internal: the closed form for two balls in straight-line motion whose sum of radii grows
// at a constant speed (the Lubachevsky–Stillinger pair equation), for the generic case only:
//   |s + u·t|² = (R + g·t)²,  gap(t) = A·t² + 2·B·t + C,
//   A = u·u − g², B = s·u − R·g, C = s·s − R².
// A pair parting faster than its radii grow, beyond the rounding, never closes, whatever its gap
// (one that has just met). Elsewhere, where a coefficient lies within the rounding of its terms
// (touching, parting as fast as the radii grow, a graze), the answer is `undecided`, and the
// caller takes the certified isolation of the Motion queries instead (docs/derivation.md,
// section 8), which reads those cases by their rounding bounds, as it does magnitudes outside
// the window where those bounds hold. Every decided root is taken in its cancellation-free form.
#pragma once

#include <cmath>

#include "carom/vec2.hpp"

namespace carom::detail {

struct GrowingPairClosing {
  bool decided = false;
  bool found = false;
  double t = 0.0;  // the first closing, from now (found only)
};

// The window of magnitudes in which the closed form's rounding bounds hold: with the squared
// sum of radii and the squared growth speed between kGrowingLow and kGrowingHigh, and the squared
// offset and relative speed below kGrowingHigh, every product the form takes (up to b², a·c) stays
// between 2⁻⁸⁸⁰ and 2¹⁰⁰², far from the subnormals' absolute rounding and from overflow. Outside,
// the answer is undecided.
inline constexpr double kGrowingLow = 0x1p-400;
inline constexpr double kGrowingHigh = 0x1p+500;
// Far below the rounding of any of the coefficients (2⁻⁵³ of each term, times a few operations).
inline constexpr double kGrowingUndecided = 0x1p-40;

// s: the first centre from the second; u: its velocity relative to the second's; reach: the sum
// of the radii now; growth: the sum of their growth speeds (> 0). (growing_pair_batch.cpp takes
// the same operations, lane by lane.)
[[nodiscard]] inline GrowingPairClosing growing_pair_closing(Vec2 s, Vec2 u, double reach,
                                                             double growth) {
  const double ss = dot(s, s);
  const double uu = dot(u, u);
  const double rr = reach * reach;
  const double gg = growth * growth;
  const double rg = reach * growth;
  const double a = uu - gg;
  const double b = dot(s, u) - rg;
  const double c = ss - rr;
  const bool in_range = (ss <= kGrowingHigh) & (uu <= kGrowingHigh) & (rr >= kGrowingLow) &
                        (rr <= kGrowingHigh) & (gg >= kGrowingLow) & (gg <= kGrowingHigh);
  const bool b_clear =
      std::abs(b) > kGrowingUndecided * (std::abs(s.x * u.x) + std::abs(s.y * u.y) + rg);
  const bool a_clear = std::abs(a) > kGrowingUndecided * (uu + gg);
  GrowingPairClosing out;
  if (!in_range) return out;
  if (b_clear && b > 0.0 && a_clear && a > 0.0) {
    // Parting faster than the radii grow, now and for ever (the gap's slope 2·(b + a·t) stays
    // positive): no closing, however the gap itself rounds (a pair that has just met).
    out.decided = true;
    return out;
  }
  if (!(std::abs(c) > kGrowingUndecided * (ss + rr)) || !b_clear || !a_clear) {
    return out;  // touching, parting at the growth's pace, or sliding at it: undecided
  }
  if (c < 0.0) return out;  // overlapping beyond the rounding: the certified path says what
  const double d = b * b - a * c;
  if (!(std::abs(d) > kGrowingUndecided * (b * b + std::abs(a * c)))) return out;  // a graze
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
