// carom: standard pool tables as scenes — a 7-, 8- or 9-foot table's playing surface, its
// cushions with jaws at six pockets, the pockets, and a rack of balls with the cue ball on the
// head spot, on a cloth with the standard friction (world.table). The user guide: docs/pool.md,
// "Standard tables".
#pragma once

#include <cstdint>

#include "carom/scene.hpp"

namespace carom {

// The WPA's playing surfaces, between the cushions' noses: 78 x 39, 88 x 44 and 100 x 50 inches.
enum class PoolTableSize : std::uint8_t { seven_foot, eight_foot, nine_foot };

enum class PoolRack : std::uint8_t {
  none,        // the cue ball alone
  eight_ball,  // 15 balls in a triangle, the 8 in its middle
  nine_ball,   // 9 balls in a diamond, the 1 at the front and the 9 in the middle
};

struct PoolTableSpec {
  PoolTableSize size = PoolTableSize::nine_foot;
  PoolRack rack = PoolRack::eight_ball;
  double ball_radius = 0.028575;  // m (57.15 mm balls)
  double ball_mass = 0.17;        // kg
  // The gap left between neighbouring balls of the rack (m): a rack whose balls touch exactly
  // meets one pair at a time all the same, and a gap keeps the scene's check of overlaps clear.
  double rack_gap = 1e-4;
};

// The table as a scene in metres, seconds and kilograms: a box around the rails (balls that
// leave the table stay in it), the cushions' noses as segments from jaw to jaw, the jaws as
// segments turned 38° (corner) and 76° (side) off the cushion line into each pocket, the pockets
// as discs behind the jaws, and the rack with its apex on the foot spot, the cue ball ("cue") on
// the head spot. Balls are named by their numbers and coloured as pool balls are. Throws
// InvalidArgument for a radius or mass that is not positive and finite, or a negative gap.
[[nodiscard]] Scene pool_table_scene(const PoolTableSpec& spec = {});

}  // namespace carom
