// carom internal: one ball's first contacts with a batch of neighbours, for the world's
// prediction. The same arithmetic as circle_crossing.hpp's entry_crossing_in_range, operation for
// operation (so every result is bit-identical), but evaluated for every pair without branches:
// the compiler can run the pairs through SIMD lanes, and the CPU never guesses wrong about which
// pairs approach (about half, at random: a mispredicted branch costs as much as a pair's
// arithmetic). Pairs outside exact_range.hpp's window are flagged for the scalar, rescaled path.
// Solved four pairs a vector operation on CPUs with AVX2 (pair_batch.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ball_slot.hpp"
#include "carom/vec2.hpp"
#include "species.hpp"

namespace carom::detail {

// What solve_slots needs of the ball whose pairs it solves: its slot, where it is (p) and how it
// moves (v) at time `now`, its radius, and the horizon of solve(). A pair's reach is
// radius + the neighbour's radius: species[neighbour's species].radius, or, where `species` is
// null (a world of one kind), radius again.
struct SlotQuery {
  std::uint32_t self = 0;
  Vec2 p;
  Vec2 v;
  double now = 0.0;
  double radius = 0.0;
  const Species* species = nullptr;
  double horizon = 0.0;
};

struct PairBatch {
  static constexpr std::size_t kCapacity = 32;  // a bit of a 32-bit mask per pair
  // The inputs' arrays hold four pairs more, so that solve pads the last group of four without
  // a loop whose length (and so whose exit branch) changes from batch to batch.
  static constexpr std::size_t kInputCapacity = kCapacity + 4;
  enum Outcome : std::uint8_t { kMiss = 0, kHit = 1, kRescale = 2 };

  // (The cache-line-aligned arrays first, the small ones after: no padding between them.)
  // Pair k: the offset s (this ball minus the neighbour), the relative velocity u and the sum of
  // the radii; the neighbour's slot.
  alignas(64) std::array<double, kInputCapacity> sx;
  alignas(64) std::array<double, kInputCapacity> sy;
  alignas(64) std::array<double, kInputCapacity> ux;
  alignas(64) std::array<double, kInputCapacity> uy;
  alignas(64) std::array<double, kInputCapacity> reach;
  // Filled by solve(): the time from now of each hit, and what became of the pairs as bit masks
  // (bit k for pair k), so that the caller visits the few hits alone: pairs that hit, and pairs
  // outside the exact range (whose answer is the scalar, rescaled path's; the rest miss).
  alignas(64) std::array<double, kCapacity> t;
  // (Room for four more: solve_slots pads the last group of four with the ball itself.)
  std::array<std::uint32_t, kInputCapacity> other;
  std::uint32_t hits = 0;
  std::uint32_t rescales = 0;
  std::size_t count = 0;

  void push(Vec2 s, Vec2 u, double radius_sum, std::uint32_t neighbour) {
    sx[count] = s.x;
    sy[count] = s.y;
    ux[count] = u.x;
    uy[count] = u.y;
    reach[count] = radius_sum;
    other[count] = neighbour;
    ++count;
  }
  // push, but a pair that is `dropped` is written and not counted (the next push overwrites it):
  // no branch.
  void push_unless(Vec2 s, Vec2 u, double radius_sum, std::uint32_t neighbour, bool dropped) {
    push(s, u, radius_sum, neighbour);
    count -= static_cast<std::size_t>(dropped);
  }
  [[nodiscard]] bool full() const { return count == kCapacity; }
  [[nodiscard]] Outcome outcome(std::size_t k) const {
    if (((rescales >> k) & 1U) != 0) return kRescale;
    return ((hits >> k) & 1U) != 0 ? kHit : kMiss;
  }

  // entry_crossing_in_range for every pair, with the horizon at +infinity's largest finite
  // stand-in (the world's kFarFuture); pairs whose magnitudes leave the exact range get
  // kRescale, whatever the arithmetic here gave. With AVX2 four at a time (pair_batch.cpp).
  void solve(double horizon);
  // The same, one pair at a time whatever the CPU (what solve does without AVX2; for tests).
  void solve_one_by_one(double horizon);

  // The pairs of one ball with the balls other[0 .. count), read from their slots rather than
  // pushed: each pair's offset, relative velocity and reach are slot_pair's, formed inside the
  // kernel, so that neighbours need no copying into the arrays above (which it leaves as they
  // were). The answers are those of push() and solve() on slot_pair's values, bit for bit. The
  // ball itself is not among the others (its slot fills the last group of four). With AVX2 four
  // pairs at a time.
  void solve_slots(const BallSlot* slots, const SlotQuery& query);
  // The same, one pair at a time whatever the CPU (for tests).
  void solve_slots_one_by_one(const BallSlot* slots, const SlotQuery& query);

  // The pairs of two balls at once (a contact's two balls, predicted together so that the
  // processor overlaps their work): pair k is `second`'s where bit k of `second_lanes` is set,
  // `first`'s otherwise, and each answer is that ball's solve_slots answer, bit for bit. Both
  // queries are at one time, with one horizon and one species table (the first's are read).
  void solve_slots_of_two(const BallSlot* slots, const SlotQuery& first, const SlotQuery& second,
                          std::uint32_t second_lanes);
  // The same, one pair at a time whatever the CPU (for tests).
  void solve_slots_of_two_one_by_one(const BallSlot* slots, const SlotQuery& first,
                                     const SlotQuery& second, std::uint32_t second_lanes);
};

// A pair as the world's prediction forms it: the offset of the ball at p from the neighbour's
// position at `now`, and the relative velocity (what solve_slots forms in its lanes, operation
// for operation).
struct SlotPair {
  Vec2 s;
  Vec2 u;
};
[[nodiscard]] inline SlotPair slot_pair(const BallSlot& other, Vec2 p, Vec2 v, double now) {
  return {p - other.position_at(now), v - other.velocity};
}
// The pair's sum of radii, as SlotQuery says.
[[nodiscard]] inline double slot_reach(const BallSlot& other, const SlotQuery& query) {
  return query.radius +
         (query.species != nullptr ? query.species[other.species].radius : query.radius);
}

}  // namespace carom::detail
