// carom benchmarks: the cost of the hard-disk measurements (carom/science/gas_monitor.hpp)
// against the plain world on the same gas. Both advance the gas of `carom bench` by the same
// time, the time that 100 collisions per disk take; one runs World::run_until alone, the other
// measure_gas with the settings `carom gas` uses for that run (gas_monitor_settings: 16 blocks of
// 6 runs, a structure sample every 10 collisions per disk). items_per_second is collisions per
// (CPU) second in both; the ratio is the measurements' overhead. The figures: docs/performance.md.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "carom/science/gas_monitor.hpp"
#include "carom/science/hard_disk_gas.hpp"
#include "carom/world.hpp"

namespace carom::bench {
namespace {

constexpr std::uint64_t kSeed = 1;
constexpr std::uint64_t kEquilibrationPerDisk = 20;
constexpr double kCollisionsPerDiskPerIteration = 100.0;
constexpr std::uint64_t kBlocks = 16;

struct Gas {
  World world;
  double iteration_time = 0.0;  // the time kCollisionsPerDiskPerIteration take
  science::GasMonitorSettings settings;
};

Gas make_gas(std::uint64_t n, double eta) {
  const science::HardDiskLayout layout = science::hard_disk_layout(n, eta);
  Gas gas{science::make_hard_disk_world(layout, kSeed), 0.0, {}};
  const double rate = science::equilibrate(gas.world, kEquilibrationPerDisk * n);
  gas.iteration_time = 2.0 * kCollisionsPerDiskPerIteration / rate;
  gas.settings = science::gas_monitor_settings(kBlocks, kCollisionsPerDiskPerIteration, rate);
  return gas;
}

void BM_GasPlain(benchmark::State& state) {
  Gas gas = make_gas(static_cast<std::uint64_t>(state.range(0)),
                     static_cast<double>(state.range(1)) / 100.0);
  std::uint64_t collisions = 0;
  for (auto _ : state) {
    const std::uint64_t before = gas.world.collision_count();
    gas.world.run_until(gas.world.time() + gas.iteration_time);
    collisions += gas.world.collision_count() - before;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
}

void BM_GasMeasured(benchmark::State& state) {
  Gas gas = make_gas(static_cast<std::uint64_t>(state.range(0)),
                     static_cast<double>(state.range(1)) / 100.0);
  std::uint64_t collisions = 0;
  double z = 0.0;
  for (auto _ : state) {
    const science::GasResults results =
        science::measure_gas(gas.world, gas.iteration_time, gas.settings);
    collisions += results.collisions;
    z = results.z.mean;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
  state.counters["Z"] = z;
}

void sizes(benchmark::internal::Benchmark* registered) {
  registered->ArgNames({"n", "eta_percent"});
  for (const std::int64_t n : {1000, 10000}) {
    for (const std::int64_t eta : {30, 60}) registered->Args({n, eta});
  }
  registered->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_GasPlain)->Apply(sizes);
BENCHMARK(BM_GasMeasured)->Apply(sizes);

}  // namespace
}  // namespace carom::bench
