// Moving walls in scenes: a segment's and an arc's "motion" read, written back bit for bit, built
// into the world (a flipper hits the ball), captured mid-motion where the walls are then, counted
// by the summary, and refused field by field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "carom/scene.hpp"

namespace carom::scene_moving_wall_tests {
namespace {

constexpr const char* kScene = R"({
  "world": {"boundary": "box", "lower": [-5, -5], "upper": [5, 5]},
  "balls": [{"name": "ball", "position": [1, 1.5], "radius": 0.5}],
  "segments": [{"a": [-4, -4], "b": [4, -4]},
               {"a": [0, 0], "b": [2, 0], "motion": {"angular_velocity": 1, "duration": 2}}],
  "arcs": [{"center": [-3, 3], "radius": 1, "start_angle": 0, "end_angle": 1,
            "motion": {"velocity": [0.5, 0], "pivot": [-3, 3]}}]
})";

TEST(SceneMovingWalls, ReadWriteBuildAndCapture) {
  const Scene scene = parse_scene(kScene);
  ASSERT_EQ(scene.segment_motions.size(), 2U);
  EXPECT_FALSE(scene.segment_motions[0]);
  ASSERT_TRUE(scene.segment_motions[1]);
  EXPECT_EQ(scene.segment_motions[1]->angular_velocity, 1.0);
  EXPECT_EQ(scene.segment_motions[1]->duration, 2.0);
  ASSERT_EQ(scene.arc_motions.size(), 1U);
  EXPECT_EQ(scene.arc_motions[0]->velocity, (Vec2{0.5, 0.0}));
  EXPECT_TRUE(std::isinf(scene.arc_motions[0]->duration));
  const std::string text = to_json_text(scene);
  EXPECT_EQ(to_json_text(parse_scene(text)), text);
  EXPECT_EQ(summarize(scene, scene.balls).moving_walls, 2U);

  SceneWorld sw = make_world(scene);
  EXPECT_EQ(segment_wall(sw, 1), 5U);  // after the box's four sides and the first segment
  EXPECT_EQ(arc_wall(sw, 0), 6U);
  EXPECT_EQ(sw.world.wall_motion(5).angular_velocity, 1.0);
  // The flipper turning about (0, 0) meets the ball at rest at (1, 1.5) at
  // θ = atan2(1.5, 1) − asin(0.5 / √3.25).
  std::vector<ContactEvent> contacts;
  step_scene(sw, 1.0, &contacts);
  ASSERT_FALSE(contacts.empty());
  EXPECT_NEAR(contacts[0].time, std::atan2(1.5, 1.0) - std::asin(0.5 / std::sqrt(3.25)), 1e-12);
  // Captured at 1: each moving wall where it is, with what is left of its motion.
  const Scene captured = capture_scene(sw);
  EXPECT_NEAR(captured.segments[1].b.x, 2.0 * std::cos(1.0), 1e-15);
  EXPECT_NEAR(captured.segments[1].b.y, 2.0 * std::sin(1.0), 1e-15);
  EXPECT_EQ(captured.segment_motions[1]->duration, 1.0);
  EXPECT_EQ(captured.arcs[0].center, (Vec2{-2.5, 3.0}));
  EXPECT_EQ(captured.segments[0].b, scene.segments[0].b);
  EXPECT_FALSE(captured.segment_motions[0]);
}

TEST(SceneMovingWalls, BadMotionsAreRefusedNamingTheField) {
  const auto error_of = [](const std::string& motion) {
    try {
      (void)parse_scene(R"({"segments": [{"a": [0, 0], "b": [1, 0], "motion": )" + motion + "}]}");
    } catch (const SceneError& error) {
      return error.details().path + ": " + error.details().problem;
    }
    return std::string("accepted");
  };
  EXPECT_NE(error_of(R"({"duration": -1})").find("segments[0].motion.duration"), std::string::npos);
  EXPECT_NE(error_of(R"({"spin": 3})").find("segments[0].motion.spin"), std::string::npos);
  EXPECT_NE(error_of(R"({"velocity": [1]})").find("segments[0].motion.velocity"),
            std::string::npos);
  EXPECT_NE(error_of(R"(3)").find("segments[0].motion"), std::string::npos);
  EXPECT_EQ(error_of(R"({"velocity": [1, 0]})"), "accepted");
}

}  // namespace
}  // namespace carom::scene_moving_wall_tests
