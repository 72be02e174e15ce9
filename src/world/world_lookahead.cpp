// Large worlds' lookahead: each time the queue's current bucket advances, the cache is asked for
// what the events of the next buckets will read, one more level of indirection each time, so
// that their misses overlap the work in between rather than stalling it when each event comes
// up. It only prefetches and reads: no result depends on it. Design: docs/engine.md, "Memory";
// measurements: docs/decisions/0013-lookahead-in-large-worlds.md.
#include <algorithm>

#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::EventKind;

namespace {

// The walk reaches this many buckets ahead of the current one (about two events a bucket): the
// j-th event of bucket current + d is at stage kReach − d − j, so its own records are asked for
// some ten events before it comes up, far more than a memory round trip. Measured at 10⁵ and
// 10⁶ balls: 4 worse at 10⁶, 5, 6 and 9 alike (8 and more were worse at 10⁵ with d2b8310's
// walk, which went down each list from its head every time).
constexpr std::int64_t kReach = 6;
// After a jump of the current bucket over empty ones, a walk is made for each bucket passed,
// up to this many; after a longer one every bucket in reach starts again at its first ball.
// (Walking for the last bucket alone measured 7 % slower at 10⁶ with d2b8310's walk.)
constexpr std::int64_t kMostWalks = 3;
static_assert(kReach < detail::Lookahead::kCursors);
constexpr auto kCursors = static_cast<std::size_t>(detail::Lookahead::kCursors);

// A ball's slot, one line with its grid entries (ball_slot.hpp). (Inlined by force, as
// Grid::prefetch_block_heads is: GCC drops calls to a function whose only effects are
// prefetches.)
[[gnu::always_inline]] inline void prefetch_slot(const BallSlot& slot) {
  __builtin_prefetch(&slot);
}

}  // namespace

void World::Impl::look_ahead() {
  const std::int64_t current = queue.current_bucket();
  const std::int64_t passed = lookahead.passed_bucket;
  lookahead_noted();
  if (passed >= 0 && current > passed && current - passed <= kMostWalks) {
    for (std::int64_t bucket = passed + 1; bucket <= current; ++bucket) lookahead_walk(bucket);
  } else {
    // The first call, a new year or queue, a re-ordered queue, or a jump over many empty
    // buckets: every bucket in reach starts again at its first ball.
    for (std::int64_t d = 1; d <= kReach; ++d) lookahead_enter(current + d);
  }
  lookahead.passed_bucket = current;
  lookahead.parity ^= 1;
}

// Stage 0 of an event's ball: its own records.
[[gnu::always_inline]] inline void World::Impl::lookahead_stage_0(std::uint32_t ball) const {
  prefetch_slot(balls[ball]);
  queue.prefetch_slot(ball);
}

// Stage 1, from the records stage 0 asked for: its pair partner's records, and the list heads of
// the block of cells its next prediction walks (after a cell crossing, the block around the
// cell it enters).
[[gnu::always_inline]] inline void World::Impl::lookahead_stage_1(std::uint32_t ball) {
  // Selections rather than branches: kinds and sides are random.
  const EventKind kind = queue.kind_of(ball);
  const bool pair = kind == EventKind::ball_ball;
  const std::uint32_t named = queue.partner_of(ball);  // a ball, a wall or a side, by the kind
  const std::uint32_t partners[2] = {ball, named};
  const std::uint32_t partner = partners[pair];
  prefetch_slot(balls[partner]);
  queue.prefetch_slot(partner);
  lookahead.partners[lookahead.parity].push_if(partner, pair);
  const std::int32_t cell = grid.cell_of_ball(ball);
  if (cell == detail::kNoBall) return;
  static constexpr std::int32_t kStepX[5] = {-1, 1, 0, 0, 0};  // kLeft, kRight, kDown, kUp, none
  static constexpr std::int32_t kStepY[5] = {0, 0, -1, 1, 0};
  const std::uint32_t sides[2] = {4, named & 3};
  const std::uint32_t side = sides[kind == EventKind::cell_crossing];
  lookahead_block(grid.column(cell) + kStepX[side], grid.row(cell) + kStepY[side]);
}

// Asks for the list heads of the 3 × 3 block around cell (cx, cy) and notes the cell for the
// next call, when the block is an interior one (the rest are few).
[[gnu::always_inline]] inline void World::Impl::lookahead_block(std::int32_t cx, std::int32_t cy) {
  if (!grid.block_inside(cx, cy)) return;
  grid.prefetch_block_heads(cx, cy);
  lookahead.cells[lookahead.parity].push_if(grid.index(cx, cy), true);
}

// Stages 2 and 3, from what the last call noted (a call comes an event or more after the last).
void World::Impl::lookahead_noted() {
  const int now = lookahead.parity;
  const int last = now ^ 1;
  // Stage 3: the second balls of the cells whose first balls the last call asked for (deep
  // lookahead only: none were noted otherwise).
  for (const std::uint32_t first : lookahead.first_balls[last]) {
    const std::int32_t second = grid.next_ball(first);
    const auto ball = static_cast<std::uint32_t>(second != detail::kNoBall ? second : 0);
    prefetch_slot(balls[ball]);
  }
  lookahead.first_balls[last].clear();
  // Stage 2: the first balls of the blocks whose heads the last call asked for (the check keeps
  // a cell noted before the grid was re-planned inside it) ...
  const std::int32_t nx = grid.nx();
  const std::int32_t cells = nx * grid.ny();
  auto& firsts = lookahead.first_balls[now];
  std::uint32_t found = firsts.count;
  for (const std::int32_t cell : lookahead.cells[last]) {
    if (cell <= nx || cell + nx + 1 >= cells) continue;
    if (found + 9 > firsts.kCapacity) break;  // (a burst past the list's room drops the rest)
    for (const std::int32_t row : {cell - nx, cell, cell + nx}) {
      for (std::int32_t at = row - 1; at <= row + 1; ++at) {
        const std::int32_t head = grid.first_ball(at);
        found = firsts.push_if_at(found, static_cast<std::uint32_t>(head), head != detail::kNoBall);
      }
    }
  }
  firsts.count = found;
  for (const std::uint32_t first : firsts) {
    prefetch_slot(balls[first]);
  }
  if (!lookahead.deep) firsts.clear();
  lookahead.cells[last].clear();
  // ... and, for the partners noted, the links that taking their events out of their lists
  // writes, and their blocks (their cells' records were asked for by the last call).
  for (const std::uint32_t partner : lookahead.partners[last]) {
    queue.prefetch_list_neighbours(partner);
    if (!lookahead.deep) continue;
    const std::int32_t cell = grid.cell_of_ball(partner);
    if (cell != detail::kNoBall) lookahead_block(grid.column(cell), grid.row(cell));
  }
  lookahead.partners[last].clear();
}

// Stages 0 and 1 along the lists of the buckets ahead of `current`: the j-th event of bucket
// current + d is at stage kReach − d − j. Each bucket's cursor is the ball its last walk made
// stage 0 for: that ball now gets stage 1 (its records, its list link included, were asked for
// then) and its successor stage 0; the bucket coming into reach starts at its first ball.
void World::Impl::lookahead_walk(std::int64_t current) {
  for (std::int64_t d = 1; d < kReach; ++d) {
    std::uint32_t& cursor = lookahead.cursors[static_cast<std::size_t>(current + d) % kCursors];
    if (cursor == detail::EventQueue::kNone) continue;
    lookahead_stage_1(cursor);
    cursor = queue.list_next(cursor);
    if (cursor != detail::EventQueue::kNone) lookahead_stage_0(cursor);
  }
  lookahead_enter(current + kReach);
}

// A bucket coming into reach: its cursor starts at its first ball, which gets stage 0.
void World::Impl::lookahead_enter(std::int64_t bucket) {
  const std::uint32_t first = queue.bucket_first(bucket);
  lookahead.cursors[static_cast<std::size_t>(bucket) % kCursors] = first;
  if (first != detail::EventQueue::kNone) lookahead_stage_0(first);
}

}  // namespace carom
