// Moving walls' cost: the box gas of box_gas.hpp (10⁴ disks, η = 0.3, equilibrated) with no
// moving wall, with 4 bars of length 10 turning about their middles at 1 rad a time unit (they
// stay where they are, so the gas around them stays alike for the whole run), or with 4 paddles
// of length 10 translating at 0.2. Every ball's prediction asks every moving wall. Items are
// collisions (with balls and walls), so the time an item is the cost a collision.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>

#include "box_gas.hpp"
#include "carom/world.hpp"

namespace carom::bench {
namespace {

constexpr std::uint64_t kMovingWallGasBalls = kEquilibratedGasBalls;

// walls: 0 none, 1 turning bars, 2 translating paddles, each on a fresh copy of the equilibrated
// gas; the walls placed where no ball is (balls in their way are removed).
World* moving_wall_gas(std::int64_t walls) {
  static std::int64_t cached_kind = -1;
  static std::unique_ptr<World> cached;
  if (cached && cached_kind == walls) return cached.get();
  cached = equilibrated_gas_copy();
  const double side = cached->def().upper.x;
  if (walls != 0) {
    for (int k = 0; k < 4; ++k) {
      const Vec2 middle{side * (0.25 + 0.5 * (k % 2)), side * (0.25 + 0.5 * (k / 2))};
      const Segment bar{middle - Vec2{5.0, 0.0}, middle + Vec2{5.0, 0.0}};
      // Clear the ground the bar sweeps (a disc of radius 5.5 about its middle).
      for (const BallId id : cached->balls_in_circle(middle, 6.0)) cached->remove_ball(id);
      const WallId wall = cached->add_segment(bar);
      cached->set_wall_motion(
          wall, walls == 1 ? WallMotion{{}, 1.0, middle} : WallMotion{{0.0, 0.2}, 0.0, middle});
    }
  }
  cached_kind = walls;
  return cached.get();
}

void BM_WorldMovingWallGas(benchmark::State& state) {
  World* world = moving_wall_gas(state.range(0));
  std::uint64_t collisions = 0;
  for (auto _ : state) collisions += world->run_collisions(kMovingWallGasBalls);
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
}
BENCHMARK(BM_WorldMovingWallGas)
    ->ArgName("walls")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace carom::bench
