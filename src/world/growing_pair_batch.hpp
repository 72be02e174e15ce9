// carom internal: one growing ball's closings with a batch of neighbours, for the prediction of a
// world whose balls grow (world_growth_prediction.cpp). Each pair is core/growing_pair.hpp's
// closed form, operation for operation (so every answer is the same bits), evaluated for every
// pair without branches: which pairs close, part or stay undecided is random, and a mispredicted
// branch costs as much as a pair's arithmetic. Four pairs a vector operation on CPUs with AVX2
// (growing_pair_batch.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "carom/vec2.hpp"

namespace carom::detail {

struct GrowingPairBatch {
  static constexpr std::size_t kCapacity = 32;  // a bit of a 32-bit mask per pair
  // The inputs' arrays hold four pairs more, so that solve pads the last group of four without
  // a loop whose length changes from batch to batch.
  static constexpr std::size_t kInputCapacity = kCapacity + 4;

  // Pair k: the offset s (this ball minus the neighbour), the relative velocity u, the sum of the
  // radii now and the sum of their growth speeds; the neighbour's slot.
  alignas(64) std::array<double, kInputCapacity> sx;
  alignas(64) std::array<double, kInputCapacity> sy;
  alignas(64) std::array<double, kInputCapacity> ux;
  alignas(64) std::array<double, kInputCapacity> uy;
  alignas(64) std::array<double, kInputCapacity> reach;
  alignas(64) std::array<double, kInputCapacity> growth;
  // Filled by solve(): each closing's time from now, and what became of the pairs as bit masks
  // (bit k for pair k): those the closed form finds closing (at t), and those it leaves
  // undecided (for the certified isolation); the rest never close.
  alignas(64) std::array<double, kInputCapacity> t;
  std::array<std::uint32_t, kInputCapacity> other;
  std::uint32_t closings = 0;
  std::uint32_t undecided = 0;
  std::size_t count = 0;

  void push(Vec2 s, Vec2 u, double radius_sum, double growth_sum, std::uint32_t neighbour) {
    sx[count] = s.x;
    sy[count] = s.y;
    ux[count] = u.x;
    uy[count] = u.y;
    reach[count] = radius_sum;
    growth[count] = growth_sum;
    other[count] = neighbour;
    ++count;
  }
  [[nodiscard]] bool full() const { return count == kCapacity; }

  // growing_pair_closing for every pair; with AVX2 four at a time.
  void solve();
  // The same, one pair at a time whatever the CPU (what solve does without AVX2; for tests).
  void solve_one_by_one();
};

}  // namespace carom::detail
