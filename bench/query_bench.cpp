// The world's queries on the periodic hard-disk gas of `carom bench` (η = 0.3, equilibrated): ray
// casts and ball casts ten diameters long and circle queries two diameters wide, from random
// places in random directions, at 10⁴ and 10⁵ disks. Items are queries, so items_per_second is
// queries a CPU second; the cost should not grow with the world (only the cells a query visits).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "carom/science/hard_disk_gas.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

constexpr std::uint64_t kQueryGasSeed = 1;
constexpr std::size_t kQueryPlaces = 4096;

struct QueryGas {
  std::unique_ptr<World> world;
  double diameter = 0.0;
  std::vector<Vec2> origins;
  std::vector<Vec2> directions;  // unit
};

const QueryGas& query_gas(std::uint64_t n) {
  static std::uint64_t cached_n = 0;
  static QueryGas cached;
  if (cached.world && cached_n == n) return cached;
  cached.world.reset();
  const science::HardDiskLayout layout = science::hard_disk_layout(n, 0.3);
  cached.world = std::make_unique<World>(science::make_hard_disk_world(layout, kQueryGasSeed));
  cached.world->run_collisions(2 * n);
  cached.diameter = 2.0 * cached.world->radius(cached.world->balls().front());
  const WorldDef& def = cached.world->def();
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  cached.origins.clear();
  cached.directions.clear();
  for (std::size_t k = 0; k < kQueryPlaces; ++k) {
    cached.origins.push_back({def.lower.x + (def.upper.x - def.lower.x) * unit(engine),
                              def.lower.y + (def.upper.y - def.lower.y) * unit(engine)});
    const double angle = 2.0 * std::numbers::pi * unit(engine);
    cached.directions.push_back({std::cos(angle), std::sin(angle)});
  }
  cached_n = n;
  return cached;
}

void BM_WorldCastRay(benchmark::State& state) {
  const QueryGas& gas = query_gas(static_cast<std::uint64_t>(state.range(0)));
  const double length = 10.0 * gas.diameter;
  std::size_t k = 0;
  std::uint64_t hits = 0;
  for (auto _ : state) {
    const QueryHit hit = gas.world->cast_ray(gas.origins[k], gas.directions[k] * length);
    hits += hit ? 1U : 0U;
    benchmark::DoNotOptimize(hit);
    k = (k + 1) % kQueryPlaces;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_share"] =
      static_cast<double>(hits) / std::max(static_cast<double>(state.iterations()), 1.0);
}
BENCHMARK(BM_WorldCastRay)->ArgName("n")->Arg(10'000)->Arg(100'000);

void BM_WorldCastBall(benchmark::State& state) {
  const QueryGas& gas = query_gas(static_cast<std::uint64_t>(state.range(0)));
  const double length = 10.0 * gas.diameter;
  std::size_t k = 0;
  for (auto _ : state) {
    const QueryHit hit =
        gas.world->cast_ball(gas.origins[k], 0.5 * gas.diameter, gas.directions[k] * length);
    benchmark::DoNotOptimize(hit);
    k = (k + 1) % kQueryPlaces;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WorldCastBall)->ArgName("n")->Arg(10'000)->Arg(100'000);

void BM_WorldBallsInCircle(benchmark::State& state) {
  const QueryGas& gas = query_gas(static_cast<std::uint64_t>(state.range(0)));
  std::size_t k = 0;
  for (auto _ : state) {
    const std::vector<BallId> found = gas.world->balls_in_circle(gas.origins[k], gas.diameter);
    benchmark::DoNotOptimize(found.data());
    k = (k + 1) % kQueryPlaces;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WorldBallsInCircle)->ArgName("n")->Arg(10'000)->Arg(100'000);

}  // namespace
}  // namespace carom
