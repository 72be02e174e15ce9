// The threading rule of world.hpp: one world per thread, no shared state. Independent worlds
// stepped on several threads at once must give exactly what each gives alone (bit for bit), and
// the stateless queries may be called from any thread. Run under ThreadSanitizer by
// `make test-tsan` (the tsan preset), which fails on any data race it sees; built in the other
// presets too, where it checks the bit-identical results.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

// Two threads per scene, so that identical worlds also run side by side.
constexpr int kScenes = 3;
constexpr int kThreadsPerScene = 2;

struct Outcome {
  std::vector<Vec2> positions;
  std::vector<Vec2> velocities;
  std::uint64_t collisions = 0;
  std::size_t last_step_contacts = 0;
  bool audit_clean = false;

  friend bool operator==(const Outcome&, const Outcome&) = default;
};

// A box with balls on a lattice (never overlapping), seeded random velocities, mixed
// restitution, an arc and a segment inside: every kind of contact happens.
Outcome run_scene(std::uint64_t seed) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {24.0, 24.0};
  World world(def);
  world.add_segment({{4.0, 20.0}, {10.0, 21.0}});
  world.add_arc({{18.0, 18.0}, 3.0, 3.5, 5.5});
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> speed(-3.0, 3.0);
  std::uniform_real_distribution<double> size(0.2, 0.45);
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) {
      BallDef ball;
      ball.position = {2.0 + 1.0 * i, 2.0 + 1.0 * j};
      ball.velocity = {speed(random), speed(random)};
      ball.radius = size(random);
      ball.mass = ball.radius * ball.radius;
      ball.restitution = (i + j) % 3 == 0 ? 0.9 : 1.0;
      (void)world.add_ball(ball);
    }
  }
  for (int step = 0; step < 40; ++step) (void)world.step(0.05);
  Outcome outcome;
  for (const BallId id : world.balls()) {
    outcome.positions.push_back(world.position(id));
    outcome.velocities.push_back(world.velocity(id));
  }
  outcome.collisions = world.collision_count();
  outcome.last_step_contacts = world.contacts().size();
  outcome.audit_clean = !world.audit().has_value();
  return outcome;
}

TEST(WorldThreads, IndependentWorldsOnSeveralThreadsMatchTheirSerialRuns) {
  std::vector<Outcome> serial;
  for (int scene = 0; scene < kScenes; ++scene) {
    serial.push_back(run_scene(static_cast<std::uint64_t>(1000 + scene)));
    ASSERT_TRUE(serial.back().audit_clean) << "scene " << scene;
    ASSERT_GT(serial.back().collisions, 100u) << "scene " << scene << " barely moved";
  }
  std::vector<Outcome> parallel(kScenes * kThreadsPerScene);
  {
    std::vector<std::jthread> threads;
    for (int k = 0; k < kScenes * kThreadsPerScene; ++k) {
      threads.emplace_back([k, &parallel] {
        parallel[static_cast<std::size_t>(k)] =
            run_scene(static_cast<std::uint64_t>(1000 + k % kScenes));
      });
    }
  }
  for (int k = 0; k < kScenes * kThreadsPerScene; ++k) {
    EXPECT_EQ(parallel[static_cast<std::size_t>(k)], serial[static_cast<std::size_t>(k % kScenes)])
        << "thread " << k << " (scene " << k % kScenes << ")";
  }
}

// request_stop from another thread ends a run that would never end by itself (two balls on a
// closed orbit in a periodic cell that never meets), at an event boundary.
TEST(WorldThreads, RequestStopFromAnotherThreadEndsARunThatNeverEnds) {
  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {10.0, 10.0};
  World world(def);
  (void)world.add_ball({{1.0, 1.0}, {0.5, 0.5}, 1.0, 1.0, std::nullopt, 0});
  (void)world.add_ball({{6.0, 1.0}, {-0.5, -0.5}, 1.0, 1.0, std::nullopt, 0});
  std::atomic<bool> running{false};
  world.set_progress_callback([&running](const RunStatus& status) {
    if (status.events > 0) running.store(true);
    return false;
  });
  std::jthread stopper([&world, &running] {
    while (!running.load()) std::this_thread::yield();
    world.request_stop();
  });
  EXPECT_EQ(world.run_collisions(1), 0U);
  stopper.join();
  EXPECT_EQ(world.stop_reason(), StopReason::interrupted);
  EXPECT_GT(world.time(), 0.0);
  EXPECT_EQ(world.audit_all_pairs(), std::nullopt);
}

// The queries keep no state: many threads at once, errors included, give the serial answers.
std::vector<double> run_queries(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> value(-10.0, 10.0);
  std::vector<double> answers;
  std::vector<double> columns[10];
  for (int i = 0; i < 2000; ++i) {
    const Ball a{{value(random), value(random)}, 0.5};
    const Ball b{{value(random), value(random)}, 0.7};
    const Vec2 move{value(random), value(random)};
    answers.push_back(sweep_ball_ball(a, move, b).t);
    answers.push_back(sweep_ball_segment(a, move, {b.center, {0.0, 0.0}}).t);
    answers.push_back(sweep_ball_arc(a, move, {b.center, 2.0, 0.0, 3.0}).t);
    // An extreme case (the rescaled path) and a refused one (the error path).
    answers.push_back(
        sweep_ball_ball({a.center * 1e250, 0.5e250}, move * 1e250, {b.center * 1e250, 0.7e250}).t);
    try {
      (void)sweep_ball_ball(a, {move.x, std::nan("")}, b);
    } catch (const InvalidArgument& error) {
      answers.push_back(static_cast<double>(error.value().size()));
    }
    const double pair[] = {a.center.x, a.center.y, a.radius, move.x, move.y,
                           b.center.x, b.center.y, b.radius, 0.0,    0.0};
    for (int k = 0; k < 10; ++k) columns[k].push_back(pair[k]);
  }
  std::vector<double> t(columns[0].size());
  (void)sweep_ball_ball_batch({columns[0], columns[1], columns[2], columns[3], columns[4],
                               columns[5], columns[6], columns[7], columns[8], columns[9]},
                              t);
  answers.insert(answers.end(), t.begin(), t.end());
  return answers;
}

TEST(QueryThreads, TimeOfImpactQueriesFromSeveralThreadsMatchTheSerialAnswers) {
  constexpr int kThreads = 4;
  std::vector<std::vector<double>> serial;
  for (int k = 0; k < kThreads; ++k) serial.push_back(run_queries(static_cast<std::uint64_t>(k)));
  std::vector<std::vector<double>> parallel(kThreads);
  {
    std::vector<std::jthread> threads;
    for (int k = 0; k < kThreads; ++k) {
      threads.emplace_back([k, &parallel] {
        parallel[static_cast<std::size_t>(k)] = run_queries(static_cast<std::uint64_t>(k));
      });
    }
  }
  for (int k = 0; k < kThreads; ++k) {
    EXPECT_EQ(parallel[static_cast<std::size_t>(k)], serial[static_cast<std::size_t>(k)])
        << "thread " << k;
  }
}

}  // namespace
}  // namespace carom
