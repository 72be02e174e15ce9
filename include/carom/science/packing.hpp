// carom science: dense and jammed packings of disks by Lubachevsky–Stillinger compression —
// event-driven dynamics while every radius grows at a common rate, with a thermostat taking out
// the energy the growth pumps in.
//
// make_packing_world() places N disks (one size, or two) at random in a periodic cell or a box at
// a low packing fraction; compress() grows them until a target packing fraction, or until the
// packing jams (the reduced pressure passes a threshold). The contact network of the result is
// found by find_contact_network (contact_network.hpp). Definitions and derivations:
// docs/science.md, "Compression and jamming".
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

#include "carom/world.hpp"

namespace carom::science {

// A random dilute start. The disks of the first species have the reference diameter, those of
// the second `second_diameter` times it; the cell is sized so that the reference diameter is 1
// at packing fraction `sized_for_eta` (the target of the compression, if there is one), and the
// disks start smaller, at packing fraction `start_eta`.
struct PackingSpec {
  std::uint64_t n = 0;                     // >= 2
  double second_diameter = 1.0;            // > 0, relative to the first species
  double second_fraction = 0.0;            // in [0, 1]: round(F·N) disks are of the second species
  Boundary boundary = Boundary::periodic;  // periodic or box
  double aspect = 1.0;                     // the cell's height over its width, > 0
  double start_eta = 0.3;                  // in (0, 0.5]: random placement fills up to ≈ 0.547
  double sized_for_eta = 0.84;             // >= start_eta, < 1
  std::uint64_t seed = 1;
};

// The fraction of the plane inside the disks now: Σ π·r² over the cell's (or box's) area.
[[nodiscard]] double packing_fraction(const World& world);

// Disks placed one by one at uniform random places, each redrawn until it overlaps none placed
// before (random sequential addition; the larger species first), with Maxwell–Boltzmann
// velocities at kT = 1 (mass 1, zero total momentum, K/N = 1 exactly), all from
// std::mt19937_64(seed). Throws InvalidArgument naming the field for a spec out of range, and
// when the cell is too narrow for a periodic world (fewer than about three large disks across).
[[nodiscard]] World make_packing_world(const PackingSpec& spec);

struct CompressionSettings {
  // The speed at which the smallest disk's diameter grows, in units of the thermal speed
  // √(kT/m): finite, > 0. Slow compression (10⁻⁴) lets one-size disks crystallise; fast
  // compression (10⁻¹) jams them amorphous.
  double rate = 1e-2;
  // Stop at this packing fraction (> the world's now); 0: compress until jammed.
  double target_eta = 0.0;
  double kT = 1.0;  // the thermostat's temperature, finite and > 0
  // Jammed when the reduced pressure Z = PA/(NkT) measured over one window passes this (> 1).
  double pressure_limit = 1e12;
  // The thermostat scales the velocities back to kT after every window of this many collisions
  // (0: one a disk, N in all); the pressure is measured over each window.
  std::uint64_t window_collisions = 0;
  // Give up (jammed = false) after this many collisions in all; 0: no limit.
  std::uint64_t collision_limit = 0;
};

enum class CompressionEnd : std::uint8_t {
  target,           // the target packing fraction was reached
  pressure,         // jammed: the reduced pressure passed the limit
  stalled,          // jammed: a window of collisions no longer moves the world's time on
  collision_limit,  // the collision limit came first
  interrupted,      // the progress callback answered true, or World::request_stop
};

[[nodiscard]] std::string_view compression_end_name(CompressionEnd end) noexcept;

struct CompressionProgress {
  double eta = 0.0;       // the packing fraction now
  double pressure = 0.0;  // the reduced pressure of the last window (0 before the first)
  std::uint64_t collisions = 0;
  double time = 0.0;  // the world's
};

struct CompressionResult {
  CompressionEnd end = CompressionEnd::target;
  bool jammed = false;  // end is pressure or stalled
  double eta = 0.0;     // reached
  // Z = PA/(NkT) over the last window, from the collisional virial of ball–ball contacts:
  // PA = NkT + Σ σ_ij·J_ij / (2·Δt), kT the window's mean kinetic energy a disk.
  double pressure = 0.0;
  std::uint64_t collisions = 0;  // resolved by compress
  std::uint64_t windows = 0;     // thermostat steps
  double thermostat_work = 0.0;  // Σ of the thermostat's changes of kinetic energy (< 0)
  double time = 0.0;             // of the world at the end
};

// Compresses `world` (at least two balls, all movable, no gravity; a periodic cell or a box) as
// the settings say; the progress callback is called once a window and stops the run by answering
// true. On return growth is off (rate 0) and the velocities are at kT, so the world is a packing
// at rest in size, ready to be saved or run on. It measures the pressure through the world's stop
// condition and contact recording, so it leaves the world with no stop condition and recording as
// it found it. Throws InvalidArgument for settings out of range.
CompressionResult compress(World& world, const CompressionSettings& settings,
                           const std::function<bool(const CompressionProgress&)>& progress = {});

}  // namespace carom::science
