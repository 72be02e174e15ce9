// carom science (internal): a cell list over a periodic cell or a box, for the neighbour searches
// of a packing (random placement, the contact network, ψ₆) in O(N) rather than O(N²).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "carom/geometry.hpp"
#include "carom/vec2.hpp"

namespace carom::science {

class NeighbourCells {
 public:
  // Cells at least `reach` wide over [lower, upper): every point within reach of a position lies
  // in its 3×3 block of cells (through the wrap when periodic). About `expected` points go in;
  // there are at most about as many cells.
  NeighbourCells(Vec2 lower, Vec2 upper, double reach, bool periodic, std::uint64_t expected)
      : lower_(lower), cell_(lower, upper), periodic_(periodic) {
    const Vec2 side = upper - lower;
    const double most = std::max(1.0, std::floor(std::sqrt(static_cast<double>(expected)) * 2.0));
    columns_ = cells_along(side.x, reach, most);
    rows_ = cells_along(side.y, reach, most);
    width_ = side.x / static_cast<double>(columns_);
    height_ = side.y / static_cast<double>(rows_);
    head_.assign(columns_ * rows_, kNone);
  }

  void insert(std::uint32_t index, Vec2 position) {
    if (next_.size() <= index) {
      next_.resize(index + 1, kNone);
      positions_.resize(index + 1);
    }
    positions_[index] = position;
    const std::size_t cell = cell_index(column_of(position), row_of(position));
    next_[index] = head_[cell];
    head_[cell] = index;
  }

  // visit(j, offset) for every inserted point j in the 3×3 block of cells around position (each
  // once), with the offset from position to it (the nearest image when periodic).
  template <typename Visit>
  void for_each_near(Vec2 position, Visit visit) const {
    const std::int64_t cx = column_of(position);
    const std::int64_t cy = row_of(position);
    std::int64_t xs[3];
    std::int64_t ys[3];
    const int nx = neighbours(cx, columns_, xs);
    const int ny = neighbours(cy, rows_, ys);
    for (int i = 0; i < nx; ++i) {
      for (int k = 0; k < ny; ++k) {
        for (std::uint32_t j = head_[cell_index(xs[i], ys[k])]; j != kNone; j = next_[j]) {
          Vec2 offset = positions_[j] - position;
          if (periodic_) offset = cell_.minimum_image(offset);
          visit(j, offset);
        }
      }
    }
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffU;

  static std::size_t cells_along(double side, double reach, double most) {
    const double count = reach > 0.0 ? std::floor(side / reach) : most;
    return static_cast<std::size_t>(std::clamp(count, 1.0, most));
  }
  [[nodiscard]] std::int64_t column_of(Vec2 p) const {
    return clamp_cell(std::floor((p.x - lower_.x) / width_), columns_);
  }
  [[nodiscard]] std::int64_t row_of(Vec2 p) const {
    return clamp_cell(std::floor((p.y - lower_.y) / height_), rows_);
  }
  static std::int64_t clamp_cell(double c, std::size_t count) {
    return static_cast<std::int64_t>(std::clamp(c, 0.0, static_cast<double>(count - 1)));
  }
  [[nodiscard]] std::size_t cell_index(std::int64_t x, std::int64_t y) const {
    return static_cast<std::size_t>(y) * columns_ + static_cast<std::size_t>(x);
  }
  // The distinct cells at c − 1, c, c + 1 along an axis of `count` cells (wrapped when periodic,
  // cut at the ends otherwise).
  int neighbours(std::int64_t c, std::size_t count, std::int64_t* out) const {
    const auto n = static_cast<std::int64_t>(count);
    int found = 0;
    for (std::int64_t d = -1; d <= 1; ++d) {
      std::int64_t v = c + d;
      if (periodic_) {
        v = ((v % n) + n) % n;
      } else if (v < 0 || v >= n) {
        continue;
      }
      if (std::find(out, out + found, v) == out + found) out[found++] = v;
    }
    return found;
  }

  Vec2 lower_;
  PeriodicCell cell_;
  bool periodic_;
  std::size_t columns_ = 1;
  std::size_t rows_ = 1;
  double width_ = 1.0;
  double height_ = 1.0;
  std::vector<std::uint32_t> head_;
  std::vector<std::uint32_t> next_;
  std::vector<Vec2> positions_;
};

}  // namespace carom::science
