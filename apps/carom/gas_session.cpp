#include "gas_session.hpp"

#include <algorithm>
#include <chrono>

namespace carom::cli {

GasOutcome run_gas_session(const GasSpec& spec) {
  GasOutcome outcome;
  World world = make_hard_disk_world(spec.layout, spec.seed, spec.diameters);
  outcome.equilibration_collisions = std::max<std::uint64_t>(spec.equilibration_collisions, spec.n);
  outcome.equilibration_rate = science::equilibrate(world, spec.equilibration_collisions);
  science::GasMonitorSettings settings;
  settings.blocks = spec.blocks;
  // K collisions per disk (K·N in all, as in `carom bench`) take the time 2K/ω: ω counts each
  // collision for both of its disks, so N disks see ω·N·t/2 collisions in time t.
  const auto time_of = [&](double per_disk) { return 2.0 * per_disk / outcome.equilibration_rate; };
  settings.structure_interval = time_of(kStructureEveryCollisionsPerDisk);
  const science::PeriodicCell cell{{0.0, 0.0}, {spec.layout.side, spec.layout.side}};
  const auto start = std::chrono::steady_clock::now();
  outcome.results = science::measure_gas(world, cell, time_of(spec.collisions_per_disk), settings);
  outcome.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace carom::cli
