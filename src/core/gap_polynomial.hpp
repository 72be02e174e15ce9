// carom internal: when a gap that is a polynomial in time (degree at most four) closes. Time is
// split at the polynomial's turning points, which come from its derivative's, recursively; on
// each piece between them the gap is monotone, so a fall through zero there is one root, found by
// bisection with Newton steps. A dip between two turning points cannot exist, so no closing is
// skipped. Signs are trusted only beyond a bound on the rounding of the coefficients and of the
// evaluation; within it the gap counts as touching. Derivation and accuracy: docs/derivation.md,
// "Gaps that are polynomials in time".
#pragma once

#include <array>
#include <cstddef>

namespace carom::detail {

// p(t) = c[0] + c[1]·t + c[2]·t² + c[3]·t³ + c[4]·t⁴. weight[i] >= |c[i]| bounds the magnitudes
// of the terms c[i] was computed from (before any cancellation between them): a value of p is
// trusted to within kGapRounding·Σ weight[i]·|t|^i, which covers the rounding of the
// coefficients (a few units each, of those terms) and of Horner's evaluation (8 operations).
struct GapPolynomial {
  std::array<double, 5> c{};
  std::array<double, 5> weight{};
};

// 32 units of rounding of a double: the coefficients here are dot products of two or three
// terms (3 units at most), Horner's rule adds 2 a degree (8), and the products of weights with
// powers of t 5 more; twice their sum, so that the bound stays a bound after its own rounding.
inline constexpr double kGapRounding = 0x1p-48;

// How a gap that is zero or negative at t = 0 is read.
enum class AtStart : unsigned char {
  // As a contact (touching, or overlapping) that closes at 0 when the gap starts to fall: its
  // first derivative at 0 is negative, or zero within its rounding and the first one beyond it
  // is negative (a ball at rest on a floor that gravity pulls down). Elsewhere it opens first.
  counts,
  // The same for a gap that is zero within its rounding (touching); a gap below it is read as
  // `ignored` reads it (a ball inside an arc's outer circle is not in contact with its outside).
  touching,
  // As not yet closing: only falls from positive values count (the far side of a wall, which the
  // ball can reach only by going round).
  ignored,
};

// The times in [0, horizon] at which p falls from positive to zero (within its rounding) or
// below, ascending: at most two for a quartic, one for a quadratic, and 0 by AtStart. A gap that
// only touches zero within its rounding and rises again (a graze) does not close. The closing
// time is the last time found at which p is still positive beyond its rounding, or a time at which
// it is zero within it: never after the true root by more than the rounding allows. horizon may
// be +infinity.
struct GapClosings {
  std::array<double, 3> t{};
  std::size_t count = 0;
};
[[nodiscard]] GapClosings gap_closings(const GapPolynomial& p, double horizon, AtStart at_start);

}  // namespace carom::detail
