// carom: the two-moving-balls time of impact over many pairs at once, on arrays (structure of
// arrays) so the compiler can run several pairs per instruction.
#pragma once

#include <cstddef>
#include <limits>
#include <span>

namespace carom {

// Written to t for a pair that does not touch during the step.
inline constexpr double kNoHit = std::numeric_limits<double>::infinity();

// Pair i: ball A at (a_x[i], a_y[i]) with radius a_radius[i] moving by (a_move_x[i],
// a_move_y[i]) during the step, and ball B likewise. Every span must have the same length.
struct BallPairArrays {
  std::span<const double> a_x, a_y, a_radius, a_move_x, a_move_y;
  std::span<const double> b_x, b_y, b_radius, b_move_x, b_move_y;
};

// For each pair, the fraction of the step in [0, 1] at which A and B first touch while
// approaching, exactly as sweep_ball_ball's t (bit-identical), or kNoHit. t.size() must equal
// the pairs' count. Returns the number of hits. Bad input (NaN or infinite values, a radius
// <= 0, spans of different lengths) throws carom::InvalidArgument naming the array and index.
// Any finite input is answered as sweep_ball_ball answers it (see its numeric range): a block
// of pairs holding one outside the ordinary window is redone pair by pair with the scalar code.
// t may be one of the input arrays (then every pair goes through the scalar code).
std::size_t sweep_ball_ball_batch(const BallPairArrays& pairs, std::span<double> t);

}  // namespace carom
