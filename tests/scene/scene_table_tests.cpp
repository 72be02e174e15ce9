// A table in scenes: "world.table", a ball's "spin" and the "shots" read, written back bit for bit,
// built into the world, struck at their times by every kind of run, captured mid-shot with the
// shots still to come, and refused field by field.
#include <gtest/gtest.h>

#include <string>

#include "carom/scene.hpp"

namespace carom::scene_table_tests {
namespace {

constexpr const char* kScene = R"({
  "world": {"boundary": "box", "lower": [0, 0], "upper": [2.54, 1.27], "restitution": 0.95,
            "table": {"sliding_friction": 0.25, "cushion_height": 0.64}},
  "time": 1,
  "balls": [{"name": "cue", "position": [0.6, 0.635], "radius": 0.028575, "mass": 0.17},
            {"name": "one", "position": [1.9, 0.64], "radius": 0.028575, "mass": 0.17,
             "spin": [0, 0, 3]}],
  "shots": [{"ball": "cue", "time": 1.5, "speed": 3, "height": 0.01, "side": -0.005},
            {"ball": "cue", "time": 6, "speed": 1, "direction": 3.14159}]
})";

TEST(SceneTable, ReadWriteAndBuild) {
  const Scene scene = parse_scene(kScene);
  ASSERT_TRUE(scene.world.table);
  EXPECT_EQ(scene.world.table->sliding_friction, 0.25);
  EXPECT_EQ(scene.world.table->cushion_height, 0.64);
  EXPECT_EQ(scene.world.table->rolling_friction, Table{}.rolling_friction);
  EXPECT_EQ(scene.balls[1].spin, (Spin{0.0, 0.0, 3.0}));
  ASSERT_EQ(scene.shots.size(), 2U);
  EXPECT_EQ(scene.shots[0].ball, "cue");
  EXPECT_EQ(scene.shots[0].cue.height, 0.01);
  EXPECT_EQ(scene.shots[1].cue.direction, 3.14159);
  const std::string text = to_json_text(scene);
  EXPECT_EQ(to_json_text(parse_scene(text)), text);

  SceneWorld sw = make_world(scene);
  EXPECT_EQ(sw.world.def().table, scene.world.table);
  EXPECT_EQ(sw.world.spin(sw.by_name.at("one")), (Spin{0.0, 0.0, 3.0}));
  EXPECT_EQ(sw.world.motion_state(sw.by_name.at("one")), MotionState::spinning);
  EXPECT_EQ(sw.world.motion_state(sw.by_name.at("cue")), MotionState::stationary);
}

// The same shot struck by the scene at its time and by hand at that time: the same bits.
TEST(SceneTable, AShotIsStruckAtItsTimeByEveryKindOfRun) {
  const Scene scene = parse_scene(kScene);
  SceneWorld by_hand = make_world(scene);
  by_hand.world.run_until(0.5);
  by_hand.world.strike(by_hand.by_name.at("cue"), scene.shots[0].cue);
  by_hand.world.run_until(2.0);

  SceneWorld until = make_world(scene);
  run_scene_until(until, 0.4);
  EXPECT_EQ(until.shots_taken, 0U);
  EXPECT_EQ(until.world.velocity(until.by_name.at("cue")), Vec2{});
  run_scene_until(until, 2.0);
  EXPECT_EQ(until.shots_taken, 1U);

  SceneWorld steps = make_world(scene);
  for (int k = 0; k < 8; ++k) step_scene(steps, 0.25);

  // By collisions: the world rests until the shot (the spinning ball stops long before), waits
  // for it, and runs on.
  SceneWorld collisions = make_world(scene);
  run_scene_collisions(collisions, 1'000'000, nullptr, nullptr, 2.0);
  EXPECT_EQ(collisions.shots_taken, 1U);

  for (const SceneWorld* sw : {&until, &steps, &collisions}) {
    const BallId cue = sw->by_name.at("cue");
    EXPECT_EQ(sw->world.time(), 2.0);
    EXPECT_EQ(sw->world.position(cue), by_hand.world.position(cue));
    EXPECT_EQ(sw->world.velocity(cue), by_hand.world.velocity(cue));
    EXPECT_EQ(sw->world.spin(cue), by_hand.world.spin(cue));
  }
}

TEST(SceneTable, ARunByCollisionsEndsWhenEverythingRestsAfterTheLastShot) {
  SceneWorld sw = make_world(parse_scene(kScene));
  std::vector<ContactEvent> contacts;
  run_scene_collisions(sw, 1'000'000, &contacts);
  EXPECT_EQ(sw.world.stop_reason(), StopReason::no_more_contacts);
  EXPECT_EQ(sw.shots_taken, 2U);
  EXPECT_TRUE(sw.world.at_rest());
  EXPECT_GT(sw.time(), 6.0);
  EXPECT_FALSE(contacts.empty());
  // The last call's changes of state end with the cue ball coming to rest.
  ASSERT_FALSE(sw.motion_events.empty());
  EXPECT_EQ(sw.motion_events.back().to, MotionState::stationary);
}

// Captured between the shots: the spin of now and only the shot still to come, so that the
// scene continued gives what the run never stopped gives.
TEST(SceneTable, ACapturedSceneKeepsTheSpinsAndTheShotsToCome) {
  const Scene scene = parse_scene(kScene);
  SceneWorld whole = make_world(scene);
  run_scene_until(whole, 2.0);
  const Scene middle = capture_scene(whole);
  ASSERT_EQ(middle.shots.size(), 1U);
  EXPECT_EQ(middle.shots[0].time, 6.0);
  EXPECT_EQ(middle.balls[0].spin, whole.world.spin(whole.by_name.at("cue")));
  EXPECT_NE(middle.balls[0].spin, Spin{});
  const std::string text = to_json_text(middle);
  EXPECT_EQ(to_json_text(parse_scene(text)), text);

  SceneWorld continued = make_world(parse_scene(text));
  // Scene time 9: world time 8 for the whole run (its clock started at scene time 1), 6 for the
  // continued one (at scene time 3).
  run_scene_until(whole, 8.0);
  run_scene_until(continued, 6.0);
  const BallId a = whole.by_name.at("cue");
  const BallId b = continued.by_name.at("cue");
  EXPECT_NEAR(continued.world.position(b).x, whole.world.position(a).x, 1e-9);
  EXPECT_NEAR(continued.world.position(b).y, whole.world.position(a).y, 1e-9);
  EXPECT_EQ(continued.shots_taken, 1U);
}

std::string error_of(const std::string& text) {
  try {
    static_cast<void>(parse_scene(text));
  } catch (const SceneError& error) {
    return error.details().path + ": " + error.details().problem;
  }
  return "accepted";
}

std::string with_world(const std::string& world, const std::string& rest = "") {
  return R"({"world": {"boundary": "box", "lower": [0, 0], "upper": [2, 1])" + world + "}," +
         R"("balls": [{"name": "cue", "position": [0.5, 0.5], "radius": 0.03, "mass": 0.17},
                      {"name": "post", "position": [1.5, 0.5], "radius": 0.03,
                       "mass": "immovable"}])" +
         rest + "}";
}

TEST(SceneTable, MistakesAreRefusedWithTheirField) {
  const std::string table = R"(, "table": {})";
  EXPECT_EQ(error_of(with_world(table)), "accepted");
  EXPECT_NE(error_of(with_world(R"(, "table": {"g": 0})")).find("world.table.g: must be > 0"),
            std::string::npos);
  EXPECT_NE(error_of(with_world(R"(, "table": {"cushion_height": 0.4})"))
                .find("world.table.cushion_height: must lie in [0.5, 1)"),
            std::string::npos);
  EXPECT_NE(error_of(with_world(R"(, "table": {"slide_friction": 0.2})"))
                .find("world.table.slide_friction"),
            std::string::npos);
  EXPECT_NE(error_of(with_world(R"(, "gravity": [0, -9.8], "table": {})")).find("world.gravity"),
            std::string::npos);
  EXPECT_NE(error_of(with_world(R"(, "growth_rate": 1, "table": {})")).find("world.growth_rate"),
            std::string::npos);
  // Spin and shots need a table.
  EXPECT_NE(error_of(R"({"balls": [{"position": [0, 0], "spin": [0, 0, 1]}]})")
                .find("balls[0].spin: must be [0, 0, 0] without world.table"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"balls": [{"position": [0, 0], "spin": [0, 1]}]})").find("balls[0].spin"),
            std::string::npos);
  EXPECT_NE(error_of(with_world("", R"(, "shots": [{"ball": "cue", "speed": 1}])"))
                .find("shots: needs world.table"),
            std::string::npos);
  // Each shot: a movable ball by name, the tip on the ball, in order of time.
  const auto shots = [&](const std::string& list) {
    return error_of(with_world(table, R"(, "shots": )" + list));
  };
  EXPECT_EQ(shots(R"([{"ball": "cue", "speed": 1}, {"ball": "cue", "time": 2, "speed": 1}])"),
            "accepted");
  EXPECT_NE(shots(R"([{"ball": "eight", "speed": 1}])").find("shots[0].ball: names no ball"),
            std::string::npos);
  EXPECT_NE(shots(R"([{"ball": "post", "speed": 1}])").find("shots[0].ball: is an immovable"),
            std::string::npos);
  EXPECT_NE(shots(R"([{"ball": "cue", "speed": 1, "side": 0.03}])").find("shots[0].side"),
            std::string::npos);
  EXPECT_NE(shots(R"([{"ball": "cue", "speed": -1}])").find("shots[0].speed"), std::string::npos);
  EXPECT_NE(shots(R"([{"ball": "cue", "speed": 1, "elevation": 2}])").find("shots[0].elevation"),
            std::string::npos);
  EXPECT_NE(shots(R"([{"ball": "cue", "speed": 1, "time": -1}])")
                .find("shots[0].time: must not come before the scene's time"),
            std::string::npos);
  EXPECT_NE(
      shots(R"([{"ball": "cue", "time": 2, "speed": 1}, {"ball": "cue", "time": 1, "speed": 1}])")
          .find("shots[1].time: must not come before the shot before it"),
      std::string::npos);
  EXPECT_NE(shots(R"([{"speed": 1}])").find("shots[0].ball"), std::string::npos);
}

}  // namespace
}  // namespace carom::scene_table_tests
