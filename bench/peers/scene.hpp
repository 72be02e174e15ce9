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

// Disks inside a closed box [lower, upper] of four static walls; frictionless, no damping. The
// gas and the bullets are elastic and weightless; the gravity scene sets gravity, restitution and
// its phases' times.
struct Scene {
  std::string name;
  Vec2 lower;
  Vec2 upper;
  std::vector<SceneBall> balls;
  Vec2 gravity{};            // the acceleration of every disk
  double restitution = 1.0;  // of every contact, ball on ball and ball on wall
  // Where the run's phases begin, in seconds, for a scene that has them (0: none): falling until
  // the first disk can reach the floor, impact until the last has landed and the heap has had
  // time to settle, rest after. Set from the scene's geometry, so the same for every engine.
  double impact_start = 0.0;
  double rest_start = 0.0;
  double end_time = 0.0;  // the run's length that shows all three phases
  // Whether a time-stepped engine may put still bodies to sleep (stop moving and checking them
  // until something touches them), its own way of making a heap at rest cheap; carom's resting
  // balls cost nothing without it. Off: every body is stepped every step.
  bool sleeping = false;
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

inline constexpr double kGravity = 9.81;           // length units per second², downwards
inline constexpr double kPourRestitution = 0.5;    // every contact
inline constexpr double kPourPitch = 1.5;          // the lattice's spacing: 1.5 diameters
inline constexpr double kPourVelocitySd = 0.1;     // each velocity component at the start
inline constexpr double kPourSettleSeconds = 2.0;  // after the last landing, before rest
// The rest phase's length: long enough for the peers' heaps to settle too (at N = 10³ Box2D's
// root-mean-square speed fell below 0.01 about 22 s into the run, Chipmunk's about 11 s).
inline constexpr double kPourRestSeconds = 25.0;
inline constexpr double kPourHeapPacking = 0.82;  // a frictionless heap's, for its height

// The gravity scene: n disks (radius 0.5, mass 1) on a square lattice of ⌈√n⌉ columns, 1.5
// diameters apart, filling the upper two thirds of a box as wide as the lattice (the lower third
// is empty and holds the heap they make), with velocity components normal with standard deviation
// 0.1; gravity 9.81 down, restitution 0.5, no friction. The phases: falling until the lowest
// disk, free, would touch the floor; impact until the highest, free, would reach the heap's top
// (its height from n disks at packing 0.82 across the box) plus 2 s to settle; then 25 s of rest.
[[nodiscard]] Scene make_gravity_scene(std::uint32_t n, std::uint64_t seed);

}  // namespace carom::peers
