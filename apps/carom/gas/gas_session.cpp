#include "gas/gas_session.hpp"

#include <algorithm>
#include <chrono>

#include "system/stop_signals.hpp"
#include "system/wall_clock.hpp"

namespace carom::cli {

GasOutcome run_gas_session(const GasSpec& spec, const GasProgress& progress) {
  GasOutcome outcome;
  World world = science::make_hard_disk_world(spec.layout, spec.seed, spec.diameters);
  outcome.equilibration_collisions = std::max<std::uint64_t>(spec.equilibration_collisions, spec.n);
  // Progress counts collisions: the equilibration's, then the measured run's by its time.
  const auto equilibration = static_cast<double>(outcome.equilibration_collisions);
  const double measured = spec.collisions_per_disk * static_cast<double>(spec.n);
  const double total = equilibration + measured;
  stop_world_on_signals(world, [&](const RunStatus& status) {
    if (progress) progress(static_cast<double>(status.contacts) / total);
  });
  outcome.equilibration_rate = science::equilibrate(world, spec.equilibration_collisions);
  if (world.stop_reason() == StopReason::interrupted) {
    outcome.interrupted = true;
    outcome.interrupted_equilibrating = true;
    return outcome;
  }
  const science::GasMonitorSettings settings = science::gas_monitor_settings(
      spec.blocks, spec.collisions_per_disk, outcome.equilibration_rate);
  const double duration = 2.0 * spec.collisions_per_disk / outcome.equilibration_rate;
  const double start_time = world.time();
  stop_world_on_signals(world, [&](const RunStatus& status) {
    if (progress)
      progress((equilibration + measured * (status.time - start_time) / duration) / total);
  });
  const auto start = std::chrono::steady_clock::now();
  outcome.results = science::measure_gas(world, duration, settings);
  outcome.wall_seconds = seconds_since(start);
  outcome.interrupted = outcome.results.interrupted;
  return outcome;
}

}  // namespace carom::cli
