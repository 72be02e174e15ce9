// Saving and loading a scene round-trips exactly: every double bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "carom/scene.hpp"

namespace carom {
namespace {

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

// Any finite double, drawn uniformly over bit patterns (so tiny, huge, subnormal and negative
// zero all occur), plus values from ordinary arithmetic that have long decimal expansions.
double random_double(std::mt19937_64& random) {
  for (;;) {
    const double value = std::bit_cast<double>(random());
    if (std::isfinite(value)) return value;
  }
}

Scene random_scene(std::mt19937_64& random, int balls) {
  Scene scene;
  scene.description = "random \"quoted\" \\ text\n\xc3\xa9";
  scene.time = random_double(random);
  scene.world.boundary = Boundary::open;
  scene.world.lower = {random_double(random), random_double(random)};
  scene.world.upper = {random_double(random), random_double(random)};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < balls; ++i) {
    SceneBall ball;
    // Far apart so the scene is valid: ball i lies near x = 10·i.
    ball.position = {10.0 * i + unit(random), unit(random) / 3.0};
    ball.velocity = {random_double(random), random_double(random)};
    ball.radius = 0.1 + unit(random);
    ball.mass = i % 5 == 0 ? kImmovable : std::fabs(random_double(random));
    if (ball.mass == 0.0) ball.mass = 1.0;
    if (i % 2 == 0) ball.restitution = unit(random);
    if (i % 3 == 0) ball.name = "ball " + std::to_string(i);
    if (i % 4 == 0) ball.color = "#ff8800";
    scene.balls.push_back(ball);
  }
  scene.segments.push_back({{-5.0, -100.0 + unit(random)}, {random_double(random), -100.0}});
  return scene;
}

TEST(SceneRoundTrip, EveryDoubleReadsBackBitIdentical) {
  std::mt19937_64 random(20261130);
  for (int round = 0; round < 50; ++round) {
    const Scene scene = random_scene(random, 40);
    const std::string text = to_json_text(scene);
    const Scene back = parse_scene(text, "round-trip");
    ASSERT_EQ(back.balls.size(), scene.balls.size());
    EXPECT_EQ(bits(back.time), bits(scene.time));
    EXPECT_EQ(back.description, scene.description);
    for (std::size_t i = 0; i < scene.balls.size(); ++i) {
      const SceneBall& a = scene.balls[i];
      const SceneBall& b = back.balls[i];
      EXPECT_EQ(bits(a.position.x), bits(b.position.x));
      EXPECT_EQ(bits(a.position.y), bits(b.position.y));
      EXPECT_EQ(bits(a.velocity.x), bits(b.velocity.x)) << text;
      EXPECT_EQ(bits(a.velocity.y), bits(b.velocity.y));
      EXPECT_EQ(bits(a.radius), bits(b.radius));
      EXPECT_EQ(bits(a.mass), bits(b.mass));
      EXPECT_EQ(a.restitution.has_value(), b.restitution.has_value());
      if (a.restitution) {
        EXPECT_EQ(bits(*a.restitution), bits(*b.restitution));
      }
      EXPECT_EQ(a.name, b.name);
      EXPECT_EQ(a.color, b.color);
    }
    EXPECT_EQ(bits(back.segments[0].b.x), bits(scene.segments[0].b.x));
    // And the text itself is a fixed point.
    EXPECT_EQ(to_json_text(back), text);
  }
}

TEST(SceneRoundTrip, NegativeZeroStaysNegative) {
  Scene scene;
  SceneBall ball;
  ball.velocity = {-0.0, 0.0};
  scene.balls.push_back(ball);
  const Scene back = parse_scene(to_json_text(scene));
  EXPECT_TRUE(std::signbit(back.balls[0].velocity.x));
  EXPECT_FALSE(std::signbit(back.balls[0].velocity.y));
}

TEST(SceneRoundTrip, ExtremeValues) {
  Scene scene;
  SceneBall ball;
  ball.position = {std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::max()};
  ball.velocity = {std::numeric_limits<double>::max(), 0.1 + 0.2};
  ball.radius = std::numeric_limits<double>::min();
  scene.balls.push_back(ball);
  const Scene back = parse_scene(to_json_text(scene));
  EXPECT_EQ(bits(back.balls[0].position.x), bits(ball.position.x));
  EXPECT_EQ(bits(back.balls[0].position.y), bits(ball.position.y));
  EXPECT_EQ(bits(back.balls[0].velocity.x), bits(ball.velocity.x));
  EXPECT_EQ(bits(back.balls[0].velocity.y), bits(ball.velocity.y));
  EXPECT_EQ(bits(back.balls[0].radius), bits(ball.radius));
}

TEST(SceneRoundTrip, GeneratorsPocketsPolylinesArcsAndSettingsSurvive) {
  const std::string text = R"({
    "carom_scene": 1,
    "units": {"length": "cm", "time": "ms", "mass": "g"},
    "world": {"boundary": "box", "lower": [0, 0], "upper": [100, 50], "restitution": 0.9,
              "collapse_time": 1e-6, "cell_size": 0},
    "balls": [{"name": "cue", "position": [10, 10], "velocity": [5, 1], "radius": 1}],
    "polylines": [{"points": [[20, 20], [30, 20], [30, 30]], "closed": true}],
    "arcs": [{"center": [70, 25], "radius": 5, "start_angle": 0, "end_angle": 3.14159}],
    "pockets": [{"name": "corner", "position": [98, 48], "radius": 1.5}],
    "generators": [{"name": "gas", "placement": "random", "count": 20, "radius": 0.5,
                    "region": {"lower": [40, 2], "upper": [60, 20]}, "mass": 2,
                    "velocity": {"distribution": "maxwell_boltzmann", "temperature": 3,
                                 "zero_momentum": true}, "seed": 9}]
  })";
  const Scene scene = parse_scene(text);
  const std::string saved = to_json_text(scene);
  EXPECT_EQ(to_json_text(parse_scene(saved)), saved);
  EXPECT_EQ(scene.units.length, "cm");
  EXPECT_EQ(scene.world.boundary, Boundary::box);
  ASSERT_EQ(scene.generators.size(), 1U);
  EXPECT_EQ(scene.generators[0].velocities.distribution, VelocityDistribution::maxwell_boltzmann);
  EXPECT_TRUE(scene.generators[0].velocities.zero_momentum);
  EXPECT_EQ(scene.pockets[0].name, "corner");
  EXPECT_TRUE(scene.polylines[0].closed);
}

TEST(SceneRoundTrip, ThermostatReadsBackBitIdentical) {
  Scene scene;
  scene.thermostat = SceneThermostat{0.1 + 0.2, 1.0 / 3.0, std::nullopt};
  const std::string text = to_json_text(scene);
  const Scene back = parse_scene(text, "round-trip");
  ASSERT_TRUE(back.thermostat.has_value());
  EXPECT_EQ(bits(back.thermostat->temperature), bits(0.1 + 0.2));
  EXPECT_EQ(bits(*back.thermostat->interval), bits(1.0 / 3.0));
  EXPECT_FALSE(back.thermostat->collisions.has_value());
  EXPECT_EQ(to_json_text(back), text);
  scene.thermostat = SceneThermostat{2.0, std::nullopt, 12345};
  const Scene by_collisions = parse_scene(to_json_text(scene), "round-trip");
  EXPECT_EQ(by_collisions.thermostat->collisions, std::optional<std::uint64_t>(12345));
  EXPECT_EQ(to_json_text(Scene{}).find("thermostat"), std::string::npos);
}

TEST(SceneRoundTrip, GravityReadsBackBitIdentical) {
  std::mt19937_64 random(20261201);
  std::vector<Vec2> values{{0.0, -9.81}, {-0.0, 0.0}, {0.0, -0.0}, {1e-300, -1e300}};
  for (int i = 0; i < 50; ++i) values.push_back({random_double(random), random_double(random)});
  for (const Vec2 gravity : values) {
    Scene scene;
    scene.world.gravity = gravity;
    const std::string text = to_json_text(scene);
    EXPECT_NE(text.find("\"gravity\": ["), std::string::npos) << text;
    const Scene back = parse_scene(text, "round-trip");
    EXPECT_EQ(bits(back.world.gravity.x), bits(gravity.x)) << text;
    EXPECT_EQ(bits(back.world.gravity.y), bits(gravity.y)) << text;
    EXPECT_EQ(to_json_text(back), text);
  }
}

TEST(SceneRoundTrip, GravityIsWrittenLastInTheWorldLine) {
  Scene scene;
  scene.world.gravity = {0.0, -9.81};
  EXPECT_NE(to_json_text(scene).find(
                "\"collapse_time\": 0.0, \"cell_size\": 0.0, \"gravity\": [0.0, -9.81]}"),
            std::string::npos);
  const Scene read = parse_scene(R"({"world": {"gravity": [0, -9.81]}})");
  EXPECT_EQ(read.world.gravity, (Vec2{0.0, -9.81}));
  // Absent is zero.
  EXPECT_EQ(parse_scene(R"({"world": {"boundary": "open"}})").world.gravity, Vec2{});
  EXPECT_EQ(parse_scene("{}").world.gravity, Vec2{});
}

TEST(SceneRoundTrip, RestHeightReadsBackBitIdentical) {
  std::mt19937_64 random(20261202);
  std::vector<double> values{0.01,
                             0.1 + 0.2,
                             1e-3 * (1.0 + 1e-15),
                             std::nextafter(1e-3, 0.0),
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max()};
  for (int i = 0; i < 50; ++i) values.push_back(std::fabs(random_double(random)));
  for (const double rest_height : values) {
    if (!(rest_height > 0.0)) continue;
    Scene scene;
    scene.world.rest_height = rest_height;
    const std::string text = to_json_text(scene);
    EXPECT_NE(text.find("\"rest_height\": "), std::string::npos) << text;
    const Scene back = parse_scene(text, "round-trip");
    EXPECT_EQ(bits(back.world.rest_height), bits(rest_height)) << text;
    EXPECT_EQ(to_json_text(back), text);
  }
}

TEST(SceneRoundTrip, RestHeightIsWrittenLastInTheWorldLineWhenNotTheDefault) {
  Scene scene;
  scene.world.gravity = {0.0, -9.81};
  scene.world.rest_height = 0.01;
  EXPECT_NE(to_json_text(scene).find("\"cell_size\": 0.0, \"gravity\": [0.0, -9.81], "
                                     "\"rest_height\": 0.01}"),
            std::string::npos)
      << to_json_text(scene);
  const Scene read = parse_scene(R"({"world": {"gravity": [0, -9.81], "rest_height": 0.05}})");
  EXPECT_EQ(read.world.rest_height, 0.05);
  // Absent is the world's default, and the default is never written: the text of a scene that
  // gives it is that of the same scene without it.
  EXPECT_EQ(parse_scene(R"({"world": {"boundary": "open"}})").world.rest_height,
            WorldDef{}.rest_height);
  EXPECT_EQ(parse_scene("{}").world.rest_height, WorldDef{}.rest_height);
  EXPECT_EQ(to_json_text(parse_scene(R"({"world": {"gravity": [0, -1], "rest_height": 1e-3}})")),
            to_json_text(parse_scene(R"({"world": {"gravity": [0, -1]}})")));
  EXPECT_EQ(to_json_text(parse_scene(R"({"world": {"rest_height": 0.001}})")).find("rest_height"),
            std::string::npos);
}

// A scene without gravity (or with gravity +0) writes no gravity key, and one with the default
// rest height no rest_height key, so its text is that of the same scene with the fields left out,
// and saved scenes and the reference hashes' inputs stay put.
TEST(SceneRoundTrip, SceneWithoutGravityWritesNoGravityKey) {
  const std::string text = R"({"world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10],
    "gravity": [0, 0]}, "balls": [{"position": [2, 5], "velocity": [1, 0]}]})";
  const std::string expected =
      "{\n"
      "  \"carom_scene\": 1,\n"
      "  \"units\": {\"length\": \"m\", \"time\": \"s\", \"mass\": \"kg\"},\n"
      "  \"world\": {\"boundary\": \"box\", \"lower\": [0.0, 0.0], \"upper\": [10.0, 10.0], "
      "\"restitution\": 1.0, \"collapse_time\": 0.0, \"cell_size\": 0.0},\n"
      "  \"time\": 0.0,\n"
      "  \"balls\": [\n"
      "    {\"position\": [2.0, 5.0], \"velocity\": [1.0, 0.0], \"radius\": 1.0, \"mass\": 1.0}\n"
      "  ]\n"
      "}\n";
  EXPECT_EQ(to_json_text(parse_scene(text)), expected);
  for (const auto& entry : std::filesystem::directory_iterator(CAROM_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    const Scene scene = load_scene(entry.path());
    const std::string written = to_json_text(scene);
    const std::size_t world = written.find("\n  \"world\": {");
    ASSERT_NE(world, std::string::npos) << entry.path();
    const std::string world_line = written.substr(world, written.find('\n', world + 1) - world);
    if (scene.world.rest_height == WorldDef{}.rest_height) {
      EXPECT_EQ(world_line.find("rest_height"), std::string::npos) << entry.path();
    }
    if (scene.world.gravity != Vec2{}) continue;
    EXPECT_EQ(world_line.find("gravity"), std::string::npos) << entry.path();
  }
}

TEST(SceneRoundTrip, BallFiltersReadBackAndBuildIntoTheWorld) {
  const Scene scene = parse_scene(
      R"({"balls": [{"position": [0, 0], "velocity": [1, 0], "radius": 0.5,
                     "filter": {"category": 2, "mask": 18446744073709551613, "group": -7}},
                    {"position": [0.2, 0], "radius": 0.5, "filter": {"group": -7}},
                    {"position": [5, 0], "radius": 0.5}]})",
      "filters");
  ASSERT_EQ(scene.balls.size(), 3u);
  EXPECT_EQ(scene.balls[0].filter, (CollisionFilter{2, 18446744073709551613ULL, -7}));
  EXPECT_EQ(scene.balls[1].filter, (CollisionFilter{1, ~0ULL, -7}));
  EXPECT_EQ(scene.balls[2].filter, CollisionFilter{});
  const std::string text = to_json_text(scene);
  EXPECT_EQ(to_json_text(parse_scene(text, "again")), text);
  EXPECT_EQ(text.find("\"filter\"", text.rfind("[5.0")), std::string::npos);  // default: none
  // The first two overlap, allowed by their group; the world keeps their filters.
  SceneWorld built = make_world(scene);
  EXPECT_EQ(built.world.filter(built.balls[0]), scene.balls[0].filter);
  EXPECT_EQ(built.world.audit(), std::nullopt);
  EXPECT_THROW(static_cast<void>(parse_scene(R"({"balls": [{"position": [0, 0],
                                    "filter": {"group": 1.5}}]})")),
               SceneError);
  // Walls: a segment, a polyline and an arc with filters; the ball of category 2 lies across
  // the segment that lets it through, and is refused across the one that does not.
  const Scene walls = parse_scene(
      R"({"segments": [{"a": [0, -5], "b": [0, 5], "filter": {"category": 4, "mask": 5}},
                       {"a": [20, -5], "b": [20, 5]}],
          "polylines": [{"points": [[30, 0], [31, 0], [32, 1]], "filter": {"group": 2}}],
          "arcs": [{"center": [50, 0], "radius": 3, "start_angle": 0, "end_angle": 3,
                    "filter": {"mask": 1}}],
          "balls": [{"position": [0, 0], "radius": 0.5, "filter": {"category": 2, "mask": 2}}]})",
      "walls");
  EXPECT_EQ(walls.segment_filters.size(), 2u);
  EXPECT_EQ(walls.segment_filters[0], (CollisionFilter{4, 5, 0}));
  EXPECT_EQ(walls.segment_filters[1], CollisionFilter{});
  EXPECT_EQ(walls.polylines[0].filter.group, 2);
  EXPECT_EQ(walls.arc_filters.size(), 1u);
  const std::string wall_text = to_json_text(walls);
  EXPECT_EQ(to_json_text(parse_scene(wall_text, "again")), wall_text);
  SceneWorld walled = make_world(walls);
  EXPECT_EQ(walled.world.wall_filter(0), (CollisionFilter{4, 5, 0}));
  EXPECT_EQ(walled.world.wall_filter(3).group, 2);  // the polyline's second segment
  EXPECT_EQ(walled.world.wall_filter(4), (CollisionFilter{1, 1, 0}));
  EXPECT_THROW(static_cast<void>(parse_scene(
                   R"({"segments": [{"a": [0, -5], "b": [0, 5]}],
                       "balls": [{"position": [0, 0], "radius": 0.5}]})")),
               SceneError);
  EXPECT_THROW(static_cast<void>(parse_scene(R"({"balls": [{"position": [0, 0],
                                    "filter": {"colour": 1}}]})")),
               SceneError);
}

}  // namespace
}  // namespace carom
