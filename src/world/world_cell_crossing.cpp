// A ball leaving its cell: moved to the next one and predicted from the cells the crossing brings
// into reach (docs/engine.md, "Crossing a cell").
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "carom/error.hpp"
#include "cell_exit.hpp"
#include "contact_pace.hpp"
#include "core/bowl_bounce.hpp"
#include "core/circle_crossing.hpp"
#include "core/impulse.hpp"
#include "core/validate.hpp"
#include "engine_tuning.hpp"
#include "pair_batch.hpp"
#include "permute.hpp"
#include "prediction_steps.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::Event;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

void World::Impl::cross_cell(std::uint32_t ball, std::uint32_t side, double t, bool clear_behind) {
  advance(ball, t);
  BallSlot& b = balls[ball];
  const std::int32_t cell = grid.cell_of_ball(ball);
  std::int32_t cx = grid.column(cell);
  std::int32_t cy = grid.row(cell);
  const bool interior_before = grid.block_inside(cx, cy);
  // By table, indexed by the side: which side is random, a branch on it mispredicts.
  static constexpr std::int32_t kStepX[4] = {-1, 1, 0, 0};  // kLeft, kRight, kDown, kUp
  static constexpr std::int32_t kStepY[4] = {0, 0, -1, 1};
  static_assert(detail::kLeft == 0 && detail::kRight == 1 && detail::kDown == 2 &&
                detail::kUp == 3);
  cx += kStepX[side & 3];
  cy += kStepY[side & 3];
  if (def.boundary == Boundary::periodic) {
    // Leaving the periodic cell: re-enter at the opposite side, the position shifted by a period.
    const Vec2 size = def.upper - def.lower;
    if (cx < 0) {
      cx += grid.nx();
      b.position.x += size.x;
    } else if (cx >= grid.nx()) {
      cx -= grid.nx();
      b.position.x -= size.x;
    }
    if (cy < 0) {
      cy += grid.ny();
      b.position.y += size.y;
    } else if (cy >= grid.ny()) {
      cy -= grid.ny();
      b.position.y -= size.y;
    }
  } else if (cx < 0 || cx >= grid.nx() || cy < 0 || cy >= grid.ny()) {
    // An open world's ball leaving the grid: bring everyone to now and grow the grid.
    synchronize(t);
    rebuild_grid(b.position, radius_of(ball));
    predict_all();
    return;
  }
  grid.erase(ball);
  grid.insert(ball, grid.index(cx, cy));
  if (general_motion) [[unlikely]] {
    if (accelerated) {
      predict_under_gravity(ball);
    } else {
      predict_growing(ball, clear_behind && interior_before ? side : kWholeBlock);
    }
    return;
  }
  Event best;
  detail::SlotQuery query;
  PredictionCell where;
  const bool named = start_prediction(ball, best, query, where);
  if (!(clear_behind && named && interior_before)) {
    finish_prediction(named, best, query, where);
    return;
  }
  // The last prediction found no contact with any ball of the old block, and of its nine cells
  // the new block keeps six: only the three it brings into reach, across the new cell's far
  // side, are looked at (docs/engine.md, "Crossing a cell").
  const std::int32_t step_x = kStepX[side & 3];
  const std::int32_t step_y = kStepY[side & 3];
  const std::int32_t first =
      step_x != 0 ? grid.index(cx + step_x, cy - 1) : grid.index(cx - 1, cy + step_y);
  const std::int32_t stride = step_x != 0 ? grid.nx() : 1;
  std::size_t count = 0;
  bool found = false;
  const auto solve = [&]() CAROM_ALWAYS_INLINE { found |= solve_named(query, count, best); };
  for (std::int32_t k = 0; k < 3; ++k) {
    name_list(grid, grid.first_ball(first + k * stride), ball, pair_batch.other.data(), count,
              solve);
  }
  solve();
  file_prediction(best, found);
}

}  // namespace carom
