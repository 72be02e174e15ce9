// carom_world_soak: the soak test (make soak; not in CI, minutes long). The hard-disk
// gas of `carom bench` (carom/science/hard_disk_gas.hpp: equal elastic disks in a periodic box)
// runs 10⁸ collisions in chunks of 10⁶; after every chunk it checks
// - World::audit: no overlap beyond 10⁻⁹ of the sum of radii (its default), every ball in the
//   grid cell it is filed in;
// - energy drift |K − K₀| / K₀ ≤ 10⁻¹⁰ (the world's conservation bound, docs/guarantees.md);
// - momentum drift |P − P₀| / Σ m·|v| ≤ 10⁻¹² (likewise). Relative to Σ m·|v|, not to
//   |P₀|: the gas starts with zero total momentum (|P₀| is itself rounding), so a drift relative
//   to it means nothing; Σ m·|v| is the scale of the terms whose rounding makes the drift, the
//   measure tests/world/world_conservation_tests.cpp uses too;
// - memory: the world allocates everything it needs at setup (contact recording is off), so peak
//   resident memory after the last chunk must not exceed that after the first by more than
//   kMemoryGrowthAllowedKiB.
// It prints one row per chunk and exits 1 on any violation (2 on bad arguments).
//   carom_world_soak [N=10000] [ETA=0.6] [COLLISIONS=1e8] [CHUNK=1e6] [SEED=1]
// It lives beside world_gas_probe (same scene, library alone) rather than in tests/: it is a
// long measurement to run by hand or from make soak, with figures for docs/guarantees.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "carom/science/hard_disk_gas.hpp"

namespace {

constexpr double kEnergyBound = 1e-10;
constexpr double kMomentumBound = 1e-12;
// Peak resident memory may grow by this much after the first chunk: allocator noise and buffers
// that settle in the first chunks (a first run measured +384 KiB, all of it in chunk 2, then
// flat for 98 chunks). A leak of one byte per collision would add ~100 MB over 10⁸ collisions.
constexpr long kMemoryGrowthAllowedKiB = 1024;

// A field of /proc/self/status in KiB: VmRSS (resident now) or VmHWM (the peak, "high water
// mark"). Both from one source, so the two columns compare.
long status_kib(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field + ":", 0) == 0) return std::atol(line.c_str() + field.size() + 1);
  }
  return -1;
}

long peak_resident_kib() { return status_kib("VmHWM"); }
long resident_kib() { return status_kib("VmRSS"); }

double sum_of_momentum_magnitudes(const carom::World& world) {
  double sum = 0.0;
  for (const carom::BallId id : world.balls()) sum += world.mass(id) * length(world.velocity(id));
  return sum;
}

double parse(const char* text, const char* name) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value > 0.0) || !std::isfinite(value)) {
    std::fprintf(stderr, "carom_world_soak: %s = %s: must be a finite number > 0\n", name, text);
    std::exit(2);
  }
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  const auto n = static_cast<std::uint64_t>(argc > 1 ? parse(argv[1], "N") : 1e4);
  const double eta = argc > 2 ? parse(argv[2], "ETA") : 0.6;
  const auto total = static_cast<std::uint64_t>(argc > 3 ? parse(argv[3], "COLLISIONS") : 1e8);
  const auto chunk = static_cast<std::uint64_t>(argc > 4 ? parse(argv[4], "CHUNK") : 1e6);
  const auto seed = static_cast<std::uint64_t>(argc > 5 ? parse(argv[5], "SEED") : 1);
  const carom::science::HardDiskLayout layout = carom::science::hard_disk_layout(n, eta);
  if (n == 0 || chunk == 0 || !layout.box_wide_enough() || !layout.disks_fit()) {
    std::fprintf(stderr, "carom_world_soak: the lattice cannot hold %llu disks at packing %g\n",
                 static_cast<unsigned long long>(n), eta);
    return 2;
  }
  carom::World world = carom::science::make_hard_disk_world(layout, seed);
  world.set_contact_recording(false);
  const double energy0 = world.kinetic_energy();
  const carom::Vec2 momentum0 = world.momentum();
  const long setup_peak = peak_resident_kib();
  std::printf("carom_world_soak: N = %llu, packing %.2f, %llu collisions in chunks of %llu\n",
              static_cast<unsigned long long>(n), eta, static_cast<unsigned long long>(total),
              static_cast<unsigned long long>(chunk));
  std::printf(
      "bounds: energy %.0e of K0, momentum %.0e of sum m|v|, audit tolerance 1e-9, "
      "peak RSS growth after chunk 1 <= %ld KiB\n",
      kEnergyBound, kMomentumBound, kMemoryGrowthAllowedKiB);
  std::printf("peak RSS after setup: %ld KiB\n", setup_peak);
  std::printf("%6s %12s %12s %10s %10s %9s %9s %10s %7s\n", "chunk", "collisions", "time", "dE/K0",
              "dP/sum", "RSS KiB", "peak KiB", "rate k/s", "audit");
  const auto start = std::chrono::steady_clock::now();
  std::uint64_t done = 0;
  long first_chunk_peak = 0;
  double worst_energy = 0.0;
  double worst_momentum = 0.0;
  int violations = 0;
  for (std::uint64_t k = 1; done < total; ++k) {
    const auto chunk_start = std::chrono::steady_clock::now();
    const std::uint64_t got = world.run_collisions(std::min(chunk, total - done));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - chunk_start).count();
    done += got;
    const auto audit = world.audit();
    const double energy_drift = std::abs(world.kinetic_energy() - energy0) / energy0;
    const double momentum_drift =
        length(world.momentum() - momentum0) / sum_of_momentum_magnitudes(world);
    const long peak = peak_resident_kib();
    if (k == 1) first_chunk_peak = peak;
    worst_energy = std::max(worst_energy, energy_drift);
    worst_momentum = std::max(worst_momentum, momentum_drift);
    const bool bad =
        audit || energy_drift > kEnergyBound || momentum_drift > kMomentumBound || got == 0;
    std::printf("%6llu %12llu %12.6g %10.2e %10.2e %9ld %9ld %10.0f %7s\n",
                static_cast<unsigned long long>(k), static_cast<unsigned long long>(done),
                world.time(), energy_drift, momentum_drift, resident_kib(), peak,
                static_cast<double>(got) / seconds / 1e3, audit ? "FAIL" : "ok");
    if (audit) std::printf("  audit: %s\n", audit->c_str());
    if (got == 0) std::printf("  run_collisions resolved no collision\n");
    std::fflush(stdout);
    if (bad) ++violations;
  }
  const long end_peak = peak_resident_kib();
  const long growth = end_peak - first_chunk_peak;
  if (growth > kMemoryGrowthAllowedKiB) ++violations;
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "peak RSS: %ld KiB after setup, %ld KiB after chunk 1, %ld KiB at the end (%+ld KiB)\n",
      setup_peak, first_chunk_peak, end_peak, growth);
  std::printf("worst drift: energy %.2e (bound %.0e), momentum %.2e (bound %.0e)\n", worst_energy,
              kEnergyBound, worst_momentum, kMomentumBound);
  std::printf("%llu collisions in %.1f s (%.0fk/s); %s\n", static_cast<unsigned long long>(done),
              wall, static_cast<double>(done) / wall / 1e3,
              violations == 0 ? "no violation" : "VIOLATIONS");
  return violations == 0 ? 0 : 1;
}
