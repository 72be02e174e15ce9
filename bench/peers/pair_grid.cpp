#include "pair_grid.hpp"

#include <algorithm>
#include <cmath>

namespace carom::peers {
namespace {

// Cells per axis at most: a region much larger than the disks (balls that flew far out of the
// box) gets bigger cells rather than a grid that does not fit in memory.
constexpr std::int64_t kMaxCellsPerAxis = 4096;

bool finite(const Box& box) {
  return std::isfinite(box.min.x) && std::isfinite(box.min.y) && std::isfinite(box.max.x) &&
         std::isfinite(box.max.y);
}

}  // namespace

std::int64_t PairGrid::cell_x(double x) const noexcept {
  const double c = std::floor((x - lower_.x) * inverse_cell_);
  return std::clamp(static_cast<std::int64_t>(std::clamp(c, -1.0, 1e15)), std::int64_t{0},
                    columns_ - 1);
}

std::int64_t PairGrid::cell_y(double y) const noexcept {
  const double c = std::floor((y - lower_.y) * inverse_cell_);
  return std::clamp(static_cast<std::int64_t>(std::clamp(c, -1.0, 1e15)), std::int64_t{0},
                    rows_ - 1);
}

void PairGrid::build(std::span<const Box> boxes, Vec2 lower, Vec2 upper, double cell_size) {
  boxes_ = boxes;
  lower_ = lower;
  const double width = std::max(upper.x - lower.x, cell_size);
  const double height = std::max(upper.y - lower.y, cell_size);
  const double cell = std::max({cell_size, width / kMaxCellsPerAxis, height / kMaxCellsPerAxis});
  inverse_cell_ = 1.0 / cell;
  columns_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(width / cell)));
  rows_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(height / cell)));
  const auto cells = static_cast<std::size_t>(columns_ * rows_);
  cell_start_.assign(cells + 1, 0);
  skipped_ = 0;

  // Counting sort: count each cell's boxes, turn the counts into offsets, then fill.
  for (const Box& box : boxes) {
    if (!finite(box)) {
      ++skipped_;
      continue;
    }
    for (std::int64_t y = cell_y(box.min.y); y <= cell_y(box.max.y); ++y) {
      for (std::int64_t x = cell_x(box.min.x); x <= cell_x(box.max.x); ++x) {
        ++cell_start_[static_cast<std::size_t>(y * columns_ + x) + 1];
      }
    }
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  entries_.resize(cell_start_[cells]);
  fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    const Box& box = boxes[i];
    if (!finite(box)) continue;
    for (std::int64_t y = cell_y(box.min.y); y <= cell_y(box.max.y); ++y) {
      for (std::int64_t x = cell_x(box.min.x); x <= cell_x(box.max.x); ++x) {
        entries_[fill_[static_cast<std::size_t>(y * columns_ + x)]++] = i;
      }
    }
  }
}

}  // namespace carom::peers
