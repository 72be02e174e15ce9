#include "gas/gas_session.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "carom/science/packing.hpp"
#include "system/stop_signals.hpp"
#include "system/wall_clock.hpp"

namespace carom::cli {
namespace {

// Makes world's runs stop when `stop` says so, telling `progress` (when given) beside it.
void stop_world_when(World& world, const GasStopAsked& stop,
                     std::function<void(const RunStatus&)> progress) {
  world.set_progress_callback([stop, progress = std::move(progress)](const RunStatus& status) {
    if (progress) progress(status);
    return stop();
  });
}

// The part of a session's progress bar a compressed start takes.
constexpr double kCompressionShare = 0.2;

// A random dilute start compressed to the spec's packing fraction; the compression's collisions
// count as the first part of the session's progress (a twentieth of it).
World compressed_start(const GasSpec& spec, const GasProgress& progress, const GasStopAsked& stop,
                       GasOutcome& outcome) {
  science::PackingSpec packing;
  packing.n = spec.n;
  packing.second_diameter = spec.second_diameter;
  packing.second_fraction = spec.second_fraction;
  packing.start_eta = std::min(kCompressStartEta, 0.5 * spec.eta);
  packing.sized_for_eta = spec.eta;
  packing.seed = spec.seed;
  World world = science::make_packing_world(packing);
  stop_world_when(world, stop, nullptr);
  science::CompressionSettings settings;
  settings.rate = kCompressStartRate;
  settings.target_eta = spec.eta;
  const auto start = std::chrono::steady_clock::now();
  const science::CompressionResult result =
      science::compress(world, settings, [&](const science::CompressionProgress& p) {
        if (progress) {
          progress(kCompressionShare * (p.eta - packing.start_eta) /
                   (spec.eta - packing.start_eta));
        }
        return stop();
      });
  outcome.compression_collisions = result.collisions;
  outcome.compression_seconds = seconds_since(start);
  if (result.end == science::CompressionEnd::interrupted) {
    outcome.interrupted = true;
    outcome.interrupted_equilibrating = true;
  } else if (result.end != science::CompressionEnd::target) {
    throw std::runtime_error("the compression jammed at packing fraction " +
                             std::to_string(result.eta) + ", below the target " +
                             std::to_string(spec.eta));
  }
  return world;
}

}  // namespace

GasOutcome run_gas_session(const GasSpec& spec, const GasProgress& progress,
                           const GasStopAsked& stop_asked) {
  const GasStopAsked stop = stop_asked ? stop_asked : GasStopAsked(&StopOnSignals::requested);
  GasOutcome outcome;
  const double base = spec.compress_start ? kCompressionShare : 0.0;
  const double rest = 1.0 - base;
  World world;
  if (spec.compress_start) {
    world = compressed_start(spec, progress, stop, outcome);
    if (outcome.interrupted) return outcome;
  } else {
    world = science::make_hard_disk_world(spec.layout, spec.seed, spec.diameters);
  }
  outcome.equilibration_collisions = std::max<std::uint64_t>(spec.equilibration_collisions, spec.n);
  // Progress counts collisions: the equilibration's, then the measured run's by its time.
  const auto equilibration = static_cast<double>(outcome.equilibration_collisions);
  const double measured = spec.collisions_per_disk * static_cast<double>(spec.n);
  const double total = equilibration + measured;
  stop_world_when(world, stop, [&](const RunStatus& status) {
    if (progress) progress(base + rest * static_cast<double>(status.contacts) / total);
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
  stop_world_when(world, stop, [&](const RunStatus& status) {
    if (progress)
      progress(base +
               rest * (equilibration + measured * (status.time - start_time) / duration) / total);
  });
  const auto start = std::chrono::steady_clock::now();
  outcome.results = science::measure_gas(world, duration, settings);
  outcome.wall_seconds = seconds_since(start);
  outcome.interrupted = outcome.results.interrupted;
  return outcome;
}

}  // namespace carom::cli
