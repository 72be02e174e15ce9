// carom tool: one measured run of a hard-disk gas, as `carom gas` and each point of `carom eos`
// make it: build the gas, equilibrate, measure (carom/science/gas_monitor.hpp), time it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "carom/science/gas_monitor.hpp"
#include "gas_options.hpp"

namespace carom::cli {

// Collisions per disk between two samples of the structure (g(r), ψ₆). A sample costs about as
// much as 20 to 40 collisions per disk at the default range of g(r); one every 10 collisions
// per disk keeps the measurements within the 15 % of the world's throughput that docs/
// performance.md measures ("Hard-disk science").
inline constexpr double kStructureEveryCollisionsPerDisk = 10.0;

// Runs per block: at most this many (the MSD's resolution within a block) ...
inline constexpr double kMostRunsPerBlock = 8.0;
// ... and each run at least this many collisions per disk: after every run each disk's interval
// is closed (O(N)), which must stay small beside the run's own work.
inline constexpr double kLeastCollisionsPerDiskPerRun = 1.0;

// The monitor's settings for B blocks over K collisions per disk, at the collision rate ω per disk
// (K collisions per disk, K·N in all as in `carom bench`, take the time 2K/ω: ω counts each
// collision for both of its disks). The benchmark of the measurements' cost uses the same.
[[nodiscard]] inline science::GasMonitorSettings gas_monitor_settings(std::uint64_t blocks,
                                                                      double collisions_per_disk,
                                                                      double rate) {
  science::GasMonitorSettings settings;
  settings.blocks = blocks;
  const double per_block = collisions_per_disk / static_cast<double>(blocks);
  settings.runs_per_block = static_cast<std::size_t>(
      std::clamp(std::floor(per_block / kLeastCollisionsPerDiskPerRun), 2.0, kMostRunsPerBlock));
  settings.structure_interval = 2.0 * kStructureEveryCollisionsPerDisk / rate;
  return settings;
}

struct GasOutcome {
  science::GasResults results;
  std::uint64_t equilibration_collisions = 0;  // resolved (at least one per disk)
  double equilibration_rate = 0.0;             // ω seen while equilibrating
  double wall_seconds = 0.0;                   // of the production run, measurements included
  // Stopped by a signal: during equilibration (nothing measured), or during the measurement
  // (results.interrupted: estimates over the blocks completed, maybe none).
  bool interrupted = false;
  bool interrupted_equilibrating = false;
  // Whether there are estimates to report: a block at least was completed.
  [[nodiscard]] bool measured() const { return !interrupted || results.blocks_done > 0; }
};

// Told now and then (every few thousand events) how far a session has got, from 0 to 1.
using GasProgress = std::function<void(double fraction)>;

// Runs the session; a signal (StopOnSignals) stops it within a few thousand events.
[[nodiscard]] GasOutcome run_gas_session(const GasSpec& spec, const GasProgress& progress = {});

}  // namespace carom::cli
