// carom benchmarks: one pair through carom's scalar query, reduced to what the batch writes.
#pragma once

#include <cstddef>

#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"
#include "random_pairs.hpp"

namespace carom::bench {

// sweep_ball_ball's t for pair i when the balls touch, else carom::kNoHit: the value
// sweep_ball_ball_batch must write for the pair, bit for bit.
[[nodiscard]] inline double scalar_t(const RandomPairs& p, std::size_t i) {
  const Impact impact =
      sweep_ball_ball(Ball{{p.a_x[i], p.a_y[i]}, p.a_radius[i]}, {p.a_move_x[i], p.a_move_y[i]},
                      Ball{{p.b_x[i], p.b_y[i]}, p.b_radius[i]}, {p.b_move_x[i], p.b_move_y[i]});
  return impact.hit ? impact.t : kNoHit;
}

}  // namespace carom::bench
