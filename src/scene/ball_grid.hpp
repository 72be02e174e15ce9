// carom scenes internal: a hashed uniform grid of ball centres, for the checks and queries that
// must not cost O(N²) on a scene of 10⁵ balls (overlaps, smallest gap, random placement).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "carom/geometry.hpp"
#include "carom/vec2.hpp"

namespace carom::scene_detail {

class BallGrid {
 public:
  // cell_size >= the largest distance between centres the caller will ask about (for overlaps:
  // the largest diameter). With a periodic cell, positions wrap and distances are to the nearest
  // image.
  BallGrid(double cell_size, std::optional<PeriodicCell> periodic);

  void insert(std::size_t index, Vec2 position);

  // The offset from a to b, through the nearest image when periodic.
  [[nodiscard]] Vec2 offset(Vec2 a, Vec2 b) const;

  // Calls visit(index) for every inserted ball in the 3×3 block of cells around position (each
  // ball once), so every ball within cell_size of position is visited.
  template <typename Visit>
  void for_each_near(Vec2 position, Visit visit) const {
    const auto [cx, cy] = cell_of(position);
    std::int64_t seen_x[3];
    std::int64_t seen_y[3];
    int nx = 0;
    int ny = 0;
    for (int d = -1; d <= 1; ++d) {
      add_unique(seen_x, nx, wrap(cx + d, columns_));
      add_unique(seen_y, ny, wrap(cy + d, rows_));
    }
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        const auto found = cells_.find(key(seen_x[i], seen_y[j]));
        if (found == cells_.end()) continue;
        for (const std::size_t index : found->second) visit(index);
      }
    }
  }

 private:
  struct Cell {
    std::int64_t x;
    std::int64_t y;
  };
  [[nodiscard]] Cell cell_of(Vec2 position) const;
  [[nodiscard]] static std::int64_t wrap(std::int64_t c, std::int64_t count);
  [[nodiscard]] static std::uint64_t key(std::int64_t x, std::int64_t y);
  static void add_unique(std::int64_t* seen, int& count, std::int64_t value);

  double cell_x_;
  double cell_y_;
  std::optional<PeriodicCell> periodic_;
  std::int64_t columns_ = 0;  // periodic only; 0 for an unbounded grid
  std::int64_t rows_ = 0;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

}  // namespace carom::scene_detail
