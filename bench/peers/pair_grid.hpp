// carom peers benchmark: a uniform grid over axis-aligned boxes that lists each pair of
// overlapping boxes once, so that the detectors check N disks in O(N) rather than O(N²).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "carom/vec2.hpp"

namespace carom::peers {

struct Box {
  Vec2 min;
  Vec2 max;
};

class PairGrid {
 public:
  // Sorts the boxes into cells of side at least `cell_size` over [lower, upper]; a box reaching
  // beyond the region is counted in the border cells (the pair test stays exact, it is only
  // slower). Boxes with a non-finite corner are left out; `skipped()` counts them.
  void build(std::span<const Box> boxes, Vec2 lower, Vec2 upper, double cell_size);

  // Calls visit(i, j), i < j, once for every pair of boxes that overlap (touching counts).
  template <typename Visit>
  void for_each_overlapping_pair(Visit&& visit) const;

  [[nodiscard]] std::uint32_t skipped() const noexcept { return skipped_; }

 private:
  struct CellRange {
    std::int64_t x0, y0, x1, y1;
  };
  [[nodiscard]] std::int64_t cell_x(double x) const noexcept;
  [[nodiscard]] std::int64_t cell_y(double y) const noexcept;

  std::span<const Box> boxes_;
  Vec2 lower_;
  double inverse_cell_ = 1.0;
  std::int64_t columns_ = 1;
  std::int64_t rows_ = 1;
  std::vector<std::uint32_t> cell_start_;  // columns·rows + 1 offsets into entries_
  std::vector<std::uint32_t> entries_;     // box indices, cell by cell
  std::vector<std::uint32_t> fill_;        // the next free entry of each cell, while building
  std::uint32_t skipped_ = 0;
};

template <typename Visit>
void PairGrid::for_each_overlapping_pair(Visit&& visit) const {
  for (std::int64_t cell = 0; cell < columns_ * rows_; ++cell) {
    const std::uint32_t begin = cell_start_[static_cast<std::size_t>(cell)];
    const std::uint32_t end = cell_start_[static_cast<std::size_t>(cell) + 1];
    for (std::uint32_t p = begin; p < end; ++p) {
      const Box& a = boxes_[entries_[p]];
      for (std::uint32_t q = p + 1; q < end; ++q) {
        const Box& b = boxes_[entries_[q]];
        if (a.max.x < b.min.x || b.max.x < a.min.x || a.max.y < b.min.y || b.max.y < a.min.y) {
          continue;
        }
        // Two boxes share every cell their intersection covers; the pair is reported only from
        // the cell that holds the intersection's lower-left corner.
        const double corner_x = a.min.x > b.min.x ? a.min.x : b.min.x;
        const double corner_y = a.min.y > b.min.y ? a.min.y : b.min.y;
        if (cell_y(corner_y) * columns_ + cell_x(corner_x) != cell) continue;
        const std::uint32_t i = entries_[p];
        const std::uint32_t j = entries_[q];
        if (i < j) {
          visit(i, j);
        } else {
          visit(j, i);
        }
      }
    }
  }
}

}  // namespace carom::peers
