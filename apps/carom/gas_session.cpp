#include "gas_session.hpp"

#include <algorithm>
#include <chrono>

#include "wall_clock.hpp"

namespace carom::cli {

GasOutcome run_gas_session(const GasSpec& spec) {
  GasOutcome outcome;
  World world = make_hard_disk_world(spec.layout, spec.seed, spec.diameters);
  outcome.equilibration_collisions = std::max<std::uint64_t>(spec.equilibration_collisions, spec.n);
  outcome.equilibration_rate = science::equilibrate(world, spec.equilibration_collisions);
  const science::GasMonitorSettings settings =
      gas_monitor_settings(spec.blocks, spec.collisions_per_disk, outcome.equilibration_rate);
  const science::PeriodicCell cell{{0.0, 0.0}, {spec.layout.side, spec.layout.side}};
  const double duration = 2.0 * spec.collisions_per_disk / outcome.equilibration_rate;
  const auto start = std::chrono::steady_clock::now();
  outcome.results = science::measure_gas(world, cell, duration, settings);
  outcome.wall_seconds = seconds_since(start);
  return outcome;
}

}  // namespace carom::cli
