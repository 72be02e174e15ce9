// Prediction: each ball's one pending event, the earliest of its contacts with the balls and
// walls around it and its leaving its cell (docs/engine.md, "One event per ball", "Prediction").
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

// ---- prediction ---------------------------------------------------------------------------

void World::Impl::advance(std::uint32_t ball, double t) {
  if (accelerated) [[unlikely]] {
    if (table_on) {
      advance_on_table(ball, t);
    } else {
      advance_under_gravity(ball, t);
    }
    return;
  }
  BallSlot& b = balls[ball];
  b.position = b.position_at(t);
  b.local_time = t;
}

void World::Impl::synchronize(double t) {
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (balls[i].alive()) advance(i, t);
  }
  time = t;
}

void World::Impl::predict_all() {
  synchronize(time);  // prediction reads each ball's record as being at the world's time
  queue.reset(static_cast<std::uint32_t>(balls.size()));
  queue.use_handles(handle_of.data());
  lookahead.passed_bucket = -1;
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (balls[i].alive()) predict(i);
  }
  events_valid = true;
}

// The changed ball is at the world's time (or dead). Its prediction is what a contact's would
// be: its slot covers every pair it is now in, and a neighbour's event with the ball as it was
// is stale by the ball's version and is re-predicted when it comes up (docs/engine.md, "One
// event per ball").
void World::Impl::repredict_changed(std::uint32_t ball) {
  if (!events_valid) return;            // the next run predicts every ball anyway
  queue.use_handles(handle_of.data());  // add_ball may have moved the array
  queue.reserve_slots(static_cast<std::uint32_t>(balls.size()));  // a ball added in a new slot
  if (!balls[ball].alive()) {
    queue.set(ball, Event{});  // nothing will happen to a removed ball
    return;
  }
  predict(ball);
}

// Ball `ball` is at the world's time. Its slot gets its earliest event: a contact with a ball
// in the 3×3 block of cells around it or a wall listed in its cell, or leaving its cell. The
// other ball's slot is left alone: this one's covers their pair (docs/engine.md, "One event per
// ball").
void World::Impl::predict(std::uint32_t ball) {
  if (general_motion) [[unlikely]] {
    if (accelerated) {
      predict_under_gravity(ball);
    } else {
      predict_growing(ball);
    }
    return;
  }
  Event best;
  detail::SlotQuery query;
  PredictionCell where;
  const bool named = start_prediction(ball, best, query, where);
  finish_prediction(named, best, query, where);
}

// A contact's two balls, each as predict would, i's slot set first. Where both take the named
// path their neighbours go into one batch, solved by one kernel call: the two predictions are
// independent, and so the processor overlaps their chains of loads and arithmetic
// (docs/decisions/0009-pair-kernel-avx2.md).
void World::Impl::predict_both(std::uint32_t i, std::uint32_t j) {
  Event best_i;
  Event best_j;
  detail::SlotQuery query_i;
  detail::SlotQuery query_j;
  PredictionCell where_i;
  PredictionCell where_j;
  const bool named_i = start_prediction(i, best_i, query_i, where_i);
  const bool named_j = start_prediction(j, best_j, query_j, where_j);
  if (!named_i || !named_j) {
    finish_prediction(named_i, best_i, query_i, where_i);
    finish_prediction(named_j, best_j, query_j, where_j);
    return;
  }
  detail::PairBatch& batch = pair_batch;
  constexpr std::size_t kCapacity = detail::PairBatch::kCapacity;
  std::size_t count = 0;
  // The batch's lanes from `split` on are j's: none while i's block is named, all once a full
  // batch was solved during j's.
  std::size_t split = kCapacity;
  bool found_i = false;
  bool found_j = false;
  const auto solve = [&]() CAROM_ALWAYS_INLINE {
    const std::uint32_t second_lanes = split < kCapacity ? ~0U << split : 0U;
    batch.count = count;
    batch.solve_slots_of_two(balls.data(), query_i, query_j, second_lanes);
    found_i |=
        take_hits(batch.hits & ~second_lanes, batch.rescales & ~second_lanes, query_i, best_i);
    found_j |= take_hits(batch.hits & second_lanes, batch.rescales & second_lanes, query_j, best_j);
    batch.count = 0;
    count = 0;
    split = split < kCapacity ? 0 : kCapacity;
  };
  name_block(grid, where_i.cx, where_i.cy, i, batch.other.data(), count, solve);
  split = count;
  name_block(grid, where_j.cx, where_j.cy, j, batch.other.data(), count, solve);
  solve();
  file_prediction(best_i, found_i);
  file_prediction(best_j, found_j);
}

// Every other case: the edges of the grid (clipped, or wrapped with the minimum image), small
// periodic grids (every image), immovable balls. Neighbours are gathered into a batch
// (offset, relative velocity, sum of radii) whose pairs are solved together (pair_batch.hpp),
// then each hit considered. The lambdas are inlined by force: each runs several times a
// prediction, where a call costs as much as its body.
[[gnu::noinline]] bool World::Impl::predict_gathered(std::uint32_t ball, std::int32_t cell,
                                                     bool interior, Event& best) const {
  const BallSlot& b = balls[ball];
  const Vec2 p = b.position;
  const Vec2 v = b.velocity;
  const detail::Species& kind = species[b.species];
  const std::int32_t cx = grid.column(cell);
  const std::int32_t cy = grid.row(cell);
  const bool movable = kind.movable();
  detail::PairBatch batch;
  bool found = false;
  const auto solve_batch = [&]() CAROM_ALWAYS_INLINE {
    batch.solve(kFarFuture);
    found |= batch.hits != 0;
    if (filters.active()) [[unlikely]] {
      batch.hits = meeting(ball, batch.other.data(), batch.hits);
      batch.rescales = meeting(ball, batch.other.data(), batch.rescales);
    }
    for (std::uint32_t hits = batch.hits; hits != 0; hits &= hits - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(hits));
      consider_contact(best, batch.other[k], batch.t[k]);
    }
    for (std::uint32_t rescales = batch.rescales; rescales != 0; rescales &= rescales - 1) {
      const auto k = static_cast<std::size_t>(std::countr_zero(rescales));
      const detail::Crossing crossing = detail::entry_crossing_rescaled(
          {{batch.sx[k], batch.sy[k]}, {batch.ux[k], batch.uy[k]}, batch.reach[k]}, kFarFuture);
      if (crossing.found) consider_contact(best, batch.other[k], crossing.t);
      found |= crossing.found;
    }
    batch.count = 0;
  };
  // How a neighbour's offset is taken: as it is, as the minimum image, or as the minimum image
  // and its eight neighbouring images (periodic grids with few cells, below).
  enum Images { kDirect, kNearest, kAround };
  const auto gather_list = [&](std::int32_t first, auto images) CAROM_ALWAYS_INLINE {
    for (std::int32_t j = first; j != detail::kNoBall;
         j = grid.next_ball(static_cast<std::uint32_t>(j))) {
      const auto other = static_cast<std::uint32_t>(j);
      // The ball itself is in its cell's list. The one-image paths push it and drop it (count
      // not advanced, below) rather than skip it by a branch, which mispredicts wherever it sits
      // in the list; the nine-image path (small periodic grids, rare) skips it here.
      if constexpr (images == kAround) {
        if (other == ball) continue;
      }
      const BallSlot& o = balls[other];
      const detail::Species& other_kind = species[o.species];
      if (!movable && !other_kind.movable()) continue;  // nothing can respond
      const detail::SlotPair pair = detail::slot_pair(o, p, v, time);
      const double reach = kind.radius + other_kind.radius;
      if constexpr (images == kDirect) {
        batch.push_unless(pair.s, pair.u, reach, other, other == ball);
      } else if constexpr (images == kNearest) {
        batch.push_unless(minimum_image(pair.s), pair.u, reach, other, other == ball);
      } else {
        const Vec2 nearest = minimum_image(pair.s);
        for (int kx = -1; kx <= 1; ++kx) {
          for (int ky = -1; ky <= 1; ++ky) {
            if (batch.count + 1 > detail::PairBatch::kCapacity) solve_batch();
            batch.push(nearest + Vec2{kx * periodic_cell.period().x, ky * periodic_cell.period().y},
                       pair.u, reach, other);
          }
        }
      }
      if (batch.full()) solve_batch();
    }
  };
  const auto gather = [&](std::int32_t neighbour, auto images)
                          CAROM_ALWAYS_INLINE { gather_list(grid.first_ball(neighbour), images); };
  using Direct = std::integral_constant<Images, kDirect>;
  using Nearest = std::integral_constant<Images, kNearest>;
  using Around = std::integral_constant<Images, kAround>;
  const bool periodic = def.boundary == Boundary::periodic;
  // A periodic grid with fewer cells per axis than this lets a pair meet through an image other
  // than the one nearest when it was predicted (docs/world.md, "Boundaries"): all nine are tried.
  const bool few_cells =
      periodic && (grid.nx() < kSingleImageMinCells || grid.ny() < kSingleImageMinCells);
  if (few_cells) {
    grid.for_each_neighbour(cell, [&](std::int32_t n) { gather(n, Around{}); });
  } else if (interior) {
    for_each_block_list(grid, cx, cy, [&](std::int32_t first) { gather_list(first, Direct{}); });
  } else if (periodic) {
    grid.for_each_neighbour(cell, [&](std::int32_t n) { gather(n, Nearest{}); });
  } else {
    grid.for_each_neighbour(cell, [&](std::int32_t n) { gather(n, Direct{}); });
  }
  solve_batch();
  return found;
}

}  // namespace carom
