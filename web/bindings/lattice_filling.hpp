// carom web: the "Many balls" page's generated balls. N equal balls on a rectangular lattice
// spread over the world's box, each moving at the same speed in a random direction. Sites where a
// ball would overlap a wall already in the world are left empty.
#pragma once

#include <cstdint>

#include "drawn_world.hpp"

namespace carom::web {

struct LatticeFilling {
  int count = 1000;                // lattice sites, N >= 1
  double packing_fraction = 0.25;  // N balls' area over the box's; sets their radius
  double speed = 10.0;             // every ball's speed, length units per time unit
  std::uint32_t seed = 1;          // for the directions
};

// Adds the balls to world, whose boundary must be a box or a periodic cell; returns how many it
// placed. Throws carom::InvalidArgument when the lattice is too dense for the balls to fit.
int fill_lattice(DrawnWorld& world, const LatticeFilling& filling);

}  // namespace carom::web
