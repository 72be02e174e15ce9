// carom internal: a ball's record as the world's engine stores it, one slot a ball, and what
// prediction reads of every candidate partner (the radius and mass it reads too are its
// species', species.hpp). Design: docs/engine.md, "Memory".
#pragma once

#include <cstdint>

#include "carom/vec2.hpp"

namespace carom::detail {

inline constexpr std::uint32_t kNoSpecies = 0xFFFFFFFFu;  // a free slot's
inline constexpr std::int32_t kNoBall = -1;               // no ball, no cell (grid.hpp)

// 64 bytes, one cache line. A ball moves in a straight line between its events, so it is stored
// at its own local time: its position at any later time t is position + velocity·(t − local_time).
// The grid's entries for the ball sit in the same line (grid.hpp): walking a cell's list then
// reads the line that prediction reads of each neighbour anyway, where a 48-byte slot (which
// straddles two lines half the time) beside the grid's own arrays touched two to four lines a
// neighbour; 8 bytes are left over (docs/decisions/0010-memory-layout.md).
struct alignas(64) BallSlot {
  Vec2 position;
  Vec2 velocity;
  double local_time = 0.0;
  std::uint32_t species = kNoSpecies;  // kNoSpecies while the slot is free
  std::uint32_t version = 0;           // bumped whenever the trajectory changes
  // Written by the grid alone (Grid::insert, erase, setup, relist).
  std::int32_t cell_next = kNoBall;  // the next ball in its cell's list
  std::int32_t cell = kNoBall;       // the cell it is listed in

  [[nodiscard]] bool alive() const { return species != kNoSpecies; }
  [[nodiscard]] Vec2 position_at(double t) const { return position + velocity * (t - local_time); }
};
static_assert(sizeof(BallSlot) == 64);

}  // namespace carom::detail
