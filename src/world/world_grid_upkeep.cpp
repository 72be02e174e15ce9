// The grid's upkeep: planning its cells for the balls and walls, rebuilding it, listing walls,
// and re-ordering the balls' slots by cell (docs/engine.md, "The broad phase", "Memory").
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

using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

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
    largest = std::max(largest, radius_at(i, time));
    const Vec2 p = position_at(i, time);
    lower = {std::min(lower.x, p.x), std::min(lower.y, p.y)};
    upper = {std::max(upper.x, p.x), std::max(upper.y, p.y)};
  }
  for (const detail::Wall& wall : walls) {
    if (!wall.listed()) continue;  // (moving walls are met without the grid)
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
  if (growth_on) plan_growth_regrid();
}

void World::Impl::list_walls() {
  std::vector<Vec2> wall_lower(walls.size());
  std::vector<Vec2> wall_upper(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (walls[w].listed()) {
      detail::bounds(walls[w], wall_lower[w], wall_upper[w]);
    } else {
      // Moving and removed walls are in no cell: an empty box.
      wall_lower[w] = {kInfinity, kInfinity};
      wall_upper[w] = {-kInfinity, -kInfinity};
    }
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
  renumber(new_slot);
  if (!last_contact_times.empty()) detail::move_to(last_contact_times, new_slot);
  if (!carriages.empty()) detail::move_to(carriages, new_slot);
  if (!table_slots.empty()) detail::move_to(table_slots, new_slot);
  grid.relist();
  if (events_valid) {
    queue.use_handles(handle_of.data());
    queue.reorder(new_slot);
    lookahead.passed_bucket = -1;  // its lists are rebuilt: the lookahead starts again
  }
}

}  // namespace carom
