// The event-driven engine behind carom::World: prediction, the event loop, contact response and
// the grid's upkeep. Design and the argument that no contact is missed: docs/engine.md.
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
#include "pair_batch.hpp"
#include "permute.hpp"
#include "world_impl.hpp"

// GCC and clang both spell it this way; on a lambda it goes after the parameter list.
#define CAROM_ALWAYS_INLINE __attribute__((always_inline))

namespace carom {

using detail::BallSlot;
using detail::Event;
using detail::EventKind;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The horizon handed to a time-of-impact query when nothing earlier bounds it.
constexpr double kFarFuture = std::numeric_limits<double>::max();
// An open world's grid covers the balls and walls with this much room on each side (as a
// fraction of their extent), so that it is rebuilt only every so often as balls spread out.
constexpr double kOpenGrowth = 0.5;
// ... and at least this fraction of the coordinates' size (far above their rounding, 2⁻⁵²).
constexpr double kRoomOfScale = 0x1p-40;
// At most this many cells per ball (plus a floor), so that a ball far away makes cells larger
// rather than the grid huge.
constexpr double kCellsPerBall = 4.0;
constexpr double kMinCells = 1024.0;
// A dilute world (fewer balls than this per cell of the smallest size) gets cells kDiluteCells
// times that size, and the room beyond the diameter becomes the cells' hysteresis: a ball then
// leaves its cell only this far past its side, so that one turning back near a side does not
// cross twice (docs/engine.md, "The broad phase"). In a dilute gas it cuts the crossings a
// collision by a third; in denser gases crossings are few and the larger blocks cost more than
// they save (docs/decisions/0006-grid-cells-and-hysteresis.md).
constexpr double kDiluteBallsPerCell = 0.55;
constexpr double kDiluteCells = 1.25;
// The share of that room given to the hysteresis: all but a sliver, so that the cell less twice
// the hysteresis stays above the diameter after rounding (and at most detail::kMostHysteresis
// of the cell).
constexpr double kHysteresisShare = 0.999;
// A grid is re-planned while balls are added once a re-plan would make its cells this much
// smaller per side (the ball count has grown about 4 times: O(1) amortised per add_ball) ...
constexpr double kAddCoarseness = 2.0;
// ... and before a run once it would make them any smaller beyond the floor-rounding of the cell
// count, so that a run never keeps cells coarser than it needs (a run's re-plan is paid once).
constexpr double kRunCoarseness = 1.01;
// The slots are re-ordered by cell (sort_by_cell) once the events since the last time exceed
// this many per ball (plus a floor, so that small worlds, which fit in cache anyway, are rarely
// re-ordered). A re-order costs about as much as a few events per ball; in between, balls
// drift only a few cells from their neighbours in memory.
constexpr std::uint64_t kSortEvents = 8;
constexpr std::uint64_t kSortMinEvents = 1 << 16;
// A grid with at least this many cells per axis has interior cells whose 3×3 block needs no
// minimum image (predict).
constexpr std::int32_t kInteriorMinCells = 5;
// A periodic grid with at least this many cells per axis needs only the nearest image of each
// pair: between two predictions of a pair neither ball leaves its cell, so their offset moves
// by under two cells per axis, and a pair that touches (within one cell) was within three cells
// when predicted, under half a period from 7 cells on (6 leaves no room for the cell margin).
constexpr std::int32_t kSingleImageMinCells = 7;
// Contacts without measurable motion (a jammed chain of touching balls), or events at one
// instant (a jam, or time too large to advance), beyond this many per ball plus a floor mean a
// run that would never end (docs/world.md, "Known limits"). A Newton's cradle has one contact a
// ball at one instant, a break from rest a few.
constexpr std::uint64_t kInstantEventsPerBall = 100;
constexpr std::uint64_t kInstantEventsFloor = 1 << 16;
// A contact counts as motion when one of its balls has travelled more than this fraction of its
// coordinates' size (|x| + |y| + radius) since the last one that did: a jammed ball creeps a
// rounding at a time, so its contacts advance time by ulps rather than not at all.
constexpr double kMeasurableMotion = 0x1p-30;
// A contact is refused (time "has stalled") where one step of the double grid of time moves one
// of its balls by more than this fraction of its radius: contacts are resolved at event times
// rounded to that grid, so they would land that far off their places (and overlaps of that
// size are beyond what World::audit allows for the rounding of positions). Speed 1 and radius 1
// reach it at t ≈ 4·10¹²; a ball of radius 10⁻⁶ at speed 100 at t ≈ 3·10⁴.
constexpr double kResolvableMotion = 0x1p-10;
// Events without a contact before run_collisions first tries to prove that none will come
// (at least; 2 per ball in larger worlds, where one crossing per ball is ordinary).
constexpr std::uint64_t kEventsBeforeProof = 64;
// Worlds with at least this many balls look ahead (world_lookahead.cpp: the data of the events
// in the queue's next buckets asked for, stage by stage) and defer filing events (event_queue.hpp).
// Where everything is in cache both only cost their instructions, so they start where the world
// outgrows the caches (docs/decisions/0013-lookahead-in-large-worlds.md).
constexpr std::uint32_t kPrefetchMinBalls = 1u << 16;
// ... and from this many on, their lookahead goes a stage deeper (world_lookahead.cpp), which
// pays once the arrays are several times the last-level cache (the same record).
constexpr std::uint32_t kDeepLookaheadMinBalls = 90'000;

// The unit vector along d, d not zero. Where d·d is far from both ends of the double range,
// d / √(d·d) (within an ulp or so of unit length, as carom::normalized's quotient by std::hypot
// is): glibc's hypot, careful where the squares would overflow or underflow, is a slow call in
// the response's hot path (docs/decisions/0016-response-repeats-bounce.md). Elsewhere
// normalized, which scales first.
CAROM_ALWAYS_INLINE inline Vec2 unit_along(Vec2 d) {
  const double squared = length_squared(d);
  if (squared > 0x1p-1000 && squared < 0x1p+1000) [[likely]]
    return d / std::sqrt(squared);
  return normalized(d);
}

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

}  // namespace

// ---- the grid -----------------------------------------------------------------------------

void World::Impl::ensure_grid(Vec2 extra_point, double extra_radius) {
  if (grid_valid) {
    const bool cell_fits = 2.0 * extra_radius * (1.0 + detail::kCellMargin) <= grid.room();
    const Vec2 lower = grid.lower();
    const Vec2 upper = grid.upper();
    const bool inside =
        def.boundary != Boundary::open || (extra_point.x >= lower.x && extra_point.x <= upper.x &&
                                           extra_point.y >= lower.y && extra_point.y <= upper.y);
    // Re-planned as balls are added: the cell count allowed grows with the balls, and each
    // re-plan (O(N)) comes only after the count has grown by a constant factor (kAddCoarseness),
    // so adding balls costs O(1) amortised and every add_ball scans only a few balls.
    if (cell_fits && inside && !grid_too_coarse(live_count + 1, kAddCoarseness)) return;
  }
  rebuild_grid(extra_point, extra_radius);
}

double World::Impl::wanted_cell_size(double extent_x, double extent_y, std::size_t ball_total,
                                     double largest) const {
  const double diameter = 2.0 * largest * (1.0 + detail::kCellMargin);
  double cell = std::max(def.cell_size, diameter);
  const double balls_per_cell =
      static_cast<double>(ball_total) * diameter * diameter / (extent_x * extent_y);
  if (balls_per_cell < kDiluteBallsPerCell) cell = std::max(cell, kDiluteCells * diameter);
  const double max_cells = std::max(kMinCells, kCellsPerBall * static_cast<double>(ball_total));
  if (extent_x / cell * (extent_y / cell) > max_cells) {
    cell = std::sqrt(extent_x * extent_y / max_cells);
  }
  if (def.boundary == Boundary::periodic) {
    // Three cells per axis at least, so the 3×3 block never holds a cell twice (add_ball keeps
    // every diameter below this).
    cell = std::min(cell, std::min(extent_x, extent_y) / 3.0);
  }
  // An open world with no ball and walls that are all one point has nothing to size cells by;
  // any positive size serves (the grid is re-planned when a ball comes).
  return cell > 0.0 ? cell : 1.0;
}

void World::Impl::rebuild_grid(Vec2 extra_point, double extra_radius) {
  double largest = extra_radius;
  Vec2 lower = extra_point;
  Vec2 upper = extra_point;
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (!balls[i].alive()) continue;
    largest = std::max(largest, radius_of(i));
    const Vec2 p = position_at(i, time);
    lower = {std::min(lower.x, p.x), std::min(lower.y, p.y)};
    upper = {std::max(upper.x, p.x), std::max(upper.y, p.y)};
  }
  for (const detail::Wall& wall : walls) {
    Vec2 wall_lower;
    Vec2 wall_upper;
    detail::bounds(wall, wall_lower, wall_upper);
    lower = {std::min(lower.x, wall_lower.x), std::min(lower.y, wall_lower.y)};
    upper = {std::max(upper.x, wall_upper.x), std::max(upper.y, wall_upper.y)};
  }
  const std::size_t ball_total = live_count + 1;
  if (def.boundary == Boundary::open) {
    const double cell = wanted_cell_size(upper.x - lower.x, upper.y - lower.y, ball_total, largest);
    // At least kRoomOfScale of the coordinates' size: far from the origin, room below their
    // rounding would leave an extent of 0 (cells of size 0).
    const double scale =
        std::max({std::abs(lower.x), std::abs(lower.y), std::abs(upper.x), std::abs(upper.y)});
    const double room =
        std::max(kOpenGrowth * std::max(upper.x - lower.x, upper.y - lower.y) + 2.0 * cell,
                 kRoomOfScale * scale);
    lower -= Vec2{room, room};
    upper += Vec2{room, room};
  } else {
    lower = def.lower;
    upper = def.upper;
  }
  const Vec2 extent = upper - lower;
  const double cell = wanted_cell_size(extent.x, extent.y, ball_total, largest);
  const auto nx = static_cast<std::int32_t>(std::max(1.0, std::floor(extent.x / cell)));
  const auto ny = static_cast<std::int32_t>(std::max(1.0, std::floor(extent.y / cell)));
  const Vec2 cell_size{extent.x / nx, extent.y / ny};
  // Every ball, those added later included, fits what the cells hold beyond the hysteresis
  // (ensure_grid re-plans for a larger one); the rest of the room is hysteresis.
  const double diameter = 2.0 * std::max(largest, largest_radius) * (1.0 + detail::kCellMargin);
  const auto hysteresis_of = [&](double side) {
    return std::min(detail::kMostHysteresis * side,
                    kHysteresisShare * std::max(0.0, (side - diameter) / 2.0));
  };
  const Vec2 hysteresis{hysteresis_of(cell_size.x), hysteresis_of(cell_size.y)};
  grid.setup(lower, cell_size, nx, ny, def.boundary == Boundary::periodic,
             def.boundary == Boundary::box, hysteresis);
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (balls[i].alive()) grid.insert(i, grid.cell_of(position_at(i, time)));
  }
  list_walls();
  grid_valid = true;
  events_valid = false;
}

void World::Impl::list_walls() {
  std::vector<Vec2> wall_lower(walls.size());
  std::vector<Vec2> wall_upper(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    detail::bounds(walls[w], wall_lower[w], wall_upper[w]);
  }
  grid.set_walls(wall_lower, wall_upper);
}

// The wall is listed in a few cells, and only the balls in those cells can meet it before they
// cross into another cell (which predicts them afresh): they alone are re-predicted. Their
// trajectories are unchanged until they meet it, so every other pending event stays valid.
void World::Impl::wall_added() {
  Vec2 lower;
  Vec2 upper;
  detail::bounds(walls.back(), lower, upper);
  const Vec2 grid_lower = grid.lower();
  const Vec2 grid_upper = grid.upper();
  const bool covered = lower.x >= grid_lower.x && lower.y >= grid_lower.y &&
                       upper.x <= grid_upper.x && upper.y <= grid_upper.y;
  if (!grid_valid || !covered) {  // an open world's grid grows to cover it at the next run
    grid_valid = false;
    events_valid = false;
    return;
  }
  list_walls();  // O(cells) integer work, far below a prediction per ball
  if (!events_valid) return;
  queue.use_handles(handle_of.data());
  const detail::Grid::CellSpan cells = grid.wall_cells(lower, upper);
  for (std::int32_t y = cells.y0; y <= cells.y1; ++y) {
    for (std::int32_t x = cells.x0; x <= cells.x1; ++x) {
      for (std::int32_t j = grid.first_ball(grid.index(x, y)); j != detail::kNoBall;
           j = grid.next_ball(static_cast<std::uint32_t>(j))) {
        advance(static_cast<std::uint32_t>(j), time);  // prediction reads it at the world's time
        predict(static_cast<std::uint32_t>(j));
      }
    }
  }
}

// Whether a re-plan for `ball_total` balls over the grid's present extent would make cells
// smaller by more than `coarseness` (per side). The grid planned while few balls were there has
// few cells (at most kCellsPerBall per ball); more balls per cell means more pairs per prediction.
bool World::Impl::grid_too_coarse(std::size_t ball_total, double coarseness) const {
  const Vec2 extent = grid.upper() - grid.lower();
  const double cell = wanted_cell_size(extent.x, extent.y, ball_total, largest_radius);
  const double planned_x = extent.x / std::max(1.0, std::floor(extent.x / cell));
  const double planned_y = extent.y / std::max(1.0, std::floor(extent.y / cell));
  const Vec2 now = grid.cell_size();
  return now.x > coarseness * planned_x || now.y > coarseness * planned_y;
}

// The live balls take slots 0, 1, ... cell by cell (each cell's list in its order), the dead
// slots the rest. Every array indexed by slot follows; handles do not change, and
// since events are ordered by handle (world_event.hpp) and sums are taken in handle order, no
// result depends on the new order.
void World::Impl::sort_by_cell() {
  events_since_sort = 0;
  if (!grid_valid) return;
  const auto slots = static_cast<std::uint32_t>(balls.size());
  std::vector<std::uint32_t> new_slot(slots);
  std::uint32_t next = 0;
  const std::int32_t cells = grid.nx() * grid.ny();
  for (std::int32_t c = 0; c < cells; ++c) {
    for (std::int32_t j = grid.first_ball(c); j != detail::kNoBall;
         j = grid.next_ball(static_cast<std::uint32_t>(j))) {
      new_slot[static_cast<std::uint32_t>(j)] = next++;
    }
  }
  for (std::uint32_t i = 0; i < slots; ++i) {
    if (!balls[i].alive()) new_slot[i] = next++;
  }
  detail::move_all_to(new_slot, balls, infos, handle_of);
  if (!last_contact_times.empty()) detail::move_to(last_contact_times, new_slot);
  for (std::uint32_t k = 0; k < slots; ++k) slot_of_handle[handle_of[k]] = k;
  grid.relist();
  if (events_valid) {
    queue.use_handles(handle_of.data());
    queue.reorder(new_slot);
    lookahead.passed_bucket = -1;  // its lists are rebuilt: the lookahead starts again
  }
}

// ---- prediction ---------------------------------------------------------------------------

void World::Impl::advance(std::uint32_t ball, double t) {
  BallSlot& b = balls[ball];
  b.position = position_at(ball, t);
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
    const Impact impact = detail::time_of_impact(walls[w], shape, v, horizon);
    if (!impact.hit) continue;
    Event candidate;
    candidate.time = time + impact.t;
    candidate.kind = EventKind::ball_wall;
    candidate.owner = ball;
    candidate.partner = w;
    if (detail::earlier(candidate, best, handle_of.data())) best = candidate;
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

// Ball `ball` is at the world's time. Its slot gets its earliest event: a contact with a ball
// in the 3×3 block of cells around it or a wall listed in its cell, or leaving its cell. The
// other ball's slot is left alone: this one's covers their pair (docs/engine.md, "One event per
// ball").
void World::Impl::predict(std::uint32_t ball) {
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

// ---- the event loop -----------------------------------------------------------------------

bool World::Impl::stop_asked(const RunStatus& status) {
  // exchange only when set: the common case stays a plain load.
  if (stop_requested.load(std::memory_order_relaxed) &&
      stop_requested.exchange(false, std::memory_order_relaxed)) {
    return true;
  }
  return progress_callback && progress_callback(status);
}

std::uint64_t World::Impl::run(const char* function, RunGoal goal, double end,
                               std::uint64_t max_contacts) {
  contacts.clear();
  stop_reason = StopReason::none;
  mover_met = false;
  if (!grid_valid || grid_too_coarse(live_count, kRunCoarseness)) rebuild_grid(Vec2{}, 0.0);
  if (!events_valid) predict_all();
  queue.use_handles(handle_of.data());  // add_ball may have moved the array
  std::uint64_t resolved = 0;
  // Without an end time, a run must notice when contacts are over for good (two balls flying
  // apart cross cells for ever). After a stretch of events without a contact it tries to prove
  // it; each failed proof doubles the stretch before the next, so proofs (O(N²)) stay rare.
  std::uint64_t without_contact = 0;
  std::uint64_t next_proof = std::max<std::uint64_t>(kEventsBeforeProof, 2 * live_count);
  // Runs that would never end (docs/world.md, "Known limits"): contacts since the last contact
  // that moved a ball measurably (a jam), and events at the previous event's very time (a jam,
  // or a time whose rounding step is longer than the motion, so that it no longer advances).
  const std::uint64_t endless = kInstantEventsPerBall * live_count + kInstantEventsFloor;
  double motion_time = -kInfinity;
  std::uint64_t contacts_without_motion = 0;
  double instant = -kInfinity;
  std::uint64_t at_instant = 0;
  // Runs that would never end the other way: contacts coming ever faster, each with motion.
  detail::ContactPace pace;
  const bool prefetching = live_count >= kPrefetchMinBalls;
  lookahead.deep = live_count >= kDeepLookaheadMinBalls;
  // Filing is deferred during the run only, however it ends (a refusal throws).
  struct DeferredFiling {
    detail::EventQueue& queue;
    DeferredFiling(detail::EventQueue& q, bool on) : queue(q) { queue.defer_filing(on); }
    DeferredFiling(const DeferredFiling&) = delete;
    DeferredFiling& operator=(const DeferredFiling&) = delete;
    ~DeferredFiling() { queue.defer_filing(false); }
  } deferred_filing(queue, prefetching);
  const std::uint64_t sort_after = kSortEvents * live_count + kSortMinEvents;
  // Stop requests are looked at before the first event and then every kStopCheckEvents events.
  static_assert(std::has_single_bit(kStopCheckEvents));
  std::uint64_t events = 0;
  for (;;) {
    if ((events & (kStopCheckEvents - 1)) == 0 && stop_asked({time, events, resolved})) {
      stop_reason = StopReason::interrupted;
      return resolved;
    }
    ++events;
    if (++events_since_sort > sort_after) sort_by_cell();
    const Event event = queue.top();
    if (!(event.time <= end) || event.time == kInfinity) {
      // Reaching the time asked for is what a timed run is for; for a count of contacts, an end
      // of the queue means none will ever come, and a finite end is the caller's limit.
      if (goal == RunGoal::contacts) {
        stop_reason =
            event.time == kInfinity ? StopReason::no_more_contacts : StopReason::time_limit;
      }
      break;
    }
    if (prefetching && queue.current_bucket() != lookahead.passed_bucket) look_ahead();
    time = event.time;
    const bool contact = process(event);
    if (time != instant) {
      instant = time;
      at_instant = 0;
    } else if (++at_instant > endless) {
      refuse_endless(function, at_instant, event);
    }
    if (!contact) {
      // Any event at a time too coarse for its balls is refused as a contact would be: a
      // predicted contact whose balls were then found not to meet (a rounding short of it or
      // past it) was lost to rounding, not missed by a hair (a ball of radius 10⁻⁶ at
      // t = 2.7·10¹¹ went through a wall so), and a cell crossing taken a rounding late puts its
      // ball past the next cell, past the box's wall (one at t = 4.4·10¹⁷ left the box so).
      const bool partner_gone = event.kind == EventKind::ball_ball && !balls[event.partner].alive();
      if (!partner_gone && time_too_coarse(event)) refuse_stalled(function, event);
      if (end == kInfinity && ++without_contact >= next_proof) {
        if (no_contact_ever()) {
          stop_reason = StopReason::no_more_contacts;
          break;
        }
        next_proof *= 2;
        without_contact = 0;
      }
      continue;
    }
    without_contact = 0;
    ++resolved;
    ++collisions;
    if (time_too_coarse(event)) refuse_stalled(function, event);
    if (pace.piling_up(time)) refuse_piling_up(function, event);
    if (moved_measurably(event, time - motion_time)) {
      motion_time = time;
      contacts_without_motion = 0;
    } else if (++contacts_without_motion > endless) {
      refuse_endless(function, contacts_without_motion, event);
    }
    const bool stop = stop_condition && stop_condition(last_contact);
    if (stop || resolved == max_contacts) {
      if (stop) stop_reason = StopReason::stop_condition;
      return resolved;
    }
  }
  // Balls stay at their own local times: queries compute positions at the world's time, so
  // splitting a run into steps changes nothing (no re-rounding of positions at step ends).
  if (end < kInfinity) time = end;
  return resolved;
}

CAROM_ALWAYS_INLINE inline bool World::Impl::moved_measurably(const Event& contact,
                                                              double elapsed) const {
  if (elapsed == kInfinity) return true;  // the run's first contact
  const auto moved = [&](std::uint32_t ball) {
    const BallSlot& b = balls[ball];
    // |x| + |y| bounds the length within a factor √2, which is all a threshold needs.
    const double travel = elapsed * (std::abs(b.velocity.x) + std::abs(b.velocity.y));
    const double size = std::abs(b.position.x) + std::abs(b.position.y) + radius_of(ball);
    return travel > kMeasurableMotion * size;
  };
  return moved(contact.owner) || (contact.kind == EventKind::ball_ball && moved(contact.partner));
}

CAROM_ALWAYS_INLINE inline bool World::Impl::time_too_coarse(const Event& event) const {
  // Neighbouring doubles near t are at most t·2⁻⁵² apart.
  const double time_step = std::abs(time) * 0x1p-52;
  const auto coarse = [&](std::uint32_t ball) {
    const BallSlot& b = balls[ball];
    const double motion = time_step * (std::abs(b.velocity.x) + std::abs(b.velocity.y));
    return motion > kResolvableMotion * radius_of(ball);
  };
  return coarse(event.owner) || (event.kind == EventKind::ball_ball && coarse(event.partner));
}

void World::Impl::refuse_endless(const char* function, std::uint64_t count,
                                 const Event& last) const {
  // Time stalls where its step to the next double would move the event's ball measurably: the
  // motion between events is then lost to rounding. Otherwise the balls are jammed.
  const double time_step = std::nextafter(time, kInfinity) - time;
  if (moved_measurably(last, time_step)) refuse_stalled(function, last);
  refuse_never_ending(
      function, std::to_string(count) + " events at t = " + carom::number_text(time),
      "their contacts come at one instant (or a rounding apart) without end", last,
      "has balls jammed: balls held by touching balls and walls on every side (a closed row of "
      "exactly touching balls around the periodic cell or from wall to wall, a ball wedged in a "
      "corner) pass their contacts on without moving, for ever; leave a gap (docs/world.md, "
      "\"Known limits\")");
}

void World::Impl::refuse_piling_up(const char* function, const Event& last) const {
  const std::string how =
      "contacts come ever faster, infinitely often before one instant (each doubling of the "
      "run's contact count took under 3/4 of the time of the one before, 8 times in a row)";
  refuse_never_ending(
      function,
      "t = " + carom::number_text(time) + " (ball " + std::to_string(handle_of[last.owner]) + ")",
      how, last, "has contacts piling up: " + how + " (docs/world.md, \"Known limits\")");
}

void World::Impl::refuse_never_ending(const char* function, const std::string& where,
                                      const std::string& how, const Event& last,
                                      const std::string& otherwise) const {
  if (mover_met) {
    throw InvalidArgument(function, "world", where,
                          "has balls crushed: a moving immovable ball closes on balls against a "
                          "wall or another immovable ball, and " +
                              how +
                              "; stop the immovable ball first (docs/world.md, \"Known "
                              "limits\")");
  }
  const bool inelastic = def.collapse_time == 0.0 &&
                         (restitution_of(last.owner) < 1.0 || (last.kind == EventKind::ball_ball &&
                                                               restitution_of(last.partner) < 1.0));
  if (inelastic) {
    throw InvalidArgument(function, "world", where,
                          "has an inelastic collapse: balls with restitution below 1 pressed "
                          "together (against a wall, or in a cluster) meet again and again, and " +
                              how +
                              "; set WorldDef::collapse_time (a ball that met something less "
                              "than that long ago then bounces elastically; docs/world.md, "
                              "\"Known limits\")");
  }
  throw InvalidArgument(function, "world", where, otherwise);
}

void World::Impl::refuse_stalled(const char* function, const Event& last) const {
  throw InvalidArgument(
      function, "world",
      "t = " + carom::number_text(time) + " (ball " + std::to_string(handle_of[last.owner]) + ")",
      "has stalled: at this time the step between neighbouring doubles moves a ball measurably "
      "(more than 2^-10 of its radius), so contacts would be resolved off their places, and "
      "events may no longer advance time at all; continue the motion in a new world, from time "
      "0 (docs/world.md, \"Known limits\")");
}

bool World::Impl::process(const Event& event) {
  const std::uint32_t i = event.owner;
  switch (event.kind) {
    case EventKind::ball_ball: {
      const std::uint32_t j = event.partner;
      if (!balls[j].alive() || balls[j].version != event.partner_version) {
        advance(i, event.time);  // stale: the partner changed course since
        predict(i);
        return false;
      }
      return resolve_ball_ball(i, j, event.time);
    }
    case EventKind::ball_wall:
      return resolve_ball_wall(i, event.partner, event.time);
    case EventKind::cell_crossing:
      cross_cell(i, event.partner, event.time, event.partner_version == detail::kClearBehind);
      return false;
  }
  return false;
}

// Inelastic collapse prevention (the TC model; docs/engine.md, "Response"): a ball that collided
// less than collapse_time before t bounces elastically.
CAROM_ALWAYS_INLINE inline bool World::Impl::collided_recently(std::uint32_t ball, double t) const {
  return def.collapse_time > 0.0 && last_contact_times[ball] > t - def.collapse_time;
}

CAROM_ALWAYS_INLINE inline double World::Impl::pair_restitution(std::uint32_t i, std::uint32_t j,
                                                                double t) const {
  if (collided_recently(i, t) || collided_recently(j, t)) return 1.0;
  if (!mixed_restitution) return def.restitution;
  return std::min(species_of(i).restitution, species_of(j).restitution);
}

bool World::Impl::resolve_ball_ball(std::uint32_t i, std::uint32_t j, double t) {
  advance(i, t);
  advance(j, t);
  BallSlot& a = balls[i];
  BallSlot& b = balls[j];
  const Vec2 between = minimum_image(b.position - a.position);
  const Vec2 normal = between == Vec2{} ? normalized(a.velocity - b.velocity) : unit_along(between);
  const double approach = dot(a.velocity - b.velocity, normal);
  bool resolved = false;
  if (approach > 0.0) {
    const double restitution = pair_restitution(i, j, t);
    const double inverse_a = species_of(i).inverse_mass;
    const double inverse_b = species_of(j).inverse_mass;
    const double impulse = detail::normal_impulse(approach, inverse_a, inverse_b, restitution);
    detail::apply_impulse(a.velocity, b.velocity, normal, impulse, inverse_a, inverse_b);
    if (def.collapse_time > 0.0) {
      last_contact_times[i] = t;
      last_contact_times[j] = t;
    }
    if (contact_wanted()) record_ball_ball(i, j, t, between, normal, approach, impulse);
    resolved = true;
    // An immovable ball at rest is a post, like a wall; a moving one does work on what it meets.
    if (inverse_a == 0.0 ? a.velocity != Vec2{} : (inverse_b == 0.0 && b.velocity != Vec2{})) {
      mover_met = true;
    }
  }
  ++a.version;
  ++b.version;
  predict_both(i, j);
  return resolved;
}

void World::Impl::record_ball_ball(std::uint32_t i, std::uint32_t j, double t, Vec2 between,
                                   Vec2 normal, double approach, double impulse) {
  const BallSlot& a = balls[i];
  const bool a_first = handle_before(i, j);  // the pair in handle order, as the docs promise
  ContactEvent contact;
  contact.time = t;
  contact.kind = ContactKind::ball_ball;
  contact.a = id_of(a_first ? i : j);
  contact.b = id_of(a_first ? j : i);
  contact.normal = a_first ? normal : -normal;
  const double radius_a = radius_of(i);
  const double reach = radius_a + radius_of(j);
  contact.point = a.position + between * (radius_a / reach);
  contact.approach_speed = approach;
  contact.impulse = impulse;
  record(contact);
}

bool World::Impl::resolve_ball_wall(std::uint32_t i, std::uint32_t wall, double t) {
  advance(i, t);
  BallSlot& a = balls[i];
  // The contact's own normal where the query confirms it (touching and approaching now), else
  // the direction to the nearest point (the ball a rounding short of the wall).
  const Ball shape{a.position, radius_of(i)};
  Impact now = detail::time_of_impact(walls[wall], shape, a.velocity, 0.0);
  if (!now.hit) {
    // A contact a sliver ahead that the motion cannot reach: a gap below the rounding of the
    // position closes at a time at which the ball is still where it is now, so advancing it
    // changes nothing and the same contact would come up again and again, a sliver later each
    // time (a ball filling an arc's circle, at its centre, met its end point so). It is a
    // contact now.
    const Impact ahead = detail::time_of_impact(walls[wall], shape, a.velocity, kFarFuture);
    if (ahead.hit && ahead.a_at == a.position) now = ahead;
  }
  const Vec2 point = now.hit ? now.point : detail::nearest_point(walls[wall], a.position);
  const Vec2 normal = now.hit ? now.normal : normalized(point - a.position);
  const double approach = dot(a.velocity, normal);
  // Inside a bowl a ball moving along the wall (approach 0) is a contact too (the query reports
  // it), answered by bounce_inside_arc's turn (docs/engine.md, "Response").
  const bool in_bowl = detail::inside_arc(walls[wall], a.position);
  bool resolved = false;
  if (approach > 0.0 || (in_bowl && now.hit)) {
    const double restitution = collided_recently(i, t) ? 1.0 : restitution_of(i);
    double speed_change = 0.0;
    if (in_bowl) {
      const detail::BowlBounce bounce = detail::bounce_inside_arc(a.velocity, normal, restitution);
      a.velocity = bounce.velocity;
      speed_change = bounce.normal_speed_change;
    } else {
      speed_change = detail::wall_speed_change(approach, restitution);
      a.velocity -= normal * speed_change;
    }
    if (def.collapse_time > 0.0) last_contact_times[i] = t;
    ContactEvent contact;
    contact.time = t;
    contact.kind = ContactKind::ball_wall;
    contact.a = id_of(i);
    contact.wall = wall;
    contact.point = point;
    contact.normal = normal;
    contact.approach_speed = approach;
    contact.impulse = movable(i) ? speed_change * species_of(i).mass : 0.0;
    record(contact);
    resolved = true;
    ++a.version;
  }
  predict(i);
  return resolved;
}

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
