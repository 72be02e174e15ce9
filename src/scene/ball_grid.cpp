#include "ball_grid.hpp"

#include <algorithm>
#include <cmath>

namespace carom::scene_detail {
namespace {

// Cell coordinates are clamped here so that far-away (or huge) positions share edge cells
// rather than overflow; sharing a cell only costs time, never a missed neighbour.
constexpr double kMaxCellCoordinate = 1 << 30;

}  // namespace

BallGrid::BallGrid(double cell_size, std::optional<PeriodicCell> periodic)
    : cell_x_(cell_size), cell_y_(cell_size), periodic_(periodic) {
  if (!(cell_x_ > 0.0) || !std::isfinite(cell_x_)) {
    cell_x_ = 1.0;
    cell_y_ = 1.0;
  }
  if (periodic_) {
    const Vec2 size = periodic_->period();
    columns_ = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::min(kMaxCellCoordinate, std::floor(size.x / cell_x_))));
    rows_ = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::min(kMaxCellCoordinate, std::floor(size.y / cell_y_))));
    cell_x_ = size.x / static_cast<double>(columns_);
    cell_y_ = size.y / static_cast<double>(rows_);
  }
}

BallGrid::Cell BallGrid::cell_of(Vec2 position) const {
  Vec2 p = position;
  if (periodic_) p -= periodic_->lower();
  const double fx = std::clamp(std::floor(p.x / cell_x_), -kMaxCellCoordinate, kMaxCellCoordinate);
  const double fy = std::clamp(std::floor(p.y / cell_y_), -kMaxCellCoordinate, kMaxCellCoordinate);
  auto x = static_cast<std::int64_t>(std::isnan(fx) ? 0.0 : fx);
  auto y = static_cast<std::int64_t>(std::isnan(fy) ? 0.0 : fy);
  return {wrap(x, columns_), wrap(y, rows_)};
}

std::int64_t BallGrid::wrap(std::int64_t c, std::int64_t count) {
  if (count == 0) return c;
  c %= count;
  return c < 0 ? c + count : c;
}

std::uint64_t BallGrid::key(std::int64_t x, std::int64_t y) {
  constexpr std::int64_t kBias = std::int64_t{1} << 31;
  return (static_cast<std::uint64_t>(x + kBias) << 32U) ^ static_cast<std::uint64_t>(y + kBias);
}

void BallGrid::add_unique(std::int64_t* seen, int& count, std::int64_t value) {
  for (int i = 0; i < count; ++i) {
    if (seen[i] == value) return;
  }
  seen[count++] = value;
}

void BallGrid::insert(std::size_t index, Vec2 position) {
  const Cell cell = cell_of(position);
  cells_[key(cell.x, cell.y)].push_back(index);
}

Vec2 BallGrid::offset(Vec2 a, Vec2 b) const {
  return periodic_ ? periodic_->minimum_image(b - a) : b - a;
}

}  // namespace carom::scene_detail
