// Prediction under growth: a ball's one pending event when every movable radius grows at one
// rate and every ball moves on a straight line (docs/engine.md, "Growth"). A pair's gap is then
// the quadratic of the pair equation, taken in closed form where it is clear of its rounding
// (core/growing_pair.hpp) and by the certified isolation elsewhere; the cell's exit is the
// straight-line one; and, as without growth, a crossing whose last prediction met no ball looks
// only at the three cells it brings into reach (docs/engine.md, "Crossing a cell").
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cell_exit.hpp"
#include "core/accelerated_sweep.hpp"
#include "core/circle_crossing.hpp"
#include "engine_tuning.hpp"
#include "growing_pair_batch.hpp"
#include "prediction_steps.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::Event;
using detail::EventKind;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

void World::Impl::predict_growing(std::uint32_t ball, std::uint32_t crossed) {
  const BallSlot& b = balls[ball];
  const Vec2 p = b.position;  // at the world's time
  const Vec2 v = b.velocity;
  const detail::Species& kind = species[b.species];
  const bool movable_ball = kind.movable();
  // A movable radius now is its radius at growth_start times this (radius_at's arithmetic).
  const double scale = 1.0 + growth_relative * (time - growth_start);
  const double radius = movable_ball ? kind.radius * scale : kind.radius;
  const double growth = movable_ball ? kind.radius * growth_relative : 0.0;
  Event best;
  best.owner = ball;

  // Leaving the cell: the straight-line exit (growth moves no centre).
  const std::int32_t cell = grid.cell_of_ball(ball);
  const std::int32_t cx = grid.column(cell);
  const std::int32_t cy = grid.row(cell);
  const detail::CellExit exit =
      detail::cell_exit(p, v, time, grid.exit_x(cx, v.x > 0.0), grid.exit_y(cy, v.y > 0.0));
  best.time = exit.time;
  best.kind = EventKind::cell_crossing;
  best.partner = exit.side;
  // Contacts after the ball leaves its cell are found again from the next one.
  const auto horizon = [&] { return best.time < kInfinity ? best.time - time : kFarFuture; };
  const auto consider = [&](double t, EventKind event_kind, std::uint32_t partner,
                            std::uint32_t partner_version) {
    consider_event(best, ball, t, event_kind, partner, partner_version);
  };

  const Motion motion{v, {}, growth};
  const Ball shape{p, radius};
  for (const std::uint32_t w : grid.walls(cell)) {
    if (!walls[w].solid()) {
      consider_sensor(best, ball, w, shape, motion, horizon());
      continue;
    }
    const Impact impact = detail::time_of_impact(walls[w], shape, motion, horizon());
    if (impact.hit) consider(impact.t, EventKind::ball_wall, w, 0);
  }
  if (!sensor_inside.empty()) consider_inside_sensors(best, ball, shape, motion, horizon());
  if (!moving_walls.empty()) consider_moving_walls(best, ball, shape, motion, horizon());

  // A neighbour's radius now and growth speed, as radius_at and growth_of give them.
  struct Size {
    double radius;
    double growth;
  };
  const auto size_of = [&](std::uint32_t other) CAROM_ALWAYS_INLINE {
    const detail::Species& other_kind = species[balls[other].species];
    return other_kind.movable()
               ? Size{other_kind.radius * scale, other_kind.radius * growth_relative}
               : Size{other_kind.radius, 0.0};
  };
  // Whether some pair meets at some time (or may: an undecided one), so that a crossing that
  // finds none can look ahead only.
  bool met = false;
  detail::GrowingPairBatch batch;
  batch.count = 0;
  // The batch's closings, and its undecided pairs by the certified isolation.
  const auto solve_batch = [&] {
    batch.solve();
    met |= (batch.closings | batch.undecided) != 0;
    for (std::uint32_t closings = batch.closings; closings != 0; closings &= closings - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(closings));
      const std::uint32_t other = batch.other[k];
      if (batch.t[k] <= horizon()) {
        consider(batch.t[k], EventKind::ball_ball, other, balls[other].version);
      }
    }
    for (std::uint32_t undecided = batch.undecided; undecided != 0; undecided &= undecided - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(undecided));
      const std::uint32_t other = batch.other[k];
      const BallSlot& o = balls[other];
      const Size other_size = size_of(other);
      const Vec2 offset{batch.sx[k], batch.sy[k]};
      const Impact impact =
          detail::accelerated_ball_ball(Ball{offset, radius}, motion, Ball{{}, other_size.radius},
                                        Motion{o.velocity, {}, other_size.growth}, horizon());
      if (!impact.hit) continue;
      // A contact at the world's time itself counts only where the response will act on it:
      // the two approach or grow (else the pair, left alone, would be predicted again at once).
      if (time + impact.t == time && offset != Vec2{} && growth + other_size.growth == 0.0 &&
          !detail::approaching(v, o.velocity, normalized(-offset))) {
        continue;
      }
      consider(impact.t, EventKind::ball_ball, other, o.version);
    }
    batch.count = 0;
  };
  // offset: from the other ball's centre to this one's, at the world's time. A pair that is
  // `dropped` (the ball itself, in its cell's list) is written and not counted: no branch.
  const auto pair = [&](std::uint32_t other, Vec2 offset, bool dropped) CAROM_ALWAYS_INLINE {
    if (!movable_ball && !movable(other)) return;  // nothing can respond
    const Size other_size = size_of(other);
    batch.push(offset, v - balls[other].velocity, radius + other_size.radius,
               growth + other_size.growth, other);
    batch.count -= static_cast<std::size_t>(dropped);
    if (batch.full()) solve_batch();
  };
  const auto pair_direct = [&](std::int32_t first) CAROM_ALWAYS_INLINE {
    for (std::int32_t j = first; j != detail::kNoBall;
         j = grid.next_ball(static_cast<std::uint32_t>(j))) {
      const auto other = static_cast<std::uint32_t>(j);
      pair(other, p - balls[other].position_at(time), other == ball);
    }
  };

  const bool periodic = def.boundary == Boundary::periodic;
  const bool interior =
      grid.block_inside(cx, cy) && grid.nx() >= kInteriorMinCells && grid.ny() >= kInteriorMinCells;
  if (crossed != kWholeBlock && interior && movable_ball) {
    // The last prediction met no ball of the old block, whose six cells the new one keeps: only
    // the three across the new cell's far side are new (as world_cell_crossing.cpp reasons).
    static constexpr std::int32_t kStepX[4] = {-1, 1, 0, 0};  // kLeft, kRight, kDown, kUp
    static constexpr std::int32_t kStepY[4] = {0, 0, -1, 1};
    const std::int32_t step_x = kStepX[crossed & 3];
    const std::int32_t step_y = kStepY[crossed & 3];
    const std::int32_t first =
        step_x != 0 ? grid.index(cx + step_x, cy - 1) : grid.index(cx - 1, cy + step_y);
    const std::int32_t stride = step_x != 0 ? grid.nx() : 1;
    for (std::int32_t k = 0; k < 3; ++k) pair_direct(grid.first_ball(first + k * stride));
  } else if (interior) {
    // Away from the grid's edges no offset needs an image (prediction_steps.hpp says why).
    for_each_block_list(grid, cx, cy, pair_direct);
  } else {
    const bool few_cells =
        periodic && (grid.nx() < kSingleImageMinCells || grid.ny() < kSingleImageMinCells);
    grid.for_each_neighbour(cell, [&](std::int32_t neighbour) {
      for (std::int32_t j = grid.first_ball(neighbour); j != detail::kNoBall;
           j = grid.next_ball(static_cast<std::uint32_t>(j))) {
        const auto other = static_cast<std::uint32_t>(j);
        if (other == ball) continue;
        const Vec2 offset = p - balls[other].position_at(time);
        if (!periodic) {
          pair(other, offset, false);
        } else if (!few_cells) {
          pair(other, minimum_image(offset), false);
        } else {
          const Vec2 nearest = minimum_image(offset);
          const Vec2 period = periodic_cell.period();
          for (int kx = -1; kx <= 1; ++kx) {
            for (int ky = -1; ky <= 1; ++ky)
              pair(other, nearest + Vec2{kx * period.x, ky * period.y}, false);
          }
        }
      }
    });
  }
  solve_batch();
  if (best.kind == EventKind::cell_crossing && !met && interior && movable_ball) {
    best.partner_version = detail::kClearBehind;
  }
  queue.set(ball, best);
}

}  // namespace carom
