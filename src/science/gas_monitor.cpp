#include "carom/science/gas_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "disk_motion.hpp"
#include "structure_sampler.hpp"

namespace carom::science {
namespace {

constexpr const char* kFunction = "carom::science::measure_gas";
// Runs per block, at least: each block's MSD needs a sample at its middle and at its end.
constexpr std::uint64_t kFewestRunsPerBlock = 2;

void require(bool ok, const std::string& argument, const std::string& value,
             const std::string& requirement) {
  if (!ok) throw InvalidArgument(kFunction, argument, value, requirement);
}

// The values of one block, from which each estimate's mean and error are formed.
struct BlockSeries {
  std::vector<double> z, rate, free_path, moment_ratio, g_contact, psi6, diffusion, rate_pressure;
};

std::vector<double> finite_only(const std::vector<double>& values) {
  std::vector<double> kept;
  for (const double value : values) {
    if (std::isfinite(value)) kept.push_back(value);
  }
  return kept;
}

}  // namespace

GasResults measure_gas(World& world, double duration, const GasMonitorSettings& settings) {
  const std::vector<BallId> ids = world.balls();
  const std::size_t n = ids.size();
  require(n >= 2, "world", std::to_string(n) + " balls", "at least 2 balls");
  require(world.wall_count() == 0, "world", std::to_string(world.wall_count()) + " walls",
          "no walls (the pressure is measured from ball-ball collisions only)");
  require(world.def().boundary == Boundary::periodic, "world", "not periodic",
          "a periodic cell (the measurements assume no walls and wrap distances)");
  const PeriodicCell cell(world.def().lower, world.def().upper);
  require(settings.blocks >= 2, "settings.blocks", std::to_string(settings.blocks),
          "at least 2 blocks for an error estimate");
  require(settings.runs_per_block >= kFewestRunsPerBlock, "settings.runs_per_block",
          std::to_string(settings.runs_per_block), "at least 2 runs per block");
  require(std::isfinite(duration) && duration > 0.0, "duration", std::to_string(duration),
          "a finite time > 0");
  require(std::isfinite(settings.structure_interval) && settings.structure_interval >= 0.0,
          "settings.structure_interval", std::to_string(settings.structure_interval),
          "a finite time >= 0");
  const std::size_t blocks = settings.blocks;
  const std::size_t runs_per_block = settings.runs_per_block;
  for (const BallId id : ids) {
    require(std::isfinite(world.mass(id)), "world", "an immovable ball", "movable balls only");
  }

  GasResults results;
  results.n = n;
  const Vec2 side = cell.period();
  const double area = side.x * side.y;
  double covered = 0.0;
  std::vector<double> radius(n);
  std::vector<bool> reference(n);
  std::uint32_t largest_slot = 0;
  for (const BallId id : ids) largest_slot = std::max(largest_slot, id.index);
  std::vector<double> radius_of_slot(static_cast<std::size_t>(largest_slot) + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    radius[i] = world.radius(ids[i]);
    radius_of_slot[ids[i].index] = radius[i];
    covered += std::numbers::pi * radius[i] * radius[i];
    reference[i] = radius[i] == radius[0];
  }
  const bool one_size = std::all_of(reference.begin(), reference.end(), [](bool r) { return r; });
  results.packing_fraction = covered / area;
  results.sigma = 2.0 * radius[0];
  results.mass = world.mass(ids[0]);
  const double energy = world.kinetic_energy();
  const Vec2 momentum = world.momentum();
  results.kT = energy / static_cast<double>(n);
  double total_mass = 0.0;
  for (const BallId id : ids) total_mass += world.mass(id);

  const double thermal_speed = std::sqrt(results.kT / results.mass);
  const double speed_bin =
      settings.speed_range * thermal_speed / static_cast<double>(settings.speed_bins);
  DiskMotion motion(world, ids, cell, speed_bin, settings.speed_bins);
  StructureSettings structure_settings;
  structure_settings.cell = cell;
  structure_settings.sigma = results.sigma;
  structure_settings.rdf_range = settings.rdf_range;
  structure_settings.rdf_bin = settings.rdf_bin;
  structure_settings.psi6_cutoff = settings.psi6_cutoff;
  structure_settings.psi6_bins = settings.psi6_bins;
  StructureSampler structure(structure_settings, reference);

  const auto count = static_cast<double>(n);
  const double run_time = duration / static_cast<double>(blocks * runs_per_block);
  // Whole runs between structure samples (at least one); the count, not the time, is compared
  // below, so rounding cannot skip a sample.
  const auto structure_every =
      static_cast<std::size_t>(std::max(1.0, std::round(settings.structure_interval / run_time)));

  BlockSeries series;
  std::vector<double> msd_lag(runs_per_block, 0.0);
  std::vector<double> msd_sum(runs_per_block, 0.0);
  std::vector<Vec2> origin;
  std::vector<Vec2> positions(n);
  const double start_time = world.time();
  std::size_t since_structure = 0;
  std::uint64_t collisions = 0;
  bool interrupted = false;
  std::size_t blocks_done = 0;
  for (std::size_t block = 0; block < blocks && !interrupted; ++block) {
    std::uint64_t block_collisions = 0;
    const double block_start = world.time();
    origin.assign(motion.displacements().begin(), motion.displacements().end());
    double virial = 0.0;  // Σ r_ij·Δp_i over the block's collisions
    std::vector<double> block_msd(runs_per_block);
    std::vector<double> block_lag(runs_per_block);
    for (std::size_t run = 0; run < runs_per_block; ++run) {
      // The run's end as a multiple of run_time from the start, so rounding does not accumulate.
      const double end =
          start_time + run_time * static_cast<double>(block * runs_per_block + run + 1);
      world.run_until(end);
      if (world.stopped_early()) {
        throw std::runtime_error("carom::science::measure_gas: the world's stop condition fired");
      }
      interrupted = world.stop_reason() == StopReason::interrupted;
      block_collisions += world.contacts().size();
      for (const ContactEvent& contact : world.contacts()) {
        // r_ij = −σ_ij·n and Δp_i = −J·n, so r_ij·Δp_i = σ_ij·J (docs/science.md).
        virial +=
            contact.impulse * (radius_of_slot[contact.a.index] + radius_of_slot[contact.b.index]);
        motion.on_contact(contact);
      }
      if (interrupted) {
        // The contacts so far count (histograms, drifts); the unfinished block does not.
        motion.advance(world.time());
        collisions += block_collisions;
        break;
      }
      if (run + 1 == runs_per_block) {
        motion.synchronise(world);
      } else {
        motion.advance(world.time());
      }
      double squares = 0.0;
      const std::span<const Vec2> moved = motion.displacements();
      for (std::size_t i = 0; i < n; ++i) squares += length_squared(moved[i] - origin[i]);
      block_msd[run] = squares / count;
      block_lag[run] = world.time() - block_start;
      if (++since_structure >= structure_every) {
        since_structure = 0;
        for (std::size_t i = 0; i < n; ++i) positions[i] = world.position(ids[i]);
        structure.sample(positions);
      }
    }
    if (interrupted) break;
    ++blocks_done;
    const double block_time = world.time() - block_start;
    const SpeedIntegrals speeds = motion.take_integrals();
    const double z = 1.0 + virial / (2.0 * block_time * energy);
    const double rate = 2.0 * static_cast<double>(block_collisions) / (count * block_time);
    series.z.push_back(z);
    series.rate.push_back(rate);
    series.free_path.push_back(speeds.speed / (2.0 * static_cast<double>(block_collisions)));
    series.moment_ratio.push_back(speeds.speed4 * count * block_time /
                                  (speeds.speed2 * speeds.speed2));
    series.rate_pressure.push_back(4.0 / std::sqrt(std::numbers::pi) * (z - 1.0) /
                                   (rate * results.sigma * std::sqrt(results.mass / results.kT)));
    // The slope of the MSD between the middle of the block and its end.
    const std::size_t middle = (runs_per_block - 1) / 2;
    const std::size_t last = runs_per_block - 1;
    series.diffusion.push_back((block_msd[last] - block_msd[middle]) /
                               (4.0 * (block_lag[last] - block_lag[middle])));
    collisions += block_collisions;
    for (std::size_t run = 0; run < runs_per_block; ++run) {
      msd_lag[run] += block_lag[run];
      msd_sum[run] += block_msd[run];
    }
    const StructureSampler::BlockValues values = structure.end_block();
    series.g_contact.push_back(values.g_contact);
    series.psi6.push_back(values.psi6);
  }

  results.collisions = collisions;
  results.time = world.time() - start_time;
  results.interrupted = interrupted;
  results.blocks_done = blocks_done;
  results.structure_samples = structure.samples();
  results.z = block_estimate(series.z);
  results.collision_rate = block_estimate(series.rate);
  results.mean_free_path = block_estimate(series.free_path);
  results.moment_ratio = block_estimate(series.moment_ratio);
  results.diffusion = block_estimate(series.diffusion);
  if (one_size) results.rate_pressure_ratio = block_estimate(series.rate_pressure);
  // Blocks without a structure sample (a short run) have no g(r) or ψ₆ of their own.
  results.g_contact = block_estimate(finite_only(series.g_contact));
  results.psi6 = block_estimate(finite_only(series.psi6));

  results.energy_drift = (world.kinetic_energy() - energy) / energy;
  results.momentum_drift =
      length(world.momentum() - momentum) / std::sqrt(2.0 * total_mass * energy);
  results.max_unwrap_error = motion.max_unwrap_error();

  structure.rdf(results.rdf.x, results.rdf.y);
  structure.psi6_local_density(results.psi6_local.x, results.psi6_local.y);
  const std::vector<double>& histogram = motion.speed_histogram();
  const double disk_time = count * results.time;
  for (std::size_t bin = 0; bin + 1 < histogram.size(); ++bin) {
    results.speed.x.push_back((static_cast<double>(bin) + 0.5) * speed_bin);
    results.speed.y.push_back(histogram[bin] / (disk_time * speed_bin));
  }
  for (std::size_t run = 0; run < runs_per_block && blocks_done > 0; ++run) {
    results.msd.x.push_back(msd_lag[run] / static_cast<double>(blocks_done));
    results.msd.y.push_back(msd_sum[run] / static_cast<double>(blocks_done));
  }
  if (structure.samples() > 0) {
    results.final_positions = positions;
    results.final_radii = radius;
    for (const std::complex<double>& psi : structure.last_psi6()) {
      results.final_psi6_modulus.push_back(std::abs(psi));
      results.final_psi6_angle.push_back(std::arg(psi));
    }
  }
  return results;
}

double equilibrate(World& world, std::uint64_t collisions) {
  const std::size_t n = world.ball_count();
  require(n >= 2, "world", std::to_string(n) + " balls", "at least 2 balls");
  const std::uint64_t run = std::max<std::uint64_t>(collisions, n);
  const double start = world.time();
  const std::uint64_t done = world.run_collisions(run);
  const double elapsed = world.time() - start;
  if (world.stop_reason() == StopReason::interrupted) {
    return elapsed > 0.0 ? 2.0 * static_cast<double>(done) / (static_cast<double>(n) * elapsed)
                         : 0.0;
  }
  if (done != run || !(elapsed > 0.0)) {
    throw std::runtime_error("carom::science::equilibrate: the world resolved " +
                             std::to_string(done) + " of " + std::to_string(run) +
                             " collisions in time " + std::to_string(elapsed));
  }
  return 2.0 * static_cast<double>(done) / (static_cast<double>(n) * elapsed);
}

}  // namespace carom::science
