// When a polynomial gap closes: turning points from the derivatives, recursively, then one
// bracketed root on each monotone piece that falls through zero (docs/derivation.md, "Gaps that
// are polynomials in time").
#include "gap_polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace carom::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Bisection and Newton steps at most, per root: bisection alone halves a bracket of doubles
// (counted in their bit patterns once it spans orders of magnitude) to one unit in 64 + 11
// steps; Newton's steps, taken only where they shrink the bracket, need far fewer.
constexpr int kMostSteps = 160;
// Roundings of overlap within which a gap that starts to part still counts as in contact.
constexpr double kNearTouch = 0x1p10;

struct Poly {
  std::array<double, 5> c{};
  std::array<double, 5> w{};
  int degree = 0;  // the highest power with a non-zero coefficient (0 for a constant)
};

Poly trimmed(const GapPolynomial& p) {
  Poly out{p.c, p.weight, 4};
  while (out.degree > 0 && out.c[static_cast<std::size_t>(out.degree)] == 0.0) --out.degree;
  return out;
}

Poly derivative(const Poly& p) {
  Poly out;
  out.degree = std::max(p.degree - 1, 0);
  for (int i = 1; i <= p.degree; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.c[k - 1] = i * p.c[k];
    out.w[k - 1] = i * p.w[k];
  }
  return out;
}

// p at t >= 0 with its rounding bound. Beyond t = 1 both are taken of p(t)/t^degree, by Horner's
// rule in 1/t, so that nothing overflows however far t is: signs and ratios are unchanged.
struct Sample {
  double value;
  double bound;
  int sign;  // +1 or −1 beyond the bound, 0 within it
};

Sample sample(const Poly& p, double t) {
  double value = 0.0;
  double weight = 0.0;
  if (t <= 1.0) {
    for (int i = p.degree; i >= 0; --i) {
      const auto k = static_cast<std::size_t>(i);
      value = value * t + p.c[k];
      weight = weight * t + p.w[k];
    }
  } else {
    const double r = 1.0 / t;
    for (int i = 0; i <= p.degree; ++i) {
      const auto k = static_cast<std::size_t>(i);
      value = value * r + p.c[k];
      weight = weight * r + p.w[k];
    }
  }
  const double bound = kGapRounding * weight;
  return {value, bound, value > bound ? 1 : (value < -bound ? -1 : 0)};
}

// p(t) / p'(t), from the two samples (each scaled by its own power of t beyond 1).
double newton_step(const Sample& value, const Sample& slope, double t) {
  const double ratio = value.value / slope.value;
  return t <= 1.0 ? ratio : ratio * t;
}

// A few points in ascending order.
struct Points {
  std::array<double, 16> x{};
  std::size_t count = 0;

  void add(double t) {
    if (count < x.size()) x[count++] = t;
  }
};

// A double's bit pattern and back: memcpy rather than std::bit_cast, which the libc++ of
// Debian's emscripten 3.1.6 (the wasm preset) does not have; the two compile to the same move.
std::uint64_t bits_of(double x) {
  std::uint64_t out = 0;
  std::memcpy(&out, &x, sizeof out);
  return out;
}
double double_of(std::uint64_t bits) {
  double out = 0.0;
  std::memcpy(&out, &bits, sizeof out);
  return out;
}

// The midpoint of lo < hi for bisection: the mean of their bit patterns where they lie orders of
// magnitude apart (so that a bracket from 0 to 10^300 narrows to the root's magnitude in a few
// dozen steps), the arithmetic mean otherwise.
double midpoint(double lo, double hi) {
  if (hi > 4.0 * lo && hi != kInfinity) {
    const std::uint64_t a = bits_of(lo);
    const std::uint64_t b = bits_of(hi);
    return double_of(a + (b - a) / 2);
  }
  return lo + (hi - lo) * 0.5;
}

// p is monotone on [lo, hi], of sign `first` (±1) beyond its rounding at lo, and of the other
// sign beyond it at hi. The root between is narrowed by the sign of p's computed value (the
// certified signs at the ends make the bracket right; inside it the computed value is the best
// guide there is) to one unit of the double, or to a point where the value is exactly zero.
// Returns that point, or the final bracket's end of sign `first` (lo).
double bracketed_root(const Poly& p, const Poly& slope, double lo, double hi, int first) {
  // The first point a Newton step from lo where it lands inside (a gap that falls steadily is
  // near its tangent there), else the midpoint: bisecting from 0 by bit patterns first visits
  // the tiny times, dozens of steps below a root near 1.
  double x = midpoint(lo, hi);
  const Sample lo_sample = sample(p, lo);
  const Sample lo_slope = sample(slope, lo);
  if (lo_slope.value != 0.0) {
    const double newton = lo - newton_step(lo_sample, lo_slope, lo);
    if (newton > lo && newton < hi) x = newton;
  }
  double previous_width = kInfinity;
  for (int step = 0; step < kMostSteps; ++step) {
    const Sample at = sample(p, x);
    if (at.value == 0.0) return x;
    ((at.value > 0.0) == (first > 0) ? lo : hi) = x;
    const double width = hi - lo;
    // Newton from x where it lands strictly inside the bracket and the bracket keeps halving;
    // bisection otherwise.
    double next = midpoint(lo, hi);
    if (width < 0.5 * previous_width) {
      const Sample derivative_at = sample(slope, x);
      if (derivative_at.value != 0.0) {
        const double newton = x - newton_step(at, derivative_at, x);
        if (newton > lo && newton < hi) next = newton;
      }
    }
    previous_width = width;
    if (!(next > lo && next < hi)) break;  // one unit wide
    x = next;
  }
  return lo;
}

// Appends to `out`, ascending, the points of (lo, hi) at which p may change sign: each sign
// change, found to its rounding, and each turning point at which p's sign is uncertain.
void sign_changes(const Poly& p, double lo, double hi, Points& out) {
  if (p.degree == 0) return;
  if (p.degree == 1) {
    const double t = -p.c[0] / p.c[1];
    if (t > lo && t < hi) out.add(t);
    return;
  }
  if (p.degree == 2) {
    const double a = p.c[2];
    const double b = p.c[1];
    const double c = p.c[0];
    const double discriminant = b * b - 4.0 * a * c;
    const double bound = kGapRounding * (p.w[1] * p.w[1] + 4.0 * p.w[2] * p.w[0]);
    if (discriminant < -bound) return;
    if (discriminant <= bound) {  // a double root within the rounding: the vertex
      const double vertex = -b / (2.0 * a);
      if (vertex > lo && vertex < hi) out.add(vertex);
      return;
    }
    // The cancellation-free pair of roots.
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double r1 = q / a;
    double r2 = q != 0.0 ? c / q : r1;
    if (r2 < r1) std::swap(r1, r2);
    if (r1 > lo && r1 < hi) out.add(r1);
    if (r2 > lo && r2 < hi && r2 != r1) out.add(r2);
    return;
  }
  const Poly slope = derivative(p);
  Points turning;
  sign_changes(slope, lo, hi, turning);
  double previous = lo;
  Sample previous_sample = sample(p, lo);
  for (std::size_t k = 0; k <= turning.count; ++k) {
    const double x = k < turning.count ? turning.x[k] : hi;
    const Sample at = sample(p, x);
    if (previous_sample.sign * at.sign < 0) {
      out.add(bracketed_root(p, slope, previous, x, previous_sample.sign));
    }
    if (k < turning.count && at.sign == 0) out.add(x);
    previous = x;
    previous_sample = at;
  }
}

// Whether p falls at t = 0: its first derivative beyond its rounding there is negative.
bool falls_at_start(const Poly& p) {
  for (int i = 1; i <= p.degree; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double bound = kGapRounding * p.w[k];
    if (p.c[k] > bound) return false;
    if (p.c[k] < -bound) return true;
  }
  return false;
}

// A time beyond every root of p (Cauchy's bound, doubled), or +infinity.
double beyond_roots(const Poly& p) {
  const double lead = std::abs(p.c[static_cast<std::size_t>(p.degree)]);
  double largest = 0.0;
  for (int i = 0; i < p.degree; ++i) {
    largest = std::max(largest, std::abs(p.c[static_cast<std::size_t>(i)]));
  }
  return 2.0 * (1.0 + largest / lead);
}

}  // namespace

GapClosings gap_closings(const GapPolynomial& polynomial, double horizon, AtStart at_start) {
  GapClosings out;
  const Poly p = trimmed(polynomial);
  if (p.degree == 0 || !(horizon >= 0.0)) return out;
  const auto record = [&](double t) {
    if (out.count < out.t.size()) out.t[out.count++] = t;
  };
  const Sample start = sample(p, 0.0);
  bool open = start.sign > 0;
  const bool start_counts =
      at_start == AtStart::counts || (at_start == AtStart::touching && start.sign == 0);
  // In contact at the start (touching, or overlapping by a few roundings) and parting: a contact
  // again where the gap turns to fall before it has opened beyond its rounding (two balls a
  // rounding apart that part slower than gravity presses them together). A deeper overlap that
  // parts is left to part, as the straight-line queries leave it.
  bool parting_contact = false;
  if (start.sign <= 0 && start_counts) {
    if (falls_at_start(p)) {
      record(0.0);
    } else {
      parting_contact = start.value >= -kNearTouch * start.bound;
    }
  }
  // Clamped to the largest double: a bound that overflows says nothing, and bisection needs a
  // finite end.
  const double end = std::min({horizon, beyond_roots(p), std::numeric_limits<double>::max()});
  if (!(end > 0.0)) return out;
  const Poly slope = derivative(p);
  Points turning;
  sign_changes(slope, 0.0, end, turning);
  double previous = 0.0;
  int previous_sign = start.sign;
  for (std::size_t k = 0; k <= turning.count; ++k) {
    const double x = k < turning.count ? turning.x[k] : end;
    const int sign = sample(p, x).sign;
    if (parting_contact && k > 0 && sample(slope, 0.5 * (previous + x)).value < 0.0) {
      record(previous);  // the turning point at which it starts to fall, still in contact
      parting_contact = false;
    }
    if (parting_contact && sign > 0) {
      parting_contact = false;
      open = true;
    }
    if (open && sign < 0) {
      record(previous_sign > 0 ? bracketed_root(p, slope, previous, x, 1) : previous);
      open = false;
    } else if (!open && sign > 0) {
      open = true;
    }
    previous = x;
    previous_sign = sign;
  }
  return out;
}

}  // namespace carom::detail
