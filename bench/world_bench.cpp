// carom benchmarks: the event-driven world (carom::World).
// - BM_WorldHardDisks: collisions per second in a gas of equal hard disks in a periodic box, the
//   scene of `carom bench` (carom/science/hard_disk_gas.hpp), at N = 10⁴ and 10⁵ and packing
//   fractions 0.3 and 0.6. N = 10⁶ takes minutes (its setup alone is about 15 s), so it is
//   registered only when the environment variable CAROM_BENCH_WORLD_LARGE is set (to anything).
// - BM_WorldGasInABox: the same disks, elastic, in a closed box, with and without gravity (a
//   scale height kT/(m·g) of half the box's side): what gravity's parabolas cost a collision.
// - BM_WorldGrowingGas: the periodic gas of BM_WorldHardDisks at 10⁴ and η = 0.3, its radii
//   growing slowly (or not): what growth costs a collision.
// - BM_WorldGameStep: a game's frame, 10⁴ balls of mixed sizes in a closed box stepped at 60
//   steps per second; the mean step time and the worst.
// - BM_WorldGameDragStep: the same with the player dragging one ball every frame (set_position
//   with nearest_free, then set_velocity): the cost of a change between steps.
// - BM_WorldGameWallStep: the same with the player drawing a short wall every frame.
// The figures and what they mean: docs/performance.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "box_gas.hpp"
#include "carom/science/hard_disk_gas.hpp"
#include "carom/world.hpp"

namespace carom::bench {
namespace {

// ---- the hard-disk gas ----------------------------------------------------------------------

constexpr std::uint64_t kGasSeed = 1;  // as `carom bench`'s default
// Untimed collisions per disk before timing, as `carom bench`'s default: the lattice melts, and
// the grid's rebuild and the first prediction of every ball are done.
constexpr std::uint64_t kEquilibrationPerBall = 2;

// The last gas benchmarked, kept so that Google Benchmark's several calls of one benchmark (to
// choose the iteration count, and per repetition) set it up once. It keeps running from where it
// was: an equilibrated gas stays equilibrated.
struct CachedGas {
  std::uint64_t n = 0;
  std::int64_t eta_percent = 0;
  std::unique_ptr<World> world;
};

World* gas(std::uint64_t n, std::int64_t eta_percent) {
  static CachedGas cached;
  if (cached.world && cached.n == n && cached.eta_percent == eta_percent) {
    return cached.world.get();
  }
  cached.world.reset();  // free the old one before building the new
  const science::HardDiskLayout layout =
      science::hard_disk_layout(n, static_cast<double>(eta_percent) / 100.0);
  if (!layout.box_wide_enough() || !layout.disks_fit()) return nullptr;
  cached.world = std::make_unique<World>(science::make_hard_disk_world(layout, kGasSeed));
  cached.world->run_collisions(kEquilibrationPerBall * n);
  cached.n = n;
  cached.eta_percent = eta_percent;
  return cached.world.get();
}

// One iteration resolves N collisions (one per disk); items are collisions, so items_per_second
// is collisions per (CPU) second. energy_drift: the relative change of the kinetic energy over
// the timed iterations of this run.
void BM_WorldHardDisks(benchmark::State& state) {
  const auto n = static_cast<std::uint64_t>(state.range(0));
  World* world = gas(n, state.range(1));
  if (world == nullptr) {
    state.SkipWithError("the triangular lattice cannot hold this gas");
    return;
  }
  const double energy_before = world->kinetic_energy();
  std::uint64_t collisions = 0;
  for (auto _ : state) {
    collisions += world->run_collisions(n);
  }
  if (collisions != n * static_cast<std::uint64_t>(state.iterations())) {
    state.SkipWithError("the world resolved fewer collisions than asked for");
    return;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
  state.counters["energy_drift"] = (world->kinetic_energy() - energy_before) / energy_before;
}

void gas_sizes(benchmark::internal::Benchmark* registered) {
  registered->ArgNames({"n", "eta_percent"});
  for (const std::int64_t eta_percent : {30, 60}) {
    for (const std::int64_t n : {10'000, 100'000}) registered->Args({n, eta_percent});
    if (std::getenv("CAROM_BENCH_WORLD_LARGE") != nullptr) {
      registered->Args({1'000'000, eta_percent});
    }
  }
}
BENCHMARK(BM_WorldHardDisks)->Apply(gas_sizes)->Unit(benchmark::kMillisecond);

// ---- a gas under gravity -------------------------------------------------------------------

// The box gas of box_gas.hpp, equilibrated, with gravity and without (the pair's two halves).
struct CachedBoxGas {
  std::int64_t key = -1;
  std::unique_ptr<World> world;
};

World* box_gas(std::uint64_t n, std::int64_t eta_percent, bool gravity) {
  static CachedBoxGas cached;
  const std::int64_t key =
      static_cast<std::int64_t>(n) * 1000 + eta_percent * 10 + (gravity ? 1 : 0);
  if (cached.world && cached.key == key) return cached.world.get();
  cached.world = make_box_gas(n, static_cast<double>(eta_percent) / 100.0, gravity);
  if (!cached.world) return nullptr;
  cached.world->run_collisions(kEquilibrationPerBall * n);
  cached.key = key;
  return cached.world.get();
}

// One iteration resolves N collisions; items are collisions. energy_drift: the relative change
// of the total energy (kinetic and potential) over the timed iterations.
void BM_WorldGasInABox(benchmark::State& state) {
  const auto n = static_cast<std::uint64_t>(state.range(0));
  World* world = box_gas(n, state.range(1), state.range(2) != 0);
  if (world == nullptr) {
    state.SkipWithError("the lattice cannot hold this gas");
    return;
  }
  const double energy_before = world->kinetic_energy() + world->potential_energy();
  std::uint64_t collisions = 0;
  for (auto _ : state) collisions += world->run_collisions(n);
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
  state.counters["energy_drift"] =
      (world->kinetic_energy() + world->potential_energy() - energy_before) / energy_before;
}
BENCHMARK(BM_WorldGasInABox)
    ->ArgNames({"n", "eta_percent", "gravity"})
    ->Args({10'000, 2, 0})
    ->Args({10'000, 2, 1})
    ->Args({10'000, 35, 0})
    ->Args({10'000, 35, 1})
    ->Unit(benchmark::kMillisecond);

// The gas of `carom bench` (10⁴ disks, η = 0.3), with growth at 10⁻⁴ of the radii a time unit
// (η rises by about 10⁻³ over a run) or none; a fresh gas for each run. Items are collisions.
void BM_WorldGrowingGas(benchmark::State& state) {
  const bool growing = state.range(0) != 0;
  const science::HardDiskLayout layout = science::hard_disk_layout(10'000, 0.3);
  World world = science::make_hard_disk_world(layout, kGasSeed);
  world.set_contact_recording(false);
  world.run_collisions(kEquilibrationPerBall * 10'000);
  if (growing) world.set_growth_rate(1e-4);
  std::uint64_t collisions = 0;
  for (auto _ : state) collisions += world.run_collisions(10'000);
  state.SetItemsProcessed(static_cast<std::int64_t>(collisions));
}
BENCHMARK(BM_WorldGrowingGas)->ArgName("growing")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// ---- a game's frame -----------------------------------------------------------------------

constexpr std::uint32_t kGameSide = 100;  // 100 × 100 = 10⁴ balls
constexpr double kGameMinRadius = 0.3;
constexpr double kGameMaxRadius = 0.7;
// Lattice spacing: the largest diameter and a little room, so no two balls start in contact.
constexpr double kGameSpacing = 2.0 * kGameMaxRadius + 0.1;
// Velocity components' standard deviation, in length units per second: a ball of diameter 1
// crosses about five diameters a second, some 0.1 per frame.
constexpr double kGameSpeed = 5.0;
constexpr double kFramesPerSecond = 60.0;
constexpr int kWarmUpFrames = 60;  // one second of game time, not timed
constexpr std::uint64_t kGameSeed = 2;

// 10⁴ balls with radii uniform in [0.3, 0.7] and masses in proportion to their areas (a ball of
// radius 0.5 weighs 1), elastic so that the load stays the same from frame to frame, on a square
// lattice in a closed box 150 × 150 (packing fraction about 0.37).
World game_world() {
  const double side = kGameSpacing * kGameSide;
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {side, side};
  World world(def);
  std::mt19937_64 random(kGameSeed);
  std::uniform_real_distribution<double> radius(kGameMinRadius, kGameMaxRadius);
  std::normal_distribution<double> speed(0.0, kGameSpeed);
  for (std::uint32_t row = 0; row < kGameSide; ++row) {
    for (std::uint32_t column = 0; column < kGameSide; ++column) {
      BallDef ball;
      ball.position = {(column + 0.5) * kGameSpacing, (row + 0.5) * kGameSpacing};
      ball.radius = radius(random);
      ball.mass = (ball.radius / 0.5) * (ball.radius / 0.5);
      const double vx = speed(random);
      const double vy = speed(random);
      ball.velocity = {vx, vy};
      world.add_ball(ball);
    }
  }
  return world;
}

// One iteration is one frame, world.step(1/60), timed by hand with std::chrono::steady_clock:
// the benchmark's time is the mean frame, the counter worst_step_ms the slowest frame of the run,
// contacts_per_step the mean number of contacts a frame resolves.
World warmed_game_world() {
  World world = game_world();
  for (int frame = 0; frame < kWarmUpFrames; ++frame) world.step(1.0 / kFramesPerSecond);
  return world;
}

// The frames' times, each handed to the benchmark as it is measured; the mean and the worst.
class FrameTimes {
 public:
  explicit FrameTimes(benchmark::State& state) : state_(state) {}
  template <class Frame>
  void time(Frame&& frame) {
    const auto start = std::chrono::steady_clock::now();
    frame();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state_.SetIterationTime(seconds);
    worst_ = std::max(worst_, seconds);
    total_ += seconds;
  }
  void report() const {
    const auto frames = static_cast<double>(state_.iterations());
    state_.counters["mean_step_ms"] = total_ / frames * 1e3;
    state_.counters["worst_step_ms"] = worst_ * 1e3;
  }

 private:
  benchmark::State& state_;
  double worst_ = 0.0;
  double total_ = 0.0;
};

void BM_WorldGameStep(benchmark::State& state) {
  static World world = warmed_game_world();
  FrameTimes times(state);
  std::uint64_t contacts = 0;
  for (auto _ : state) {
    times.time([] { world.step(1.0 / kFramesPerSecond); });
    contacts += world.contacts().size();
  }
  times.report();
  state.counters["contacts_per_step"] =
      static_cast<double>(contacts) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_WorldGameStep)->UseManualTime()->Unit(benchmark::kMillisecond);

// The player's pointer drags ball 0 round a circle of radius kDragRadius at kDragTurnsPerSecond;
// each frame the ball is dragged to the pointer (stopping at whatever it touches) and given the
// pointer's velocity, then the world steps. Timed: the drag, the velocity and the step.
constexpr double kDragRadius = 5.0;
constexpr double kDragTurnsPerSecond = 0.25;

void BM_WorldGameDragStep(benchmark::State& state) {
  static World world = warmed_game_world();
  const BallId dragged = world.balls().front();
  const Vec2 centre = world.position(dragged);
  constexpr double kTurn = 2.0 * 3.141592653589793 * kDragTurnsPerSecond / kFramesPerSecond;
  FrameTimes times(state);
  int frame = 0;
  for (auto _ : state) {
    const double angle = kTurn * frame++;
    const Vec2 pointer = centre + Vec2{std::cos(angle), std::sin(angle)} * kDragRadius;
    const Vec2 pointer_velocity =
        Vec2{-std::sin(angle), std::cos(angle)} * (kDragRadius * kTurn * kFramesPerSecond);
    times.time([&] {
      world.set_position(dragged, pointer, Placement::nearest_free);
      world.set_velocity(dragged, pointer_velocity);
      world.step(1.0 / kFramesPerSecond);
    });
  }
  times.report();
}
BENCHMARK(BM_WorldGameDragStep)->UseManualTime()->Unit(benchmark::kMillisecond);

// Each frame the player draws a wall: a segment of length 2·kDrawnWallHalf at a random angle, at
// a random place no ball touches (chosen before the frame's clock starts), then the world
// steps. Timed: add_segment and the step. The walls stay: after n frames the box holds n more.
constexpr double kDrawnWallHalf = 0.5;
constexpr std::uint64_t kDrawSeed = 7;
// Frames a run: a fixed number, so that every run (and every build) steps the same walls.
constexpr benchmark::IterationCount kDrawnWalls = 600;

Segment free_wall(const World& world, std::mt19937_64& random) {
  const double side = kGameSpacing * kGameSide;
  std::uniform_real_distribution<double> place(1.0, side - 1.0);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * 3.141592653589793);
  for (;;) {
    const double x = place(random);
    const double y = place(random);
    const double angle = turn(random);
    const Vec2 site{x, y};
    const auto touches = [&](BallId id) {
      return length(world.position(id) - site) <= kDrawnWallHalf + world.radius(id);
    };
    const std::vector<BallId> balls = world.balls();
    if (std::none_of(balls.begin(), balls.end(), touches)) {
      const Vec2 half = Vec2{std::cos(angle), std::sin(angle)} * kDrawnWallHalf;
      return {site - half, site + half};
    }
  }
}

void BM_WorldGameWallStep(benchmark::State& state) {
  World world = warmed_game_world();  // afresh each run: the same walls on the same balls
  std::mt19937_64 random(kDrawSeed);
  FrameTimes times(state);
  for (auto _ : state) {
    const Segment wall = free_wall(world, random);
    times.time([&] {
      world.add_segment(wall);
      world.step(1.0 / kFramesPerSecond);
    });
  }
  times.report();
}
BENCHMARK(BM_WorldGameWallStep)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(kDrawnWalls);

}  // namespace
}  // namespace carom::bench
