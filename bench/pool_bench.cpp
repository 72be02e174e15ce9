// Pool shots simulated to rest (World with a Table, docs/pool.md): a 16-ball break on a 9-foot
// table and a three-ball position shot (a cut with draw), each from the rack to every ball at
// rest, the world built afresh for every shot as a trainer or a search over shots does. The aim
// turns a little from shot to shot (a fixed sequence), so that the runs are not one shot over and
// over. Items are shots; the time an item is the time a shot takes.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>

#include "carom/world.hpp"

namespace carom::bench {
namespace {

constexpr double kRadius = 0.028575;  // m, a pool ball
constexpr double kMass = 0.17;        // kg
constexpr double kLength = 2.54;      // m, a 9-foot table's bed
constexpr double kWidth = 1.27;

World pool_table() {
  WorldDef def;
  def.boundary = Boundary::box;
  def.upper = {kLength, kWidth};
  def.restitution = 0.95;
  def.table = Table{};
  World world(def);
  // Six pockets: discs that remove the ball entering them.
  for (const Vec2 at :
       {Vec2{0.0, 0.0}, Vec2{0.5 * kLength, -0.02}, Vec2{kLength, 0.0}, Vec2{0.0, kWidth},
        Vec2{0.5 * kLength, kWidth + 0.02}, Vec2{kLength, kWidth}}) {
    world.add_sensor(Ball{at, 0.06}, SensorAction::remove_ball);
  }
  return world;
}

BallId add_pool_ball(World& world, Vec2 at) {
  BallDef ball;
  ball.position = at;
  ball.radius = kRadius;
  ball.mass = kMass;
  return world.add_ball(ball);
}

// Shot k's small turn of the aim, in [-1, 1], from a fixed sequence.
double aim_jitter(std::uint64_t k) { return std::sin(static_cast<double>(k) * 12.9898); }

std::uint64_t break_to_rest(std::uint64_t k) {
  World world = pool_table();
  const double spacing = 2.0 * kRadius + 1e-4;
  for (int row = 0; row < 5; ++row) {
    for (int place = 0; place <= row; ++place) {
      add_pool_ball(world, {0.75 * kLength + row * spacing * std::sqrt(3.0) / 2.0,
                            0.5 * kWidth + (place - 0.5 * row) * spacing});
    }
  }
  const BallId cue = add_pool_ball(world, {0.25 * kLength, 0.5 * kWidth});
  CueStrike strike;
  strike.speed = 5.0;
  strike.direction = 0.002 * aim_jitter(k);
  strike.height = 0.2 * kRadius;
  world.strike(cue, strike);
  return world.run_collisions(UINT64_MAX);
}

std::uint64_t position_shot_to_rest(std::uint64_t k) {
  World world = pool_table();
  const BallId cue = add_pool_ball(world, {0.8, 0.4});
  add_pool_ball(world, {1.6, 0.62});  // the object ball, cut towards the far corner
  add_pool_ball(world, {2.0, 0.9});   // a third ball in the way of position
  CueStrike strike;
  strike.speed = 2.5;
  strike.direction = std::atan2(0.62 - 0.4 - 0.5 * kRadius, 0.8) + 0.01 * aim_jitter(k);
  strike.height = -0.4 * kRadius;  // draw
  strike.side = 0.2 * kRadius;
  world.strike(cue, strike);
  return world.run_collisions(UINT64_MAX);
}

template <std::uint64_t (*Shot)(std::uint64_t)>
void BM_PoolShotToRest(benchmark::State& state) {
  std::uint64_t shot = 0;
  std::uint64_t contacts = 0;
  for (auto _ : state) contacts += Shot(shot++);
  state.SetItemsProcessed(static_cast<std::int64_t>(shot));
  state.counters["contacts_per_shot"] =
      static_cast<double>(contacts) / static_cast<double>(std::max<std::uint64_t>(shot, 1));
}
BENCHMARK(BM_PoolShotToRest<break_to_rest>)
    ->Name("BM_PoolBreakToRest")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PoolShotToRest<position_shot_to_rest>)
    ->Name("BM_PoolPositionShotToRest")
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace carom::bench
