// carom internal: re-ordering the engine's per-ball arrays in place.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace carom::detail {

// Rearranges `values` so that the new values[k] is the old values[order[k]] (order is a
// permutation of 0 .. size-1). In place, cycle by cycle, so that re-ordering a large world's
// arrays needs no second copy of them (which would raise the process's peak memory).
template <class Vector>
void permute(Vector& values, std::span<const std::uint32_t> order) {
  std::vector<bool> done(order.size(), false);
  for (std::size_t start = 0; start < order.size(); ++start) {
    if (done[start]) continue;
    auto first = std::move(values[start]);
    std::size_t k = start;
    for (;;) {
      done[k] = true;
      const std::size_t from = order[k];
      if (from == start) {
        values[k] = std::move(first);
        break;
      }
      values[k] = std::move(values[from]);
      k = from;
    }
  }
}

}  // namespace carom::detail
