#include "grid.hpp"

#include <algorithm>
#include <cmath>

namespace carom::detail {

void Grid::setup(Vec2 lower, Vec2 cell, std::int32_t nx, std::int32_t ny, bool periodic,
                 std::uint32_t ball_capacity) {
  lower_ = lower;
  cell_ = cell;
  nx_ = nx;
  ny_ = ny;
  periodic_ = periodic;
  const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  head_.assign(cells, kNoBall);
  walls_.assign(cells, {});
  next_.assign(ball_capacity, kNoBall);
  prev_.assign(ball_capacity, kNoBall);
  ball_cell_.assign(ball_capacity, kNoBall);
}

void Grid::reserve_balls(std::uint32_t capacity) {
  if (capacity <= next_.size()) return;
  next_.resize(capacity, kNoBall);
  prev_.resize(capacity, kNoBall);
  ball_cell_.resize(capacity, kNoBall);
}

std::int32_t Grid::column_of(double x) const {
  const double c = std::floor((x - lower_.x) / cell_.x);
  return static_cast<std::int32_t>(std::clamp(c, 0.0, static_cast<double>(nx_ - 1)));
}

std::int32_t Grid::row_of(double y) const {
  const double c = std::floor((y - lower_.y) / cell_.y);
  return static_cast<std::int32_t>(std::clamp(c, 0.0, static_cast<double>(ny_ - 1)));
}

void Grid::insert(std::uint32_t ball, std::int32_t cell) {
  const auto first = head_[static_cast<std::size_t>(cell)];
  next_[ball] = first;
  prev_[ball] = kNoBall;
  if (first != kNoBall) prev_[static_cast<std::size_t>(first)] = static_cast<std::int32_t>(ball);
  head_[static_cast<std::size_t>(cell)] = static_cast<std::int32_t>(ball);
  ball_cell_[ball] = cell;
}

void Grid::erase(std::uint32_t ball) {
  const std::int32_t cell = ball_cell_[ball];
  if (cell == kNoBall) return;
  const std::int32_t before = prev_[ball];
  const std::int32_t after = next_[ball];
  if (before != kNoBall) {
    next_[static_cast<std::size_t>(before)] = after;
  } else {
    head_[static_cast<std::size_t>(cell)] = after;
  }
  if (after != kNoBall) prev_[static_cast<std::size_t>(after)] = before;
  ball_cell_[ball] = kNoBall;
}

void Grid::add_wall(std::uint32_t wall, Vec2 lower, Vec2 upper) {
  // Grown by one cell: a ball whose centre is in a cell reaches at most its radius (below the
  // cell size) beyond it, and a ball logically in a cell may sit a rounding outside it.
  const std::int32_t x0 = column_of(lower.x - cell_.x);
  const std::int32_t x1 = column_of(upper.x + cell_.x);
  const std::int32_t y0 = row_of(lower.y - cell_.y);
  const std::int32_t y1 = row_of(upper.y + cell_.y);
  for (std::int32_t y = y0; y <= y1; ++y) {
    for (std::int32_t x = x0; x <= x1; ++x)
      walls_[static_cast<std::size_t>(index(x, y))].push_back(wall);
  }
}

}  // namespace carom::detail
