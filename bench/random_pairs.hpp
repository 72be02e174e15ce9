// carom benchmarks: reproducible random ball pairs stored as arrays (structure of arrays). Every
// time-of-impact benchmark reads these, so carom's batch, carom's scalar query and Box2D all
// answer the same pairs.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cache_line_allocator.hpp"
#include "carom/sweep_batch.hpp"

namespace carom::bench {

// Pair i: ball A at (a_x[i], a_y[i]) with radius a_radius[i] moving by (a_move_x[i],
// a_move_y[i]) during the step, and ball B likewise; the layout of carom::BallPairArrays.
struct RandomPairs {
  Column a_x, a_y, a_radius, a_move_x, a_move_y;
  Column b_x, b_y, b_radius, b_move_x, b_move_y;

  [[nodiscard]] std::size_t size() const { return a_x.size(); }
  [[nodiscard]] BallPairArrays arrays() const;
};

// Fixed, so that every run and every machine times the same pairs.
inline constexpr std::uint64_t kPairsSeed = 20240601;

// Pairs as a broad phase would hand them over: the balls start apart, up to one length unit
// between their surfaces, and A moves roughly towards B (within 45 degrees) while B drifts. About
// half of them touch during the step, in an order no branch predictor can learn. Lengths suit
// Box2D too (metres, radii 0.1 to 0.5). The numbers come from std::mt19937_64 through this
// file's own conversions, not the <random> distributions, whose output differs between standard
// libraries: the same seed gives the same pairs everywhere, up to the last bit of std::cos and
// std::sin, which math libraries may round differently.
[[nodiscard]] RandomPairs make_random_pairs(std::size_t count, std::uint64_t seed = kPairsSeed);

// make_random_pairs(count) made once per process and kept, so that benchmarks of the same size
// share one set (the 10^6 set takes 80 MB).
[[nodiscard]] const RandomPairs& shared_random_pairs(std::size_t count);

}  // namespace carom::bench
