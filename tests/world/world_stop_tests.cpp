// Why a run returns (World::stop_reason) and stopping a run from outside (request_stop, the
// progress callback): a stopped run leaves the world at an event boundary, consistent, and going
// on from there gives exactly what a run never stopped gives.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "carom/world.hpp"
#include "world/random_scene.hpp"
#include "world/scene_world.hpp"

namespace carom {
namespace {

// Two balls in a periodic cell whose relative motion runs along a line of slope 1 that keeps
// 5/√2 ≈ 3.5 from every image of the other ball, more than the two radii (2): a closed orbit that
// never meets, which no rule can prove contact-free. Cell crossings go on for ever.
World endless_orbit() {
  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {10.0, 10.0};
  World world(def);
  (void)world.add_ball({{1.0, 1.0}, {0.5, 0.5}, 1.0, 1.0, std::nullopt, 0});
  (void)world.add_ball({{6.0, 1.0}, {-0.5, -0.5}, 1.0, 1.0, std::nullopt, 0});
  return world;
}

testing::SceneWorld box_gas() {
  testing::GasOptions options;
  options.ball_count = 300;
  options.side = 40.0;
  options.max_speed = 2.0;
  return testing::build_world(testing::random_gas(options, 11), testing::BoxAs::boundary);
}

struct State {
  std::vector<Vec2> positions;
  std::vector<Vec2> velocities;
  std::uint64_t collisions = 0;
  double time = 0.0;
  friend bool operator==(const State&, const State&) = default;
};

State state_of(const testing::SceneWorld& built) {
  State state;
  for (const BallId id : built.ids) {
    state.positions.push_back(built.world.position(id));
    state.velocities.push_back(built.world.velocity(id));
  }
  state.collisions = built.world.collision_count();
  state.time = built.world.time();
  return state;
}

TEST(WorldStop, EachWayARunEndsHasItsReason) {
  testing::SceneWorld built = box_gas();
  World& world = built.world;
  EXPECT_EQ(world.stop_reason(), StopReason::none);  // before any run

  (void)world.run_until(1.0);
  EXPECT_EQ(world.stop_reason(), StopReason::none);
  (void)world.step(0.5);
  EXPECT_EQ(world.stop_reason(), StopReason::none);
  EXPECT_EQ(world.run_collisions(10), 10U);
  EXPECT_EQ(world.stop_reason(), StopReason::none);

  // A time limit closer than the next contact.
  const double now = world.time();
  EXPECT_EQ(world.run_collisions(1'000'000, now + 1e-9), 0U);
  EXPECT_EQ(world.stop_reason(), StopReason::time_limit);
  EXPECT_EQ(world.time(), now + 1e-9);

  world.set_stop_condition([](const ContactEvent&) { return true; });
  EXPECT_EQ(world.run_collisions(5), 1U);
  EXPECT_EQ(world.stop_reason(), StopReason::stop_condition);
  EXPECT_TRUE(world.stopped_early());
  world.set_stop_condition(nullptr);

  // Two balls flying apart in an open world: the run proves no contact will come.
  World open;
  (void)open.add_ball({{0.0, 0.0}, {-1.0, 0.0}, 1.0, 1.0, std::nullopt, 0});
  (void)open.add_ball({{5.0, 0.0}, {1.0, 0.0}, 1.0, 1.0, std::nullopt, 0});
  EXPECT_EQ(open.run_collisions(1), 0U);
  EXPECT_EQ(open.stop_reason(), StopReason::no_more_contacts);
  EXPECT_FALSE(open.stopped_early());
  // Nothing moving at all: the queue is empty.
  World still;
  (void)still.add_ball({{0.0, 0.0}, {}, 1.0, 1.0, std::nullopt, 0});
  EXPECT_EQ(still.run_collisions(1, 100.0), 0U);
  EXPECT_EQ(still.stop_reason(), StopReason::no_more_contacts);
  EXPECT_EQ(still.run_collisions(0), 0U);
  EXPECT_EQ(still.stop_reason(), StopReason::none);
}

TEST(WorldStop, ARequestBetweenRunsStopsTheNextAtOnceAndIsThenCleared) {
  testing::SceneWorld built = box_gas();
  World& world = built.world;
  world.request_stop();
  EXPECT_EQ(world.run_until(10.0), 0.0);
  EXPECT_EQ(world.stop_reason(), StopReason::interrupted);
  EXPECT_EQ(world.time(), 0.0);
  EXPECT_EQ(world.collision_count(), 0U);
  EXPECT_EQ(world.run_until(10.0), 10.0);
  EXPECT_EQ(world.stop_reason(), StopReason::none);
  EXPECT_GT(world.collision_count(), 0U);
}

TEST(WorldStop, TheProgressCallbackIsCalledAtTheStartAndEveryFewThousandEvents) {
  World world = endless_orbit();
  std::vector<RunStatus> seen;
  world.set_progress_callback([&seen](const RunStatus& status) {
    seen.push_back(status);
    return seen.size() == 5;
  });
  // A contact never comes: only the callback ends this run.
  EXPECT_EQ(world.run_collisions(1), 0U);
  EXPECT_EQ(world.stop_reason(), StopReason::interrupted);
  ASSERT_EQ(seen.size(), 5U);
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].events, k * World::kStopCheckEvents) << k;
    EXPECT_EQ(seen[k].contacts, 0U);
    if (k > 0) {
      EXPECT_GT(seen[k].time, seen[k - 1].time) << k;
    }
  }
  // The world stopped at the last event the callback was told of, and is sound there.
  EXPECT_EQ(world.time(), seen.back().time);
  EXPECT_EQ(world.audit_all_pairs(), std::nullopt);
  // The endless run can be given a limit instead.
  const double limit = world.time() + 1000.0;
  world.set_progress_callback(nullptr);
  EXPECT_EQ(world.run_collisions(1, limit), 0U);
  EXPECT_EQ(world.stop_reason(), StopReason::time_limit);
  EXPECT_EQ(world.time(), limit);
}

// A run cut at every kStopCheckEvents-th event and continued with the same call ends bit for bit
// where the run never cut ends, through every kind of run.
TEST(WorldStop, ARunStoppedAndContinuedEndsBitIdenticalToOneNeverStopped) {
  testing::SceneWorld straight = box_gas();
  (void)straight.world.run_until(20.0);
  (void)straight.world.run_collisions(5000);
  (void)straight.world.step(3.0);

  testing::SceneWorld cut = box_gas();
  int stops = 0;
  cut.world.set_progress_callback([](const RunStatus& status) { return status.events > 0; });
  const auto finish = [&](auto&& run) {
    for (;;) {
      run();
      if (cut.world.stop_reason() != StopReason::interrupted) return;
      ++stops;
    }
  };
  finish([&] { (void)cut.world.run_until(20.0); });
  std::uint64_t contacts = 0;
  finish([&] { contacts += cut.world.run_collisions(5000 - contacts); });
  EXPECT_EQ(contacts, 5000U);
  const double end = cut.world.time() + 3.0;
  finish([&] { (void)cut.world.run_until(end); });

  EXPECT_GT(stops, 10);
  EXPECT_EQ(state_of(cut), state_of(straight));
  EXPECT_EQ(cut.world.audit_all_pairs(), std::nullopt);
}

TEST(WorldStop, StepReportsTheTimeItAdvancedWhenStopped) {
  World world = endless_orbit();
  world.set_progress_callback([](const RunStatus& status) { return status.events > 0; });
  const double advanced = world.step(1e6);
  EXPECT_EQ(world.stop_reason(), StopReason::interrupted);
  EXPECT_GT(advanced, 0.0);
  EXPECT_LT(advanced, 1e6);
  EXPECT_EQ(advanced, world.time());
}

}  // namespace
}  // namespace carom
