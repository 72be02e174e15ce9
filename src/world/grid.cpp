#include "grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom::detail {

namespace {

// One axis's exits (Grid::exit_x): for each of n cells from `lower`, of size `cell`, the side
// it is left through downward and upward.
void tabulate_exits(std::vector<double>& exits, double lower, double cell, std::int32_t n,
                    double hysteresis, bool periodic, bool closed) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  exits.resize(2 * static_cast<std::size_t>(n));
  for (std::int32_t c = 0; c < n; ++c) {
    const double down = lower + cell * c;
    const double up = lower + cell * (c + 1);
    const bool first = c == 0;
    const bool last = c + 1 == n;
    const auto at = 2 * static_cast<std::size_t>(c);
    exits[at] = closed && first ? -kNever : down - (periodic && first ? 0.0 : hysteresis);
    exits[at + 1] = closed && last ? kNever : up + (periodic && last ? 0.0 : hysteresis);
  }
}

}  // namespace

void Grid::setup(Vec2 lower, Vec2 cell, std::int32_t nx, std::int32_t ny, bool periodic,
                 bool closed, Vec2 hysteresis) {
  lower_ = lower;
  cell_ = cell;
  hysteresis_ = hysteresis;
  nx_ = nx;
  rows_ = FixedDivisor(static_cast<std::uint32_t>(nx));
  ny_ = ny;
  periodic_ = periodic;
  tabulate_exits(exits_x_, lower.x, cell.x, nx, hysteresis.x, periodic, closed);
  tabulate_exits(exits_y_, lower.y, cell.y, ny, hysteresis.y, periodic, closed);
  const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  // One head past the last cell, never a ball's: block_heads reads four heads where a row of
  // the block has three, and the last row's fourth may be that one.
  head_.assign(cells + 1, kNoBall);
  wall_start_.clear();
  wall_ids_.clear();
  for (BallSlot& slot : *slots_) {
    slot.cell_next = kNoBall;
    slot.cell = kNoBall;
  }
}

std::int32_t Grid::column_of(double x) const {
  const double c = std::floor((x - lower_.x) / cell_.x);
  return static_cast<std::int32_t>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

std::int32_t Grid::row_of(double y) const {
  const double c = std::floor((y - lower_.y) / cell_.y);
  return static_cast<std::int32_t>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
}

void Grid::relist() {
  BigVector<BallSlot>& slots = *slots_;
  std::fill(head_.begin(), head_.end(), kNoBall);
  // Backwards, since insert puts a ball first in its cell's list.
  for (auto k = static_cast<std::uint32_t>(slots.size()); k-- > 0;) {
    if (slots[k].cell != kNoBall) insert(k, slots[k].cell);
  }
}

void Grid::insert(std::uint32_t ball, std::int32_t cell) {
  BallSlot& slot = (*slots_)[ball];
  slot.cell_next = head_[static_cast<std::size_t>(cell)];
  head_[static_cast<std::size_t>(cell)] = static_cast<std::int32_t>(ball);
  slot.cell = cell;
}

void Grid::erase(std::uint32_t ball) {
  BigVector<BallSlot>& slots = *slots_;
  const std::int32_t cell = slots[ball].cell;
  if (cell == kNoBall) return;
  // Singly linked: the predecessor is found by walking the cell's list, which prediction scans
  // anyway (a cell holds about one ball), and saves 4 bytes a ball. The others keep their order.
  std::int32_t* link = &head_[static_cast<std::size_t>(cell)];
  while (*link != static_cast<std::int32_t>(ball)) {
    link = &slots[static_cast<std::size_t>(*link)].cell_next;
  }
  *link = slots[ball].cell_next;
  slots[ball].cell = kNoBall;
}

void Grid::set_walls(std::span<const Vec2> lower, std::span<const Vec2> upper) {
  wall_start_.clear();
  wall_ids_.clear();
  if (lower.empty()) return;
  const auto cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  // Each wall is listed in its wall_cells. Two passes: count, then fill, walls in ascending id
  // order within each cell.
  std::vector<CellSpan> spans(lower.size());
  wall_start_.assign(cells + 1, 0);
  for (std::size_t w = 0; w < lower.size(); ++w) {
    if (!(lower[w].x <= upper[w].x)) {
      spans[w] = {0, -1, 0, -1};  // an empty box: the wall is in no cell
      continue;
    }
    spans[w] = wall_cells(lower[w], upper[w]);
    for (std::int32_t y = spans[w].y0; y <= spans[w].y1; ++y) {
      for (std::int32_t x = spans[w].x0; x <= spans[w].x1; ++x)
        ++wall_start_[static_cast<std::size_t>(index(x, y)) + 1];
    }
  }
  for (std::size_t c = 0; c < cells; ++c) wall_start_[c + 1] += wall_start_[c];
  wall_ids_.resize(wall_start_[cells]);
  std::vector<std::uint32_t> fill(wall_start_.begin(), wall_start_.end() - 1);
  for (std::size_t w = 0; w < lower.size(); ++w) {
    for (std::int32_t y = spans[w].y0; y <= spans[w].y1; ++y) {
      for (std::int32_t x = spans[w].x0; x <= spans[w].x1; ++x)
        wall_ids_[fill[static_cast<std::size_t>(index(x, y))]++] = static_cast<std::uint32_t>(w);
    }
  }
}

}  // namespace carom::detail
