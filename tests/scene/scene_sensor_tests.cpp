// Sensors in scenes: read in each shape with their actions and filters, written back bit for bit,
// built into the world as its last walls (so checkpoints find them), and refused field by field.
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "carom/scene.hpp"

namespace carom::scene_sensor_tests {
namespace {

constexpr const char* kScene = R"({
  "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 10]},
  "balls": [{"name": "cue", "position": [2, 5], "velocity": [4, 0], "radius": 0.5}],
  "segments": [{"a": [1, 1], "b": [1, 9]}],
  "sensors": [
    {"name": "line", "shape": "segment", "a": [6, 0], "b": [6, 10]},
    {"shape": "arc", "center": [10, 5], "radius": 2, "start_angle": 0, "end_angle": 3,
     "filter": {"category": 2}},
    {"name": "pocket", "shape": "disc", "center": [17, 5], "radius": 0.3, "action": "remove_ball"}
  ]})";

TEST(SceneSensors, ReadWriteAndBuild) {
  const Scene scene = parse_scene(kScene);
  ASSERT_EQ(scene.sensors.size(), 3U);
  EXPECT_TRUE(std::holds_alternative<Segment>(scene.sensors[0].shape));
  EXPECT_TRUE(std::holds_alternative<Arc>(scene.sensors[1].shape));
  EXPECT_EQ(scene.sensors[1].filter.category, 2U);
  EXPECT_EQ(scene.sensors[2].action, SensorAction::remove_ball);
  EXPECT_EQ(std::get<Ball>(scene.sensors[2].shape).radius, 0.3);
  // Written and read back: the same text again.
  const std::string text = to_json_text(scene);
  EXPECT_EQ(to_json_text(parse_scene(text)), text);

  SceneWorld sw = make_world(scene);
  ASSERT_EQ(sw.sensors.size(), 3U);
  // Box walls 0-3, the segment 4, then the sensors.
  EXPECT_EQ(sw.sensors[0], 5U);
  EXPECT_EQ(sw.sensors[2], sw.world.wall_count() - 1);
  EXPECT_EQ(sw.world.sensor(sw.sensors[2]), SensorAction::remove_ball);
  EXPECT_EQ(sw.world.wall_filter(sw.sensors[1]).category, 2U);
  EXPECT_EQ(summarize(scene, scene.balls).sensors, 3U);
  // The cue ball crosses the line (an enter and an exit), passes the arc's end at angle 3 and
  // its start at angle 0 (the ball's default mask meets category 2), and falls into the pocket,
  // its scene entry then null.
  step_scene(sw, 5.0);
  const BallId cue = sw.by_name.at("cue");
  EXPECT_FALSE(sw.world.contains(cue));
  EXPECT_TRUE(sw.balls[0].is_null());
  ASSERT_EQ(sw.sensor_events.size(), 7U);
  EXPECT_EQ(sw.sensor_events[0].sensor, sw.sensors[0]);
  EXPECT_EQ(sw.sensor_events[2].sensor, sw.sensors[1]);
  EXPECT_EQ(sw.sensor_events[4].sensor, sw.sensors[1]);
  EXPECT_EQ(sw.sensor_events[6].sensor, sw.sensors[2]);
  EXPECT_TRUE(sw.sensor_events[6].removed);
  // A captured scene keeps its sensors.
  EXPECT_EQ(capture_scene(sw).sensors.size(), 3U);
}

TEST(SceneSensors, BadSensorsAreRefusedNamingTheField) {
  const auto error_of = [](const std::string& sensors) {
    try {
      (void)parse_scene(R"({"sensors": [)" + sensors + "]}");
    } catch (const SceneError& error) {
      return error.details().path + ": " + error.details().problem;
    }
    return std::string("accepted");
  };
  EXPECT_NE(error_of(R"({"shape": "square", "center": [0, 0]})").find("sensors[0].shape"),
            std::string::npos);
  EXPECT_NE(
      error_of(R"({"shape": "disc", "center": [0, 0], "radius": 0})").find("sensors[0].radius"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"shape": "disc", "center": [0, 0], "a": [1, 1]})").find("sensors[0].a"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"shape": "segment", "a": [0, 0], "b": [1, 1], "action": "eat"})")
                .find("sensors[0].action"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"shape": "arc", "center": [0, 0], "radius": 1, "start_angle": 0,
                          "end_angle": 7})")
                .find("sensors[0].end_angle"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"name": "x", "shape": "disc", "center": [0, 0]},
                        {"name": "x", "shape": "disc", "center": [5, 0]})")
                .find("sensors[1].name"),
            std::string::npos);
}

}  // namespace
}  // namespace carom::scene_sensor_tests
