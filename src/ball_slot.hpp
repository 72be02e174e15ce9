// carom internal: a ball's record as the world's engine stores it, one slot a ball, and what
// prediction reads of every candidate partner (the radius and mass it reads too are its
// species', species.hpp). Design: docs/world.md, "Memory layout".
#pragma once

#include <cstdint>

#include "carom/vec2.hpp"

namespace carom::detail {

inline constexpr std::uint32_t kNoSpecies = 0xFFFFFFFFu;  // a free slot's

// 48 bytes. A ball moves in a straight line between its events, so it is stored at its own
// local time: its position at any later time t is position + velocity·(t − local_time).
struct alignas(16) BallSlot {
  Vec2 position;
  Vec2 velocity;
  double local_time = 0.0;
  std::uint32_t species = kNoSpecies;  // kNoSpecies while the slot is free
  std::uint32_t version = 0;           // bumped whenever the trajectory changes

  [[nodiscard]] bool alive() const { return species != kNoSpecies; }
  [[nodiscard]] Vec2 position_at(double t) const { return position + velocity * (t - local_time); }
};
static_assert(sizeof(BallSlot) == 48);

}  // namespace carom::detail
