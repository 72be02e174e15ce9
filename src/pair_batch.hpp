// carom internal: one ball's first contacts with a batch of neighbours, for the world's
// prediction. The same arithmetic as circle_crossing.hpp's entry_crossing_in_range, operation for
// operation (so every result is bit-identical), but evaluated for every pair without branches:
// the compiler can run the pairs through SIMD lanes, and the CPU never guesses wrong about which
// pairs approach (about half, at random: a mispredicted branch costs as much as a pair's
// arithmetic). Pairs outside exact_range.hpp's window are flagged for the scalar, rescaled path.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "carom/vec2.hpp"
#include "exact_range.hpp"

namespace carom::detail {

struct PairBatch {
  static constexpr std::size_t kCapacity = 32;
  enum Outcome : std::uint8_t { kMiss = 0, kHit = 1, kRescale = 2 };

  std::size_t count = 0;
  // Pair k: the offset s (this ball minus the neighbour), the relative velocity u and the sum of
  // the radii; the neighbour's slot.
  alignas(64) std::array<double, kCapacity> sx;
  alignas(64) std::array<double, kCapacity> sy;
  alignas(64) std::array<double, kCapacity> ux;
  alignas(64) std::array<double, kCapacity> uy;
  alignas(64) std::array<double, kCapacity> reach;
  std::array<std::uint32_t, kCapacity> other;
  // Filled by solve(): the time from now of each hit, and what became of each pair.
  alignas(64) std::array<double, kCapacity> t;
  std::array<std::uint8_t, kCapacity> outcome;

  void push(Vec2 s, Vec2 u, double radius_sum, std::uint32_t neighbour) {
    sx[count] = s.x;
    sy[count] = s.y;
    ux[count] = u.x;
    uy[count] = u.y;
    reach[count] = radius_sum;
    other[count] = neighbour;
    ++count;
  }
  [[nodiscard]] bool full() const { return count == kCapacity; }

  // entry_crossing_in_range for every pair, with the horizon at +infinity's largest finite
  // stand-in (the world's kFarFuture); pairs whose magnitudes leave the exact range get
  // kRescale, whatever the arithmetic here gave.
  void solve(double horizon) {
    for (std::size_t k = 0; k < count; ++k) {
      // The lane's values first, so that every test below is on plain locals.
      const double s_x = sx[k];
      const double s_y = sy[k];
      const double u_x = ux[k];
      const double u_y = uy[k];
      const double r = reach[k];
      const double b = s_x * u_x + s_y * u_y;  // dot(s, u)
      const double ss = s_x * s_x + s_y * s_y;
      const double uu = u_x * u_x + u_y * u_y;
      const double rr = r * r;
      const double c = ss - rr;
      const double h = s_x * u_y - s_y * u_x;  // cross(s, u)
      const double discriminant = uu * rr - h * h;
      const double hit_time = c / (std::sqrt(discriminant) - b);
      // vector_in_range and square_in_range, on the squares already formed; & and | rather than
      // && and || so that nothing branches.
      const bool s_zero = (s_x == 0.0) & (s_y == 0.0);
      const bool u_zero = (u_x == 0.0) & (u_y == 0.0);
      const bool s_in = ((ss >= kSquareLow) & (ss <= kSquareHigh)) | s_zero;
      const bool u_in = ((uu >= kSquareLow) & (uu <= kSquareHigh)) | u_zero;
      const bool in_range = s_in & u_in & (rr >= kSquareLow) & (rr <= kSquareHigh);
      const bool inside = c <= 0.0;  // already touching and moving inwards: t = 0
      const bool hit = (b < 0.0) & (inside | ((discriminant > 0.0) & (hit_time <= horizon)));
      t[k] = inside ? 0.0 : hit_time;
      // kMiss 0, kHit 1, kRescale 2, as arithmetic rather than branches.
      outcome[k] = static_cast<std::uint8_t>(in_range ? static_cast<int>(hit) : 2);
    }
  }
};

}  // namespace carom::detail
