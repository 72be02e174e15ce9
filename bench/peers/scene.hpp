// carom peers benchmark: the scenes every engine runs, built once by the harness and handed to
// each engine as plain numbers, so that carom, Box2D and Chipmunk start from the same state.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "carom/vec2.hpp"

namespace carom::peers {

// One disk as the scene places it. Units: length, length per second (steps are 1/60 s), mass.
struct SceneBall {
  Vec2 position;
  Vec2 velocity;
  double radius = 0.5;
  double mass = 1.0;
  bool bullet = false;  // a fast ball: engines that have a continuous mode for them turn it on
};

// Disks inside a closed square box [lower, upper]² of four static walls; elastic, frictionless,
// no gravity, no damping.
struct Scene {
  std::string name;
  Vec2 lower;
  Vec2 upper;
  std::vector<SceneBall> balls;
};

inline constexpr double kGasRadius = 0.5;
inline constexpr double kGasMass = 1.0;
inline constexpr double kGasVelocitySd = 1.0;  // each velocity component, length per second

// The gas: n equal disks (radius 0.5, mass 1) at packing fraction `packing` (n·π·r² over the
// box's area), on a square grid of ⌈√n⌉² sites with the empty sites spread evenly, each disk
// jittered uniformly within its site as far as it can go without touching a neighbour or a wall;
// velocity components normal with standard deviation 1. The box is centred on the origin (Box2D
// works in single precision, which is most accurate near the origin). Deterministic for a seed
// on a given standard library. Throws std::invalid_argument if the disks do not fit.
[[nodiscard]] Scene make_gas_scene(std::uint32_t n, double packing, std::uint64_t seed);

inline constexpr std::uint32_t kBulletCount = 100;
inline constexpr std::uint32_t kBulletFieldCount = 1000;
inline constexpr double kBulletRadius = 0.05;              // a tenth of a field disk's radius
inline constexpr double kBulletDiametersPerStep = 1000.0;  // so 100 length units per step
inline constexpr double kBulletFieldPacking = 0.2;

// The bullets: a field of 1000 gas disks (packing 0.2 over the box, resting, so that only the
// bullets move at first) and, in a strip along the box's left wall kept free of the field, 100
// small disks (radius 0.05, mass in proportion to area: 0.01) flying to the right at 1000 of
// their diameters per step of 1/60 s, spread evenly up the strip so that each crosses the field.
// Over one step a bullet moves 100 length units, more than the box is wide (about 63).
[[nodiscard]] Scene make_bullets_scene(std::uint64_t seed, double steps_per_second);

}  // namespace carom::peers
