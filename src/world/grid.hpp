// carom internal: the world's broad phase, a uniform grid of square cells no smaller than the
// largest ball's diameter, so that two balls in contact are always in the same or neighbouring
// cells. Balls are kept in intrusive singly linked lists per cell, whose links are in the balls'
// slots (ball_slot.hpp; no allocation while running); walls are listed in every cell their box,
// grown by the cell size, overlaps.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "ball_slot.hpp"
#include "carom/vec2.hpp"
#include "fixed_divisor.hpp"
#include "huge_page_allocator.hpp"

namespace carom::detail {

class Grid {
 public:
  // nx × ny cells of size `cell` (width, height) from `lower`; periodic wraps both axes. A ball
  // leaves its cell only once its centre is `hysteresis` (per axis) beyond the cell's side, so
  // that a ball's centre lies within its cell grown by that much; the cell less twice the
  // hysteresis is what must hold the largest diameter (docs/engine.md, "The broad phase").
  // In a closed grid (a box) the outer sides of the outermost cells are never left.
  // Every ball of the slots (use_slots) is left in no cell.
  void setup(Vec2 lower, Vec2 cell, std::int32_t nx, std::int32_t ny, bool periodic, bool closed,
             Vec2 hysteresis);
  // The balls' slots, where the grid keeps each ball's list link and cell (ball_slot.hpp): the
  // caller keeps the vector alive, at the same address, as long as the grid is used; the grid
  // never resizes it (a new slot is in no cell).
  void use_slots(BigVector<BallSlot>& slots) { slots_ = &slots; }

  [[nodiscard]] std::int32_t nx() const { return nx_; }
  [[nodiscard]] std::int32_t ny() const { return ny_; }
  [[nodiscard]] Vec2 cell_size() const { return cell_; }
  [[nodiscard]] Vec2 hysteresis() const { return hysteresis_; }
  // The largest diameter the cells can hold: the cell less twice the hysteresis, per axis.
  [[nodiscard]] double room() const {
    return std::min(cell_.x - 2.0 * hysteresis_.x, cell_.y - 2.0 * hysteresis_.y);
  }
  [[nodiscard]] Vec2 lower() const { return lower_; }
  [[nodiscard]] Vec2 upper() const { return lower_ + Vec2{cell_.x * nx_, cell_.y * ny_}; }
  [[nodiscard]] bool periodic() const { return periodic_; }
  [[nodiscard]] std::int32_t index(std::int32_t cx, std::int32_t cy) const { return cy * nx_ + cx; }
  // Whether the 3×3 block around cell (cx, cy) lies inside the grid (no cell of it clipped or
  // wrapped).
  [[nodiscard]] bool block_inside(std::int32_t cx, std::int32_t cy) const {
    return cx > 0 && cy > 0 && cx + 1 < nx_ && cy + 1 < ny_;
  }
  // (Cell numbers are below 2^31: the row by multiplication, not a division instruction.)
  [[nodiscard]] std::int32_t row(std::int32_t cell) const {
    return static_cast<std::int32_t>(rows_.divide(static_cast<std::uint32_t>(cell)));
  }
  [[nodiscard]] std::int32_t column(std::int32_t cell) const { return cell - row(cell) * nx_; }
  // The cell column/row of a coordinate, clamped to the grid.
  [[nodiscard]] std::int32_t column_of(double x) const;
  [[nodiscard]] std::int32_t row_of(double y) const;
  [[nodiscard]] std::int32_t cell_of(Vec2 p) const { return index(column_of(p.x), row_of(p.y)); }
  // The cell's lower-left corner and upper-right corner.
  [[nodiscard]] Vec2 cell_lower(std::int32_t cell) const {
    return cell_lower(column(cell), row(cell));
  }
  [[nodiscard]] Vec2 cell_upper(std::int32_t cell) const {
    return {lower_.x + cell_.x * (column(cell) + 1), lower_.y + cell_.y * (row(cell) + 1)};
  }
  [[nodiscard]] Vec2 cell_lower(std::int32_t cx, std::int32_t cy) const {
    return {lower_.x + cell_.x * cx, lower_.y + cell_.y * cy};
  }
  // Where a ball in column cx leaves its cell moving down the x axis (upward = false) or up it
  // (true), and likewise in row cy along y: the cell's side, the hysteresis beyond it, but for
  // the periodic cell's own sides, where a ball re-enters at the opposite side (so that positions
  // stay in the cell); ±infinity at a closed grid's outer sides, which are never left. Tabled by
  // column and row (setup), read by the direction's index: which cell a ball is in, and which
  // way it moves, are random, and a branch on either mispredicts.
  [[nodiscard]] double exit_x(std::int32_t cx, bool upward) const {
    return exits_x_[2 * static_cast<std::size_t>(cx) + upward];
  }
  [[nodiscard]] double exit_y(std::int32_t cy, bool upward) const {
    return exits_y_[2 * static_cast<std::size_t>(cy) + upward];
  }
  // Rebuilds every cell's list, in ascending order, from the cells the slots hold: after the
  // world has re-ordered its slots, each ball's cell moved with it.
  void relist();

  void insert(std::uint32_t ball, std::int32_t cell);
  void erase(std::uint32_t ball);
  [[nodiscard]] std::int32_t cell_of_ball(std::uint32_t ball) const { return (*slots_)[ball].cell; }
  [[nodiscard]] std::int32_t first_ball(std::int32_t cell) const {
    return head_[static_cast<std::size_t>(cell)];
  }
  [[nodiscard]] std::int32_t next_ball(std::uint32_t ball) const {
    return (*slots_)[ball].cell_next;
  }

  // The list heads of the 3×3 block around the interior cell (cx, cy): row r's three at
  // heads[4r .. 4r + 2], and bit 4r + k of `occupied` set where heads[4r + k] names a ball. Read
  // a row at a time where the CPU has SSE2 (every x86-64): the row's three heads and the one after
  // them (the grid keeps a head past its last cell for this) in one load, compared at once.
  struct BlockHeads {
    alignas(16) std::int32_t heads[12];
    std::uint32_t occupied;
  };
  [[nodiscard]] BlockHeads block_heads(std::int32_t cx, std::int32_t cy) const;

  // For the engine's lookahead (world_lookahead.cpp): asks the cache for the list heads of the
  // 3×3 block around the interior cell (cx, cy), three rows of three. (Inlined by force: GCC 12
  // takes a function that only prefetches for one without effects and drops the calls to it that
  // it has not inlined by then.)
  [[gnu::always_inline]] void prefetch_block_heads(std::int32_t cx, std::int32_t cy) const {
    for (std::int32_t row = cy - 1; row <= cy + 1; ++row) {
      const std::int32_t* first = &head_[static_cast<std::size_t>(index(cx - 1, row))];
      __builtin_prefetch(first);
      __builtin_prefetch(first + 2);  // (a row's 12 bytes may straddle two lines)
    }
  }

  // The cells a wall with this bounding box is listed in: columns x0..x1, rows y0..y1.
  struct CellSpan {
    std::int32_t x0, x1, y0, y1;
  };
  [[nodiscard]] CellSpan wall_cells(Vec2 lower, Vec2 upper) const {
    // Its box grown by one cell: a ball whose centre is in a cell reaches at most its radius
    // (below the cell size) beyond it, and a ball logically in a cell may sit a rounding
    // outside it.
    return {column_of(lower.x - cell_.x), column_of(upper.x + cell_.x), row_of(lower.y - cell_.y),
            row_of(upper.y + cell_.y)};
  }
  // Lists the walls, given by their bounding boxes (wall k: lower[k], upper[k]), in the cells.
  void set_walls(std::span<const Vec2> lower, std::span<const Vec2> upper);
  [[nodiscard]] std::span<const std::uint32_t> walls(std::int32_t cell) const {
    if (wall_start_.empty()) return {};
    const auto c = static_cast<std::size_t>(cell);
    return {wall_ids_.data() + wall_start_[c], wall_ids_.data() + wall_start_[c + 1]};
  }

  // Calls visit(neighbour_cell) for the 3×3 block around `cell`, each cell once (wrapping in a
  // periodic grid, clipped at the edges otherwise).
  template <typename Visit>
  void for_each_neighbour(std::int32_t cell, Visit&& visit) const {
    const std::int32_t cx = column(cell);
    const std::int32_t cy = row(cell);
    std::int32_t columns[3];
    std::int32_t rows[3];
    const int column_count = neighbours(cx, nx_, columns);
    const int row_count = neighbours(cy, ny_, rows);
    for (int r = 0; r < row_count; ++r) {
      const std::int32_t base = rows[r] * nx_;
      for (int c = 0; c < column_count; ++c) visit(base + columns[c]);
    }
  }

 private:
  // The indices next to i along an axis of n cells (wrapping, or clipped at the edges), without
  // an integer division; a periodic grid has n >= 3, so the three are distinct.
  [[nodiscard]] int neighbours(std::int32_t i, std::int32_t n, std::int32_t out[3]) const {
    int count = 0;
    if (i > 0) {
      out[count++] = i - 1;
    } else if (periodic_) {
      out[count++] = n - 1;
    }
    out[count++] = i;
    if (i + 1 < n) {
      out[count++] = i + 1;
    } else if (periodic_) {
      out[count++] = 0;
    }
    return count;
  }

  Vec2 lower_;
  Vec2 cell_{1.0, 1.0};
  Vec2 hysteresis_;
  std::int32_t nx_ = 1;
  std::int32_t ny_ = 1;
  FixedDivisor rows_{1};  // division by nx_
  bool periodic_ = false;
  std::vector<double> exits_x_;           // by column: the exits down and up the axis (exit_x)
  std::vector<double> exits_y_;           // by row
  BigVector<std::int32_t> head_;          // by cell: first ball, or kNoBall; and one more (above)
  BigVector<BallSlot>* slots_ = nullptr;  // each ball's link and cell (use_slots)
  // The cells' wall lists, concatenated (cell c's: wall_ids_[wall_start_[c] .. wall_start_[c+1]]);
  // both empty in a world without walls, so cells then cost only their list head.
  std::vector<std::uint32_t> wall_start_;
  std::vector<std::uint32_t> wall_ids_;
};

inline Grid::BlockHeads Grid::block_heads(std::int32_t cx, std::int32_t cy) const {
  BlockHeads block;
  block.occupied = 0;
  for (std::size_t row = 0; row < 3; ++row) {
    const std::int32_t* first =
        &head_[static_cast<std::size_t>(index(cx - 1, cy - 1 + static_cast<std::int32_t>(row)))];
    const std::size_t at = 4 * row;  // the row's place in heads and occupied
#if defined(__SSE2__)
    const __m128i heads = _mm_loadu_si128(reinterpret_cast<const __m128i*>(first));
    _mm_store_si128(reinterpret_cast<__m128i*>(&block.heads[at]), heads);
    const __m128i empty = _mm_cmpeq_epi32(heads, _mm_set1_epi32(kNoBall));
    const auto empty_bits = static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(empty)));
    block.occupied |= (~empty_bits & 7U) << at;
#else
    for (std::size_t k = 0; k < 3; ++k) {
      block.heads[at + k] = first[k];
      block.occupied |= static_cast<std::uint32_t>(first[k] != kNoBall) << (at + k);
    }
#endif
  }
  return block;
}

}  // namespace carom::detail
