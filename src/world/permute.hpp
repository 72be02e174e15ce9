// carom internal: re-ordering the engine's per-ball arrays in place.
#pragma once

#include <cstdint>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

namespace carom::detail {

// Moves each values[i] to values[destination[i]] (destination is a permutation of
// 0 .. size-1), in every one of the arrays (all of that size). In place, cycle by cycle, so that
// re-ordering a large world's arrays needs no second copy of them (which would raise the
// process's peak memory). The cycles are followed once for all the arrays: each step's next
// place is a load that depends on the last, so a step costs a memory round trip wherever the
// permutation jumps, and the arrays' own moves in one step overlap
// (docs/decisions/0012-ball-order-by-cell.md).
template <class... Vectors>
void move_all_to(std::span<const std::uint32_t> destination, Vectors&... arrays) {
  std::vector<bool> moved(destination.size(), false);
  for (std::size_t start = 0; start < destination.size(); ++start) {
    if (moved[start]) continue;
    moved[start] = true;
    if (destination[start] == start) continue;  // (in place: nothing to carry)
    std::tuple carried{std::move(arrays[start])...};
    for (std::size_t from = start;;) {
      const std::size_t to = destination[from];
      if (to == start) {
        std::apply([&](auto&... values) { ((arrays[start] = std::move(values)), ...); }, carried);
        break;
      }
      std::apply([&](auto&... values) { (std::swap(values, arrays[to]), ...); }, carried);
      moved[to] = true;
      from = to;
    }
  }
}

template <class Vector>
void move_to(Vector& values, std::span<const std::uint32_t> destination) {
  move_all_to(destination, values);
}

}  // namespace carom::detail
