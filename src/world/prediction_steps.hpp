// carom internal: the steps of a ball's prediction that the engine's parts share
// (world_prediction.cpp predicts a ball whole; world_cell_crossing.cpp predicts a ball that
// crossed into a new cell from its new cells only), and the walks of the grid's lists they use.
// Defined here, inlined by force into each part: each runs once or more an event, where a call
// costs as much as its body. Design: docs/engine.md, "Prediction".
#pragma once

#include <bit>
#include <cstdint>

#include "engine_tuning.hpp"
#include "pair_batch.hpp"
#include "world_impl.hpp"

// GCC and clang both spell it this way; on a lambda it goes after the parameter list.
#define CAROM_ALWAYS_INLINE __attribute__((always_inline))

namespace carom {
namespace detail {

// Calls visit(first ball) for each list of the 3×3 block around the interior cell (cx, cy), in
// row-major order. Most of the nine cells are empty (a cell holds 0.4 balls at η = 0.3), so the
// heads are read first and only the occupied lists visited: an empty cell costs a comparison
// rather than a turn of the loop and a branch that often mispredicts; the lookahead asks for the
// heads in advance in large worlds, so this is the faster way at every size
// (docs/decisions/0008-selections-instead-of-branches.md).
template <typename Visit>
CAROM_ALWAYS_INLINE inline void for_each_block_list(const detail::Grid& grid, std::int32_t cx,
                                                    std::int32_t cy, Visit&& visit) {
  const detail::Grid::BlockHeads block = grid.block_heads(cx, cy);
  for (std::uint32_t occupied = block.occupied; occupied != 0; occupied &= occupied - 1) {
    visit(block.heads[std::countr_zero(occupied)]);
  }
}

// Names in `names`, from `count` on, the balls of a cell's list from `first`, all but `self`,
// and calls solve() (which empties the batch, count included) whenever the batch is full. The
// ball itself is in its cell's list: named, and counted out again, so that where it sits in the
// list needs no branch. (The count is the caller's local: GCC keeps a batch's count in memory,
// stored and loaded at every name.)
template <typename Solve>
CAROM_ALWAYS_INLINE inline void name_list(const detail::Grid& grid, std::int32_t first,
                                          std::uint32_t self, std::uint32_t* names,
                                          std::size_t& count, Solve&& solve) {
  for (std::int32_t j = first; j != detail::kNoBall;
       j = grid.next_ball(static_cast<std::uint32_t>(j))) {
    names[count] = static_cast<std::uint32_t>(j);
    count += static_cast<std::size_t>(static_cast<std::uint32_t>(j) != self);
    if (count == detail::PairBatch::kCapacity) solve();
  }
}

// name_list for each list of the 3×3 block around the interior cell (cx, cy).
template <typename Solve>
CAROM_ALWAYS_INLINE inline void name_block(const detail::Grid& grid, std::int32_t cx,
                                           std::int32_t cy, std::uint32_t self,
                                           std::uint32_t* names, std::size_t& count,
                                           Solve&& solve) {
  for_each_block_list(grid, cx, cy, [&](std::int32_t first) CAROM_ALWAYS_INLINE {
    name_list(grid, first, self, names, count, solve);
  });
}

}  // namespace detail

using detail::BallSlot;
using detail::Event;
using detail::EventKind;
using detail::for_each_block_list;
using detail::name_block;
using detail::name_list;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

// predict's first part: the earliest of leaving the cell and the walls listed in it, into
// `best`; the ball as the pair kernel asks for it, into `query`; and whether the balls around
// take the named path (a movable ball in an interior cell).
CAROM_ALWAYS_INLINE inline bool World::Impl::start_prediction(std::uint32_t ball, Event& best,
                                                              detail::SlotQuery& query,
                                                              PredictionCell& where) const {
  const BallSlot& b = balls[ball];
  const Vec2 p = b.position;
  const Vec2 v = b.velocity;
  best.owner = ball;

  // Leaving the cell, through the side it moves towards on each axis (x first on a tie). In a
  // box the outermost cells have no outer side to leave through (the grid's exit there is
  // infinite).
  const std::int32_t cell = grid.cell_of_ball(ball);
  const std::int32_t cx = grid.column(cell);
  const std::int32_t cy = grid.row(cell);
  const detail::CellExit exit =
      detail::cell_exit(p, v, time, grid.exit_x(cx, v.x > 0.0), grid.exit_y(cy, v.y > 0.0));
  best.time = exit.time;
  best.kind = EventKind::cell_crossing;
  best.partner = exit.side;

  // Walls listed in this cell.
  const detail::Species& kind = species[b.species];
  const Ball shape{p, kind.radius};
  for (const std::uint32_t w : grid.walls(cell)) {
    const double horizon = best.time < kInfinity ? best.time - time : kFarFuture;
    if (!walls[w].solid()) [[unlikely]] {
      consider_sensor(best, ball, w, shape, Motion{v, {}}, horizon);
      continue;
    }
    if (!meets_wall(ball, w)) continue;  // its filter lets it through
    const Impact impact = detail::time_of_impact(walls[w], shape, v, horizon);
    if (!impact.hit) continue;
    Event candidate;
    candidate.time = time + impact.t;
    candidate.kind = EventKind::ball_wall;
    candidate.owner = ball;
    candidate.partner = w;
    if (detail::earlier(candidate, best, handle_of.data())) best = candidate;
  }
  if (!sensor_inside.empty()) [[unlikely]]
    consider_inside_sensors(best, ball, shape, Motion{v, {}}, kFarFuture);
  if (!moving_walls.empty()) [[unlikely]] {
    consider_moving_walls(best, ball, shape, Motion{v, {}},
                          best.time < kInfinity ? best.time - time : kFarFuture);
  }

  // Balls in the neighbouring cells, next. Away from the grid's edges the 3×3 block is three
  // runs of three cells and, in a periodic world, no difference needs the minimum image:
  // neighbours lie within two cells, under half a period once the grid has five cells per axis
  // (so skipping it changes no bit). A movable ball there takes the named path; everything else
  // the gathered one, which computes the same pairs the same way.
  where.cell = cell;
  where.cx = cx;
  where.cy = cy;
  where.interior =
      grid.block_inside(cx, cy) && grid.nx() >= kInteriorMinCells && grid.ny() >= kInteriorMinCells;
  query.self = ball;
  query.p = p;
  query.v = v;
  query.now = time;
  query.radius = kind.radius;
  query.species = species.live() == 1 ? nullptr : species.data();
  query.horizon = kFarFuture;
  return where.interior && kind.movable();
}

// predict's second part, for a ball that start_prediction found.
CAROM_ALWAYS_INLINE inline void World::Impl::finish_prediction(bool named, Event& best,
                                                               const detail::SlotQuery& query,
                                                               const PredictionCell& where) {
  const bool found = named ? predict_named(query, where.cx, where.cy, best)
                           : predict_gathered(query.self, where.cell, where.interior, best);
  file_prediction(best, found);
}

// Sets the ball's slot to its prediction `best`; `found` says whether the prediction found a
// contact with some ball around it, at any time. A crossing keeps that (kClearBehind where none
// was found): cross_cell then looks only at the cells it brings into reach. Selected, not
// branched on: the kind is random.
CAROM_ALWAYS_INLINE inline void World::Impl::file_prediction(Event& best, bool found) {
  static_assert(detail::kClearBehind == 1);  // (so that !found is the flag: no branch)
  // (As a mask: GCC 12 makes a branch of the ?: form, which mispredicts;
  // docs/decisions/0008-selections-instead-of-branches.md.)
  const std::uint32_t crossing =
      0U - static_cast<std::uint32_t>(best.kind == EventKind::cell_crossing);
  best.partner_version =
      (static_cast<std::uint32_t>(!found) & crossing) | (best.partner_version & ~crossing);
  queue.set(best.owner, best);
}

// Keeps the earlier of `best` and a contact with `other` at `t` from now. Selected, not branched
// on: whether a hit comes before the best so far is random.
CAROM_ALWAYS_INLINE inline void World::Impl::consider_contact(Event& best, std::uint32_t other,
                                                              double t) const {
  Event candidate;
  candidate.time = time + t;
  candidate.kind = EventKind::ball_ball;
  candidate.owner = best.owner;
  candidate.partner = other;
  candidate.partner_version = balls[other].version;
  const Event options[2] = {best, candidate};
  best = options[detail::earlier(candidate, best, handle_of.data())];
}

// Considers a batch's answers for one ball: its pairs that hit (at times from now), and those
// outside the exact range, solved again by the scalar rescaled path. The earliest by a total
// order, so the order the pairs are visited in changes nothing.
CAROM_ALWAYS_INLINE inline bool World::Impl::take_hits(std::uint32_t hits, std::uint32_t rescales,
                                                       const detail::SlotQuery& query,
                                                       Event& best) const {
  const detail::PairBatch& batch = pair_batch;
  bool found = hits != 0;
  if (filters.active()) [[unlikely]] {
    hits = meeting(query.self, batch.other.data(), hits);
    rescales = meeting(query.self, batch.other.data(), rescales);
  }
  for (; hits != 0; hits &= hits - 1) {
    const auto k = static_cast<std::size_t>(std::countr_zero(hits));
    consider_contact(best, batch.other[k], batch.t[k]);
  }
  for (; rescales != 0; rescales &= rescales - 1) {
    const auto k = static_cast<std::size_t>(std::countr_zero(rescales));
    const BallSlot& other = balls[batch.other[k]];
    const detail::SlotPair pair = detail::slot_pair(other, query.p, query.v, query.now);
    const detail::Crossing crossing = detail::entry_crossing_rescaled(
        {pair.s, pair.u, detail::slot_reach(other, query)}, query.horizon);
    if (crossing.found) consider_contact(best, batch.other[k], crossing.t);
    found |= crossing.found;
  }
  return found;
}

// The lanes of `lanes` whose neighbour (others[k]) the ball meets under their filters: the pairs
// that pass through each other are dropped before they are considered.
inline std::uint32_t World::Impl::meeting(std::uint32_t ball, const std::uint32_t* others,
                                          std::uint32_t lanes) const {
  std::uint32_t kept = 0;
  for (std::uint32_t rest = lanes; rest != 0; rest &= rest - 1) {
    const auto k = static_cast<std::uint32_t>(std::countr_zero(rest));
    if (balls_meet(ball, others[k])) kept |= 1U << k;
  }
  return kept;
}

// The interior cell's neighbours of a movable ball: they are only named in the batch, and the
// kernel reads their slots itself (pair_batch.hpp, solve_slots), without copies of their offsets.
// (A movable ball meets every kind; an immovable one only movable ones, the gathered path's test.)
CAROM_ALWAYS_INLINE inline bool World::Impl::predict_named(const detail::SlotQuery& query,
                                                           std::int32_t cx, std::int32_t cy,
                                                           Event& best) {
  std::size_t count = 0;
  bool found = false;
  const auto solve = [&]() CAROM_ALWAYS_INLINE { found |= solve_named(query, count, best); };
  name_block(grid, cx, cy, query.self, pair_batch.other.data(), count, solve);
  solve();
  return found;
}

// Solves the batch's `count` named neighbours of the query's ball into `best`, and empties it;
// whether some pair meets.
CAROM_ALWAYS_INLINE inline bool World::Impl::solve_named(const detail::SlotQuery& query,
                                                         std::size_t& count, Event& best) {
  detail::PairBatch& batch = pair_batch;
  batch.count = count;
  batch.solve_slots(balls.data(), query);
  const bool found = take_hits(batch.hits, batch.rescales, query, best);
  batch.count = 0;
  count = 0;
  return found;
}

}  // namespace carom
