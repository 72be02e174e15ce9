// Reproducible random scenes for the World tests: a gas of balls on a jittered grid (so that no
// two overlap and none touches a wall at the start), in a box or a periodic cell.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "world/reference_simulator.hpp"

namespace carom::testing {

struct GasOptions {
  std::size_t ball_count = 100;
  double side = 100.0;    // the box or the periodic cell is [0, side]²
  bool periodic = false;  // otherwise a closed box: box_walls(0, side) are walls 0..3
  double min_radius = 0.3;
  double max_radius = 0.7;
  double max_speed = 1.0;  // each ball gets a uniform direction and a speed in [0, max_speed]
  double min_mass = 0.5;
  double max_mass = 2.0;
  std::vector<double> restitutions = {1.0};  // each ball picks one of these
  double immovable_fraction = 0.0;  // this share of the balls are resting posts (kImmovable)
};

[[nodiscard]] ReferenceScene random_gas(const GasOptions& options, std::uint64_t seed);

}  // namespace carom::testing
