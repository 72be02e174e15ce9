// The batch form of sweep_ball_ball: the same arithmetic as detail::entry_crossing, written
// without branches so that the loop vectorises (SSE2 in the portable build, AVX2 or AVX-512
// with CAROM_NATIVE). Derivation: docs/derivation.md. Measurements: docs/performance.md.
#include "carom/sweep_batch.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "circle_crossing.hpp"
#include "exact_range.hpp"
#include "validate.hpp"

// A portable build still runs the widest vectors the machine has: the compiler emits the loop
// once per instruction set listed and the loader picks the best the CPU supports (an ELF ifunc).
// The answers do not depend on the pick: with FMA contraction off (cmake/CaromOptions.cmake)
// each lane does the same correctly rounded operations at every width. A -march=native build
// needs no clones. Nor does a ThreadSanitizer build: the sanitizer instruments the ifunc's
// resolver, which the loader runs before the sanitizer's runtime is up, and it crashes.
#if defined(__x86_64__) && defined(__ELF__) && !defined(__AVX2__) && !defined(CAROM_NO_CLONES) && \
    !defined(__SANITIZE_THREAD__)
#define CAROM_VECTOR_CLONES __attribute__((target_clones("default", "avx2", "avx512f")))
#else
#define CAROM_VECTOR_CLONES
#endif

namespace carom {
namespace {

constexpr const char* kFunction = "sweep_ball_ball_batch";

// The step form's horizon: t is a fraction of the step, as in sweep_ball_ball.
constexpr double kStepEnd = 1.0;
// Any value beyond kStepEnd: subtracting it makes every hit's t negative and leaves kNoHit
// positive, so counting hits is counting sign bits.
constexpr double kPastStepEnd = 2.0 * kStepEnd;
// Pairs per block: the hits of a block are counted right after it is swept, while its t
// (4 KiB) is still in the L1 cache, so counting adds no memory traffic.
constexpr std::size_t kBlockPairs = 512;
// Moves the sign bit of a 64-bit pattern to bit 0.
constexpr int kSignShift = std::numeric_limits<std::uint64_t>::digits - 1;

struct NamedArray {
  const char* name;
  std::span<const double> values;
  bool radius;  // must be > 0, not only finite
};

// Throws for the first bad value among pairs [begin, end) (pairs in order, then arrays in
// order). Called only when the fast check in the loop saw a possible one; returns if there is
// none after all (the check also fires for finite values outside the exact range).
void throw_first_bad_value(const BallPairArrays& p, std::size_t begin, std::size_t end) {
  const NamedArray arrays[] = {
      {"pairs.a_x", p.a_x, false},           {"pairs.a_y", p.a_y, false},
      {"pairs.a_radius", p.a_radius, true},  {"pairs.a_move_x", p.a_move_x, false},
      {"pairs.a_move_y", p.a_move_y, false}, {"pairs.b_x", p.b_x, false},
      {"pairs.b_y", p.b_y, false},           {"pairs.b_radius", p.b_radius, true},
      {"pairs.b_move_x", p.b_move_x, false}, {"pairs.b_move_y", p.b_move_y, false},
  };
  for (std::size_t i = begin; i < end; ++i) {
    for (const NamedArray& array : arrays) {
      const double value = array.values[i];
      const bool bad =
          array.radius ? !(std::isfinite(value) && value > 0.0) : !std::isfinite(value);
      if (!bad) continue;
      const std::string name = std::string(array.name) + "[" + std::to_string(i) + "]";
      if (array.radius) {
        detail::require_positive(kFunction, name.c_str(), value);
      } else {
        detail::require_finite(kFunction, name.c_str(), value);
      }
    }
  }
}

void check_sizes(const BallPairArrays& p, std::span<double> t) {
  const std::size_t n = p.a_x.size();
  const std::span<const double> others[] = {p.a_y, p.a_radius, p.a_move_x, p.a_move_y, p.b_x,
                                            p.b_y, p.b_radius, p.b_move_x, p.b_move_y};
  for (const auto& other : others) {
    if (other.size() != n) {
      detail::require_in_range(kFunction, "pairs (array sizes differ)",
                               static_cast<double>(other.size()), static_cast<double>(n),
                               static_cast<double>(n), "every array must have a_x's size");
    }
  }
  if (t.size() != n) {
    detail::require_in_range(kFunction, "t.size()", static_cast<double>(t.size()),
                             static_cast<double>(n), static_cast<double>(n),
                             "must equal the number of pairs");
  }
}

// Flags and counts travel as the bits of doubles, not as bools: on the x86-64 baseline (SSE2)
// the vectoriser cannot widen a comparison of doubles to a 64-bit integer, and a bool summed
// per pair makes gcc branch. Integer and, or, shift and subtract vectorise everywhere.
[[nodiscard]] std::uint64_t bits(double x) {
#if defined(__cpp_lib_bit_cast)
  return std::bit_cast<std::uint64_t>(x);
#else
  // The libc++ of Debian's emscripten 3.1.6 (the wasm preset) has no std::bit_cast yet.
  std::uint64_t out = 0;
  std::memcpy(&out, &x, sizeof out);
  return out;
#endif
}

// The sign bit is set when x is infinite or NaN: x − x is +0 for a finite x and NaN otherwise,
// and a NaN has every exponent bit set, the highest of which the shift moves into the sign.
[[nodiscard]] std::uint64_t not_finite_flag(double x) { return bits(x - x) << 1; }

// The sign bit is set when radius is <= 0 (either zero, or negative) or a NaN with the sign
// set. A positive radius has a clear sign bit and nonzero bits, so subtracting 1 keeps the sign
// clear; +0 has all bits zero, and subtracting 1 sets them all. +inf and the other NaNs pass
// here and are caught by not_finite_flag.
[[nodiscard]] std::uint64_t not_positive_flag(double radius) {
  return bits(radius) | (bits(radius) - 1u);
}

// The sign bit is set when a square (>= +0, or NaN) lies outside detail::square_in_range's
// bounds: below the low bound the first difference wraps negative, above the high one (inf and
// NaN included) the second does.
[[nodiscard]] std::uint64_t out_of_range_flag(double square) {
  return (bits(square) - bits(detail::kSquareLow)) | (bits(detail::kSquareHigh) - bits(square));
}

// The sign bit is set when the vector (x, y) is not exactly zero (either sign of zero).
[[nodiscard]] std::uint64_t nonzero_flag(double x, double y) {
  const std::uint64_t magnitude_bits = (bits(x) | bits(y)) << 1;
  return magnitude_bits | (0u - magnitude_bits);
}

struct PairColumns {
  const double* a_x;
  const double* a_y;
  const double* a_r;
  const double* a_mx;
  const double* a_my;
  const double* b_x;
  const double* b_y;
  const double* b_r;
  const double* b_mx;
  const double* b_my;
};

// Writes t for pairs [begin, end) and returns the OR of their flags: the sign bit is set if any
// input is NaN, infinite, or a radius <= 0, or if a pair lies outside the range where the plain
// formulas are exact (detail::in_exact_range); such a block is redone pair by pair.
//
// The loop body has no branch, so that it vectorises: every lane computes the square root and
// the quotient, and selects discard the lanes where they mean nothing. gcc's default
// -ftrapping-math forbids it to compute a floating-point operation that the source computes
// only conditionally, so every operation here is needed by the first select's condition and
// the comparisons a condition needs later are the quiet ones (std::isless and kin give the same
// answers as < and its kin, NaN included, but raise no flag on NaN, so they may be hoisted).
// t may alias an input array exactly: each pair's inputs are read before its t is written.
CAROM_VECTOR_CLONES std::uint64_t sweep_range(const PairColumns& in, double* out, std::size_t begin,
                                              std::size_t end) {
  std::uint64_t bad = 0;
  // clang needs the hint to accept the run-time overlap checks of eleven arrays (its default
  // allows eight); gcc versions the loop on its own.
#if defined(__clang__)
#pragma clang loop vectorize(enable)
#endif
  for (std::size_t i = begin; i < end; ++i) {
    const double ax = in.a_x[i], ay = in.a_y[i], ar = in.a_r[i];
    const double amx = in.a_mx[i], amy = in.a_my[i];
    const double bx = in.b_x[i], by = in.b_y[i], br = in.b_r[i];
    const double bmx = in.b_mx[i], bmy = in.b_my[i];

    // Relative motion, as in sweep_ball_ball: A moves by u against a still B.
    const double sx = ax - bx;
    const double sy = ay - by;
    const double ux = amx - bmx;
    const double uy = amy - bmy;
    const double reach = ar + br;
    // detail::entry_crossing's arithmetic, operation for operation, so t is bit-identical.
    const double b = sx * ux + sy * uy;
    const double s_squared = sx * sx + sy * sy;
    const double u_squared = ux * ux + uy * uy;
    const double reach_squared = reach * reach;
    const double c = s_squared - reach_squared;
    const double h = sx * uy - sy * ux;
    const double discriminant = u_squared * reach_squared - h * h;
    const double entry = c / (std::sqrt(discriminant) - b);  // NaN where discriminant < 0

    const bool approaching = std::isless(b, 0.0);
    const bool outside = std::isgreater(c, 0.0);
    const bool inside_or_touching = std::islessequal(c, 0.0);  // not !outside: c may be NaN
    const bool crosses = std::isgreater(discriminant, 0.0);
    const bool within_step = std::islessequal(entry, kStepEnd);
    const bool contact_later = approaching & outside & crosses & within_step;
    // Coincident centres with any relative motion count as approaching, at t = 0 (as in
    // sweep_ball_ball); for other centres b < 0 means approaching.
    const bool coincident_moving = (sx == 0.0) & (sy == 0.0) & ((ux != 0.0) | (uy != 0.0));
    const bool contact_now = coincident_moving | (approaching & inside_or_touching);
    // The two contacts exclude each other: contact_later needs c > 0 and b < 0, which
    // coincident centres never have.
    out[i] = contact_later ? entry : (contact_now ? 0.0 : kNoHit);

    // The fast check: the discriminant takes in every input (through s, u and reach), and an
    // infinity or NaN in any input makes it infinite or NaN; an infinite s, u or reach makes
    // a·reach² or h² infinite, or a product of infinity and zero NaN.
    bad |= not_finite_flag(discriminant) | not_positive_flag(ar) | not_positive_flag(br);
    // detail::in_exact_range(s, u, reach), as bits.
    bad |= (out_of_range_flag(s_squared) & nonzero_flag(sx, sy)) |
           (out_of_range_flag(u_squared) & nonzero_flag(ux, uy)) | out_of_range_flag(reach_squared);
  }
  return bad;
}

// t is in [0, kStepEnd] for a hit and kNoHit (+infinity) otherwise.
std::size_t count_hits(const double* t, std::size_t begin, std::size_t end) {
  std::size_t hits = 0;
  for (std::size_t i = begin; i < end; ++i) hits += bits(t[i] - kPastStepEnd) >> kSignShift;
  return hits;
}

// Pair i by the scalar code (detail::ball_pair_crossing, which sweep_ball_ball uses), after
// validating it: outside the exact range it rescales, inside it is the same arithmetic as the
// loop above.
double sweep_one(const BallPairArrays& p, std::size_t i) {
  throw_first_bad_value(p, i, i + 1);
  const detail::Crossing crossing = detail::ball_pair_crossing(
      {p.a_x[i], p.a_y[i]}, {p.a_move_x[i], p.a_move_y[i]}, p.a_radius[i], {p.b_x[i], p.b_y[i]},
      {p.b_move_x[i], p.b_move_y[i]}, p.b_radius[i], kStepEnd);
  double t = kNoHit;
  if (crossing.found) t = crossing.t;
  return t;
}

// Whether t shares memory with an input array: then a block's inputs are gone once its t is
// written, and flagged pairs cannot be redone afterwards.
bool aliases_an_input(const BallPairArrays& p, std::span<double> t) {
  const std::span<const double> inputs[] = {p.a_x, p.a_y, p.a_radius, p.a_move_x, p.a_move_y,
                                            p.b_x, p.b_y, p.b_radius, p.b_move_x, p.b_move_y};
  const auto t_begin = reinterpret_cast<std::uintptr_t>(t.data());
  const auto t_end = reinterpret_cast<std::uintptr_t>(t.data() + t.size());
  for (const auto& input : inputs) {
    const auto begin = reinterpret_cast<std::uintptr_t>(input.data());
    const auto end = reinterpret_cast<std::uintptr_t>(input.data() + input.size());
    if (begin < t_end && t_begin < end) return true;
  }
  return false;
}

}  // namespace

std::size_t sweep_ball_ball_batch(const BallPairArrays& pairs, std::span<double> t) {
  check_sizes(pairs, t);
  if (aliases_an_input(pairs, t)) {
    // Pair by pair, each pair's inputs read before its t is written.
    std::size_t hits = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      t[i] = sweep_one(pairs, i);
      hits += t[i] != kNoHit ? 1u : 0u;
    }
    return hits;
  }
  const PairColumns columns{
      pairs.a_x.data(),      pairs.a_y.data(),      pairs.a_radius.data(), pairs.a_move_x.data(),
      pairs.a_move_y.data(), pairs.b_x.data(),      pairs.b_y.data(),      pairs.b_radius.data(),
      pairs.b_move_x.data(), pairs.b_move_y.data(),
  };
  const std::size_t n = t.size();
  std::size_t hits = 0;
  for (std::size_t begin = 0; begin < n; begin += kBlockPairs) {
    const std::size_t end = std::min(n, begin + kBlockPairs);
    const std::uint64_t flags = sweep_range(columns, t.data(), begin, end);
    if (flags >> kSignShift != 0) {
      for (std::size_t i = begin; i < end; ++i) t[i] = sweep_one(pairs, i);
    }
    hits += count_hits(t.data(), begin, end);
  }
  return hits;
}

}  // namespace carom
