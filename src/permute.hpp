// carom internal: re-ordering the engine's per-ball arrays in place.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace carom::detail {

// Moves each values[i] to values[destination[i]] (destination is a permutation of
// 0 .. size-1). In place, cycle by cycle, so that re-ordering a large world's arrays needs no
// second copy of them (which would raise the process's peak memory).
template <class Vector>
void move_to(Vector& values, std::span<const std::uint32_t> destination) {
  std::vector<bool> moved(destination.size(), false);
  for (std::size_t start = 0; start < destination.size(); ++start) {
    if (moved[start]) continue;
    auto carried = std::move(values[start]);
    for (std::size_t from = start;;) {
      moved[from] = true;
      const std::size_t to = destination[from];
      if (to == start) {
        values[start] = std::move(carried);
        break;
      }
      std::swap(carried, values[to]);
      from = to;
    }
  }
}

}  // namespace carom::detail
