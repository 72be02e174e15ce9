// carom science: measurements on a gas of hard disks in a periodic box, taken while the world
// runs, each with a block-average error.
//
// measure_gas() drives a World through a production run of a given duration and
// measures, from the contacts the world reports and from its state between runs:
// - the pressure from the collisional virial and the compressibility factor Z = PA/(N·kT), with
//   kT = K/N (K the kinetic energy);
// - the collision rate per disk ω (each collision counts for both disks) and the mean free path;
// - the time-weighted speed distribution and ⟨v⁴⟩/⟨v²⟩²: each disk's speed is constant between
//   its contacts, so every interval between two contacts counts with its length;
// - g(r) of the reference disks (those of the first ball's radius; all of them in a one-size gas)
//   and its contact value, extrapolated from the first bins;
// - the bond-orientational order ψ₆ (global modulus, and the local values' histogram);
// - the mean-square displacement of unwrapped positions and the diffusion coefficient.
// Unwrapped positions are exact (to rounding): each disk's displacement is integrated from its
// velocity over every interval between its contacts, as the world itself moves it; no sampling
// and no minimum image is involved (docs/science.md says why sampling could not be exact).
//
// The run is cut into `blocks` blocks of equal collision counts; each block gives one value of
// each quantity, and the error is the blocks' standard error (block_average.hpp). Definitions,
// derivations and the exact results the values are tested against: docs/science.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "carom/science/block_average.hpp"
#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::science {

// The periodic cell the world was made with (World does not report it).
struct GasMonitorSettings {
  std::size_t blocks = 16;  // at least 2
  // Each block is advanced in this many equal runs of World::run_until (at least 2). After each
  // run every disk's interval is closed and the mean-square displacement sampled; after a
  // block's last run the disks' velocities are also taken from the world and their unwrapped
  // positions checked against it.
  std::size_t runs_per_block = 8;
  // Time between two samples of the structure (g(r) and ψ₆), rounded to whole runs (at least
  // one run); 0 samples after every run. A sample costs about as much as a few dozen collisions
  // per disk, so sampling every few collisions per disk keeps the measurements cheap, and
  // successive samples are correlated anyway. Samples fall on a grid of times fixed in advance,
  // never at a contact (a configuration taken at a contact has that pair at r = σ, which biases
  // g(σ); see docs/science.md).
  double structure_interval = 0.0;
  double rdf_range = 5.0;    // g(r) from σ out to this many σ (or half the cell, if less)
  double rdf_bin = 0.02;     // in σ
  double psi6_cutoff = 1.4;  // neighbours for ψ₆: centres closer than this many σ
  double speed_range = 5.0;  // the speed histogram covers [0, speed_range·√(kT/m))
  std::size_t speed_bins = 100;
  std::size_t psi6_bins = 20;  // of |ψ₆| over [0, 1]
};

// One curve: x values and y values, equal lengths.
struct Curve {
  std::vector<double> x;
  std::vector<double> y;
};

struct GasResults {
  std::size_t n = 0;
  double packing_fraction = 0.0;  // Σ π·r² / A
  double sigma = 0.0;             // the reference diameter
  double mass = 0.0;              // of the reference disks
  std::uint64_t collisions = 0;   // resolved in the production run
  double time = 0.0;              // duration of the production run
  // Whether the run was stopped from outside (World::request_stop or the world's progress
  // callback): the estimates and the MSD then cover the blocks completed, `blocks_done` of them;
  // the histograms, drifts and collisions cover the whole run up to the stop.
  bool interrupted = false;
  std::size_t blocks_done = 0;
  double kT = 0.0;  // K/N
  std::size_t structure_samples = 0;

  BlockEstimate z;
  BlockEstimate collision_rate;  // ω, per disk and unit time
  BlockEstimate mean_free_path;
  BlockEstimate moment_ratio;  // ⟨v⁴⟩/⟨v²⟩², time-weighted
  BlockEstimate g_contact;
  BlockEstimate psi6;       // ⟨|Σ ψ₆,j| / N⟩ over the structure samples
  BlockEstimate diffusion;  // from the slope of each block's MSD over its second half
  // (4/√π)(Z − 1) / (ω·σ·√(m/kT)); exact value rate_pressure_ratio_exact(n) for equal disks.
  BlockEstimate rate_pressure_ratio;

  double energy_drift = 0.0;    // (K_end − K_start) / K_start
  double momentum_drift = 0.0;  // |P_end − P_start| / √(2·M·K_start)
  // The largest distance, over every synchronisation, between a disk's unwrapped position
  // (wrapped into the cell) and the world's position of it: rounding only.
  double max_unwrap_error = 0.0;

  Curve rdf;         // r (centre of a bin, in length units), g(r)
  Curve speed;       // speed (bin centre), probability density
  Curve psi6_local;  // |ψ₆,j| (bin centre), probability density
  Curve msd;  // lag τ, ⟨|Δr|²⟩ averaged over blocks (time origin at each block's start)
  // The last structure sample: every disk's wrapped position, radius, and local ψ₆.
  std::vector<Vec2> final_positions;
  std::vector<double> final_radii;
  std::vector<double> final_psi6_modulus;
  std::vector<double> final_psi6_angle;  // arg ψ₆,j in (−π, π]; 0 where a disk has no neighbour
};

// Collisions per disk between two samples of the structure (g(r), ψ₆). A sample costs about as
// much as 20 to 40 collisions per disk at the default range of g(r); one every 10 collisions
// per disk keeps the measurements' cost within 15 % of the world's throughput
// (docs/performance.md).
inline constexpr double kStructureEveryCollisionsPerDisk = 10.0;

// Runs per block: at most this many (the MSD's resolution within a block) ...
inline constexpr double kMostRunsPerBlock = 8.0;
// ... and each run at least this many collisions per disk: after every run each disk's interval
// is closed (O(N)), which must stay small beside the run's own work.
inline constexpr double kLeastCollisionsPerDiskPerRun = 1.0;

// The monitor's settings for B blocks over K collisions per disk, at the collision rate ω per disk
// (K collisions per disk, K·N in all as in `carom bench`, take the time 2K/ω: ω counts each
// collision for both of its disks), as `carom gas` and the benchmark of the measurements' cost
// use them.
[[nodiscard]] inline GasMonitorSettings gas_monitor_settings(std::uint64_t blocks,
                                                             double collisions_per_disk,
                                                             double rate) {
  GasMonitorSettings settings;
  settings.blocks = static_cast<std::size_t>(blocks);
  const double per_block = collisions_per_disk / static_cast<double>(blocks);
  settings.runs_per_block = static_cast<std::size_t>(
      std::clamp(std::floor(per_block / kLeastCollisionsPerDiskPerRun), 2.0, kMostRunsPerBlock));
  settings.structure_interval = 2.0 * kStructureEveryCollisionsPerDisk / rate;
  return settings;
}

// Runs world for `duration` more time units and measures. The world must be periodic (its cell is
// world.def()'s), hold no walls, at least two balls, all movable; duration > 0. Throws
// carom::InvalidArgument otherwise. Blocks and runs are equal in time, so every average is a
// time average (the number of collisions per block varies a little). A run stopped from outside
// ends the measurement there (GasResults::interrupted).
[[nodiscard]] GasResults measure_gas(World& world, double duration,
                                     const GasMonitorSettings& settings = {});

// The time a production run of the given collisions per disk takes, near enough: a world first
// runs `collisions` (to equilibrate), then the collision rate per disk ω = 2C/(N·t) measured over
// them turns collisions per disk into time, 2·per_disk/ω. Fewer than N equilibration collisions
// would give a poor rate, so at least N are run. Returns ω; a run stopped from outside returns the
// rate seen so far (0 if no time passed), with world.stop_reason() == interrupted.
[[nodiscard]] double equilibrate(World& world, std::uint64_t collisions);

}  // namespace carom::science
