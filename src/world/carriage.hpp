// carom internal: how gravity carries a movable ball: falling freely, sliding along one support
// with gravity's part along it, or resting on its supports (docs/engine.md, "Resting and
// sliding"). Kept beside the slots, by slot, only in a world with gravity.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "carom/vec2.hpp"

namespace carom::detail {

enum class Carried : std::uint8_t {
  free,     // acceleration: gravity
  sliding,  // along the line through `origin` at right angles to `normal`, within [lower, upper]
  resting,  // velocity and acceleration zero until something disturbs it
};

// A support: a wall, by its id, or a ball, by its handle index (which sorting the slots leaves
// alone) with kBallSupport set.
inline constexpr std::uint32_t kBallSupport = 1U << 31;

struct Carriage {
  Vec2 acceleration;  // gravity (free), its part along the support (sliding), zero (resting)
  // Sliding: the unit normal from the centre towards the support at the touch, and the line the
  // centre slides on: through `origin` (the centre at the touch; for a ball support, the offset
  // from that ball's centre), leaving the support where its coordinate along the line,
  // left_normal(normal)·(centre − origin), passes `lower` or `upper` (a segment's ends; for a
  // curved support, where the gap has opened by the rest height).
  Vec2 normal;
  Vec2 origin;
  double lower = 0.0;
  double upper = 0.0;
  std::array<std::uint32_t, 2> support{};
  std::uint8_t supports = 0;  // how many of `support` hold (0 free, 1 sliding, 1 or 2 resting)
  Carried state = Carried::free;
};

// Whether a ball at velocity `u` approaches one at `w` along the unit normal `n` (from the first
// towards the second) by more than the rounding of the velocities: a smaller approach is
// rounding, which an impulse could not remove.
[[nodiscard]] inline bool approaching(Vec2 u, Vec2 w, Vec2 n) {
  const double scale = std::abs(u.x) + std::abs(u.y) + std::abs(w.x) + std::abs(w.y);
  return dot(u - w, n) > 0x1p-50 * scale;
}

// On a table: whether a touching pair at velocities `u` and `w`, with relative acceleration
// `press_by` (the first's less the second's), approaches along `n`, or keeps touching with no
// relative motion along it (to rounding) while the acceleration presses it together.
[[nodiscard]] inline bool held_or_approaching(Vec2 u, Vec2 w, Vec2 press_by, Vec2 n) {
  const double rounding = 0x1p-50 * (std::abs(u.x) + std::abs(u.y) + std::abs(w.x) + std::abs(w.y));
  const double approach = dot(u - w, n);
  return approach > rounding || (approach >= -rounding && dot(press_by, n) > 0.0);
}

}  // namespace carom::detail
