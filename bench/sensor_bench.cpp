// Sensors' cost: the box gas of box_gas.hpp (10⁴ disks, η = 0.3, equilibrated) with none, or with
// 20 lines across the box (10 each way, evenly spaced: every disk crosses one every few
// collisions), or 400 small discs on a grid. Items are collisions, so the time an item is the
// cost a collision, sensor events included; sensor_events_per_collision says how many came with
// each.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>

#include "box_gas.hpp"
#include "carom/world.hpp"

namespace carom::bench {
namespace {

constexpr std::uint64_t kSensorGasBalls = kEquilibratedGasBalls;

// sensors: 0 none, 1 the lines, 2 the discs, each on a fresh copy of the equilibrated gas.
World* sensor_gas(std::int64_t sensors) {
  static std::int64_t cached_kind = -1;
  static std::unique_ptr<World> cached;
  if (cached && cached_kind == sensors) return cached.get();
  cached = equilibrated_gas_copy();
  const double side = cached->def().upper.x;
  constexpr int kLines = 10;
  constexpr int kDiscs = 20;
  if (sensors == 1) {
    for (int k = 1; k <= kLines; ++k) {
      const double at = side * k / (kLines + 1);
      cached->add_sensor(Segment{{at, 0.0}, {at, side}});
      cached->add_sensor(Segment{{0.0, at}, {side, at}});
    }
  } else if (sensors == 2) {
    for (int i = 0; i < kDiscs; ++i) {
      for (int j = 0; j < kDiscs; ++j) {
        cached->add_sensor(Ball{{side * (i + 0.5) / kDiscs, side * (j + 0.5) / kDiscs}, 0.5});
      }
    }
  }
  cached_kind = sensors;
  return cached.get();
}

void BM_WorldSensorGas(benchmark::State& state) {
  World* world = sensor_gas(state.range(0));
  std::uint64_t collisions = 0;
  std::uint64_t events = 0;
  for (auto _ : state) {
    collisions += world->run_collisions(kSensorGasBalls);
    events += world->sensor_events().size();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
  state.counters["sensor_events_per_collision"] =
      static_cast<double>(events) / static_cast<double>(collisions);
}
BENCHMARK(BM_WorldSensorGas)
    ->ArgName("sensors")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace carom::bench
