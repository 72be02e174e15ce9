// carom web: the "Many balls" page's generated scene. N equal balls on a rectangular lattice in a
// closed box, each moving at the same speed in a random direction.
#pragma once

#include <cstdint>

#include "carom/vec2.hpp"
#include "drawn_world.hpp"

namespace carom::web {

struct BoxFilling {
  int count = 1000;                // N >= 1
  Vec2 size{160.0, 100.0};         // the box, from (0, 0) to size
  double packing_fraction = 0.25;  // area of the balls over the box's; sets their radius
  double speed = 10.0;             // every ball's speed, length units per time unit
  double restitution = 1.0;
  std::uint32_t seed = 1;  // for the directions
};

// Throws carom::InvalidArgument when the balls cannot be placed on the lattice without touching.
[[nodiscard]] DrawnWorld fill_box(const BoxFilling& filling);

}  // namespace carom::web
