// carom: the names the world gives its balls and walls.
#pragma once

#include <cstdint>

namespace carom {

// A handle to a ball: a slot index and the slot's generation. A removed ball's handle goes stale
// (its slot's generation moves on) and every use of it throws. The default handle is null.
struct BallId {
  std::uint32_t index = 0;
  std::uint32_t generation = 0;  // 0 only in the null handle

  [[nodiscard]] constexpr bool is_null() const noexcept { return generation == 0; }
  friend constexpr bool operator==(BallId, BallId) noexcept = default;
};

// Static geometry is never removed; a wall is named by the order it was added in (from 0).
using WallId = std::uint32_t;

}  // namespace carom
