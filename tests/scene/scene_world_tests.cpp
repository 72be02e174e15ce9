// Building worlds from scenes: the balls and walls arrive as written, generators place what they
// promise, pockets swallow balls, and a captured world continues exactly.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "carom/scene.hpp"

namespace carom {
namespace {

TEST(SceneWorld, TwoBallsMeetWhenTheyShould) {
  const Scene scene = parse_scene(R"({
    "balls": [{"name": "a", "position": [0, 0], "velocity": [1, 0], "radius": 1},
              {"name": "b", "position": [10, 0], "velocity": [-1, 0], "radius": 1}]})");
  SceneWorld sw = make_world(scene);
  ASSERT_EQ(sw.balls.size(), 2U);
  EXPECT_EQ(sw.by_name.at("b"), sw.balls[1]);
  std::vector<ContactEvent> contacts;
  step_scene(sw, 10.0, &contacts);
  ASSERT_EQ(contacts.size(), 1U);
  // Gap 8 closed at relative speed 2: t = 4 exactly.
  EXPECT_EQ(contacts[0].time, 4.0);
  EXPECT_EQ(sw.index_of(contacts[0].a), 0U);
}

TEST(SceneWorld, LatticeGeneratorReachesItsPackingFraction) {
  const Scene scene = parse_scene(R"({
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [50, 40]},
    "generators": [{"count": 500, "packing_fraction": 0.6,
                    "velocity": {"distribution": "maxwell_boltzmann", "temperature": 2,
                                 "zero_momentum": true}}]})");
  const std::vector<SceneBall> balls = expand_balls(scene);
  ASSERT_EQ(balls.size(), 500U);
  const SceneSummary s = summarize(scene, balls);
  // The radius is solved from φ, so φ comes back to rounding (relative 1e-12 is generous).
  EXPECT_NEAR(*s.packing_fraction, 0.6, 1e-12);
  EXPECT_GE(*s.smallest_gap, 0.0);
  // Momentum removed: zero up to the rounding of 500 additions of O(1) values.
  EXPECT_LT(length(s.momentum), 1e-12);
  // Equipartition: E = N·T (two degrees of freedom, k = 1) within sampling error; the relative
  // standard deviation of the sum of 1000 squared normals is sqrt(2/1000) ≈ 0.045, so 5 sigma.
  EXPECT_NEAR(s.kinetic_energy / 500.0, 2.0, 2.0 * 5 * 0.045);
  SceneWorld sw = make_world(scene);
  step_scene(sw, 1.0);
  EXPECT_FALSE(sw.world.audit().has_value());
}

TEST(SceneWorld, GeneratorsAreDeterministic) {
  const std::string text = R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [30, 30]},
    "generators": [{"placement": "random", "count": 100, "radius": 0.8, "seed": 4,
                    "velocity": {"distribution": "uniform_direction", "speed": 3}},
                   {"placement": "random", "count": 200, "radius": 0.3, "seed": 5}]})";
  const std::vector<SceneBall> a = expand_balls(parse_scene(text));
  const std::vector<SceneBall> b = expand_balls(parse_scene(text));
  ASSERT_EQ(a.size(), 300U);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i].position.x),
              std::bit_cast<std::uint64_t>(b[i].position.x));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i].velocity.y),
              std::bit_cast<std::uint64_t>(b[i].velocity.y));
  }
  EXPECT_NEAR(length(a[7].velocity), 3.0, 1e-14);
  const SceneSummary s = summarize(parse_scene(text), a);
  EXPECT_GE(*s.smallest_gap, 0.0);
}

TEST(SceneWorld, PocketSwallowsTheBallThatTouchesIt) {
  const Scene scene = parse_scene(R"({
    "balls": [{"name": "cue", "position": [0, 0], "velocity": [2, 0], "radius": 1},
              {"name": "far", "position": [0, 50], "radius": 1}],
    "pockets": [{"name": "p", "position": [10, 0], "radius": 2}]})");
  SceneWorld sw = make_world(scene);
  std::vector<PottedBall> potted;
  const double advanced = step_scene(sw, 10.0, nullptr, &potted);
  EXPECT_EQ(advanced, 10.0);
  ASSERT_EQ(potted.size(), 1U);
  // Gap 10 - 3 = 7 closed at speed 2 (to the sensor's hysteresis margin, 2^-40 of the
  // coordinates over the speed: world.md, "Sensors").
  EXPECT_NEAR(potted[0].time, 3.5, 1e-11);
  EXPECT_EQ(potted[0].ball, 0U);
  EXPECT_TRUE(sw.balls[0].is_null());
  const Scene after = capture_scene(sw);
  ASSERT_EQ(after.balls.size(), 1U);
  EXPECT_EQ(after.balls[0].name, "far");
  EXPECT_EQ(after.time, 10.0);
  EXPECT_EQ(after.pockets.size(), 1U);
}

TEST(SceneWorld, CapturedSceneContinuesTheRun) {
  const std::string text = R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 20]},
    "generators": [{"placement": "random", "count": 60, "radius": 0.7, "seed": 11,
                    "velocity": {"distribution": "uniform_direction", "speed": 2}}]})";
  SceneWorld whole = make_world(parse_scene(text));
  step_scene(whole, 2.0);
  SceneWorld first = make_world(parse_scene(text));
  step_scene(first, 1.0);
  // Through text, as `carom run --save` then `carom run` on the saved file.
  SceneWorld second = make_world(parse_scene(to_json_text(capture_scene(first))));
  step_scene(second, 1.0);
  EXPECT_EQ(second.time(), 2.0);
  // A restarted world forgets each ball's local clock, so positions may differ by rounding from
  // one long run (docs/world.md); the physics must agree to a few ulps of the box size.
  for (std::size_t i = 0; i < whole.balls.size(); ++i) {
    const Vec2 a = whole.world.position(whole.balls[i]);
    const Vec2 b = second.world.position(second.balls[i]);
    EXPECT_NEAR(a.x, b.x, 1e-9) << i;
    EXPECT_NEAR(a.y, b.y, 1e-9) << i;
  }
}

// A growing gas with a thermostat: its steps fall at the interval's multiples of the scene
// clock (so a run ending on one ends at kT exactly), take out the energy growth put in, and a run
// cut in pieces takes the same steps as one that is not (to rounding: where a run stops, the world
// brings its balls to that time).
TEST(SceneWorld, ThermostatStepsAtItsIntervalAndHoldsTheTemperature) {
  const std::string text = R"({
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [20, 20], "growth_rate": 0.1},
    "time": 0.25,
    "thermostat": {"temperature": 2, "interval": 0.5},
    "generators": [{"placement": "random", "count": 80, "radius": 0.5, "seed": 3,
                    "velocity": {"distribution": "maxwell_boltzmann", "temperature": 2,
                                 "zero_momentum": true}}]})";
  SceneWorld whole = make_world(parse_scene(text));
  run_scene_until(whole, 2.75);  // scene time 3.0, a multiple of 0.5
  EXPECT_NEAR(whole.world.kinetic_energy(), 80.0 * 2.0, 1e-9);
  EXPECT_LT(whole.thermostat_work, 0.0);
  SceneWorld pieces = make_world(parse_scene(text));
  for (const double dt : {0.1, 0.4, 0.5, 0.33, 1.42}) step_scene(pieces, dt);
  ASSERT_EQ(pieces.world.time(), whole.world.time());
  EXPECT_NEAR(pieces.thermostat_work, whole.thermostat_work, 1e-9);
  EXPECT_NEAR(pieces.world.kinetic_energy(), 80.0 * 2.0, 1e-9);
  for (std::size_t i = 0; i < whole.balls.size(); ++i) {
    EXPECT_LT(length(pieces.world.position(pieces.balls[i]) - whole.world.position(whole.balls[i])),
              1e-9);
  }
  // Without the thermostat the same run heats up.
  std::string hot = text;
  const std::string thermostat = R"("thermostat": {"temperature": 2, "interval": 0.5},)";
  hot.erase(hot.find(thermostat), thermostat.size());
  SceneWorld heated = make_world(parse_scene(hot));
  run_scene_until(heated, 2.75);
  EXPECT_GT(heated.world.kinetic_energy(), 80.0 * 2.0 * 1.01);
}

TEST(SceneWorld, ThermostatByCollisionsStepsAtTheCountsMultiples) {
  const std::string text = R"({
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [20, 20], "growth_rate": 0.1},
    "thermostat": {"temperature": 1, "collisions": 100},
    "generators": [{"placement": "random", "count": 80, "radius": 0.5, "seed": 3,
                    "velocity": {"distribution": "maxwell_boltzmann", "temperature": 1}}]})";
  SceneWorld sw = make_world(parse_scene(text));
  EXPECT_EQ(run_scene_collisions(sw, 1000), 1000U);
  EXPECT_EQ(sw.world.collision_count() % 100, 0U);
  // Scaled about the centre of mass: K − P²/(2M) is N·kT.
  const Vec2 p = sw.world.momentum();
  EXPECT_NEAR(sw.world.kinetic_energy() - dot(p, p) / (2.0 * 80.0), 80.0, 1e-9);
  const double work = sw.thermostat_work;
  EXPECT_LT(work, 0.0);
  run_scene_until(sw, sw.world.time() + 1.0);
  EXPECT_NE(sw.thermostat_work, work);
}

}  // namespace
}  // namespace carom

namespace carom {
namespace {

TEST(SceneWorld, OverlapsOfARoundingAreTouchingAndGetSeparated) {
  // A saved mid-run state may hold pairs that overlap by a rounding; they load, and the world is
  // built with the later ball moved clear by a rounding. A real overlap is still an error.
  const Scene scene = parse_scene(R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]},
    "segments": [{"a": [5, 0], "b": [5, 3]}],
    "balls": [{"position": [2, 6], "radius": 1},
              {"position": [3.9999999999999, 6], "radius": 1},
              {"position": [9.0000000000001, 9], "radius": 1},
              {"position": [6.0000000000000, 2], "radius": 1.0000000000001}]})");
  SceneWorld built = make_world(scene);
  EXPECT_EQ(built.world.ball_count(), 4U);
  EXPECT_FALSE(built.world.audit(0.0).has_value());
  // Moved by about twice the overlap, no more.
  EXPECT_NEAR(built.world.position(built.balls[1]).x, 4.0, 1e-12);
  // Untouched balls keep their position exactly.
  EXPECT_EQ(built.world.position(built.balls[0]).x, 2.0);
  EXPECT_THROW(static_cast<void>(
                   parse_scene(R"({"balls": [{"position": [0, 0]}, {"position": [1.99999, 0]}]})")),
               SceneError);
}

TEST(SceneWorld, ASettledPileSavedAsASceneLoadsBack) {
  // Every ball of a settled pile touches several others, the floor or a side to a rounding:
  // moving one clear of one pair moves it onto another, so separation repeats until none is left.
  std::string balls;
  for (int i = 0; i < 120; ++i) {
    if (i > 0) balls += ",";
    balls += "{\"position\": [" + std::to_string(1.0 + 2.0 * (i % 9) + 0.3 * (i / 9 % 2)) + ", " +
             std::to_string(1.5 + 2.0 * (i / 9)) +
             "], \"radius\": " + std::to_string(0.5 + 0.1 * (i % 3)) + "}";
  }
  const Scene scene = parse_scene(
      R"({"world": {"boundary": "box", "lower": [0, 0], "upper": [20, 60], "restitution": 0.5,
                    "gravity": [0, -9.81]}, "balls": [)" +
      balls + "]}");
  SceneWorld poured = make_world(scene);
  run_scene_until(poured, 15.0);
  const Scene saved = parse_scene(to_json_text(capture_scene(poured)));
  SceneWorld loaded = make_world(saved);
  EXPECT_EQ(loaded.world.ball_count(), 120U);
  EXPECT_FALSE(loaded.world.audit(0.0).has_value());
  // Moved by roundings only.
  for (std::size_t i = 0; i < 120; ++i) {
    EXPECT_NEAR(loaded.world.position(loaded.balls[i]).x, poured.world.position(poured.balls[i]).x,
                1e-12);
    EXPECT_NEAR(loaded.world.position(loaded.balls[i]).y, poured.world.position(poured.balls[i]).y,
                1e-12);
  }
}

TEST(SceneWorld, AGrowingSceneSavedMidwayContinuesTheSameGrowth) {
  const Scene scene = parse_scene(R"({
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [30, 30], "growth_rate": 0.1},
    "balls": [{"position": [5, 5], "velocity": [1, 0.5], "radius": 1},
              {"position": [20, 12], "velocity": [-0.5, 1], "radius": 0.5}]})");
  EXPECT_EQ(scene.world.growth_rate, 0.1);
  SceneWorld grown = make_world(scene);
  run_scene_until(grown, 2.0);
  EXPECT_NEAR(grown.world.radius(grown.balls[0]), 1.2, 1e-15);
  // Saved at t = 2: the radii of now and the rate relative to them, 0.1 / 1.2.
  const Scene saved = parse_scene(to_json_text(capture_scene(grown)));
  EXPECT_DOUBLE_EQ(saved.world.growth_rate, 0.1 / 1.2);
  EXPECT_EQ(saved.balls[1].radius, grown.world.radius(grown.balls[1]));
  SceneWorld continued = make_world(saved);
  run_scene_until(continued, 3.0);  // world time: scene time 5
  run_scene_until(grown, 5.0);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(continued.world.radius(continued.balls[i]), grown.world.radius(grown.balls[i]),
                1e-14);
  }
  EXPECT_NEAR(grown.world.radius(grown.balls[0]), 1.5, 1e-14);
}

// The scene's gravity is the world's, and the summary's potential energy is the world's: −Σ m·g·p
// over movable balls (the immovable ball and the pocket do not count).
TEST(SceneWorld, GravityReachesTheWorldAndTheSummary) {
  const Scene scene = parse_scene(R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 40], "gravity": [0.5, -9.81]},
    "balls": [{"position": [3, 4], "velocity": [1, 2], "mass": 2},
              {"position": [10, 30], "radius": 0.5},
              {"position": [15, 10], "mass": "immovable"}],
    "pockets": [{"position": [18, 38]}]})");
  const SceneSummary s = summarize(scene, expand_balls(scene));
  const double expected = -(2.0 * (0.5 * 3.0 - 9.81 * 4.0) + 1.0 * (0.5 * 10.0 - 9.81 * 30.0));
  EXPECT_DOUBLE_EQ(s.potential_energy, expected);
  EXPECT_DOUBLE_EQ(s.kinetic_energy, 5.0);
  const SceneWorld sw = make_world(scene);
  EXPECT_EQ(sw.world.def().gravity, (Vec2{0.5, -9.81}));
  EXPECT_DOUBLE_EQ(sw.world.potential_energy(), expected);

  const Scene flat = parse_scene(R"({"balls": [{"position": [3, 4], "velocity": [1, 0]}]})");
  EXPECT_EQ(summarize(flat, expand_balls(flat)).potential_energy, 0.0);
  const SceneWorld flat_world = make_world(flat);
  EXPECT_EQ(flat_world.world.def().gravity, Vec2{});
  EXPECT_EQ(flat_world.world.potential_energy(), 0.0);
}

// World::set_gravity between steps is what a captured scene (`carom run --save`) holds.
TEST(SceneWorld, CapturedSceneHoldsTheGravityNow) {
  SceneWorld sw = make_world(parse_scene(R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10], "gravity": [0, -9.81]},
    "balls": [{"position": [5, 5]}]})"));
  EXPECT_EQ(capture_scene(sw).world.gravity, (Vec2{0.0, -9.81}));
  sw.world.set_gravity({1.5, -0.25});
  const Scene captured = capture_scene(sw);
  EXPECT_EQ(captured.world.gravity, (Vec2{1.5, -0.25}));
  const SceneWorld again = make_world(parse_scene(to_json_text(captured)));
  EXPECT_EQ(again.world.def().gravity, (Vec2{1.5, -0.25}));
  sw.world.set_gravity({});
  EXPECT_EQ(to_json_text(capture_scene(sw)).find("gravity"), std::string::npos);
}

// The scene's rest height is the world's, and a captured scene records the one the world ran with.
TEST(SceneWorld, RestHeightReachesTheWorldAndTheCapturedScene) {
  SceneWorld sw = make_world(parse_scene(R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10], "gravity": [0, -9.81],
              "rest_height": 0.02},
    "balls": [{"position": [5, 5]}]})"));
  EXPECT_EQ(sw.world.def().rest_height, 0.02);
  const Scene captured = capture_scene(sw);
  EXPECT_EQ(captured.world.rest_height, 0.02);
  EXPECT_NE(to_json_text(captured).find("\"rest_height\": 0.02}"), std::string::npos);
  const SceneWorld again = make_world(parse_scene(to_json_text(captured)));
  EXPECT_EQ(again.world.def().rest_height, 0.02);

  const SceneWorld plain = make_world(parse_scene(R"({"balls": [{"position": [3, 4]}]})"));
  EXPECT_EQ(plain.world.def().rest_height, WorldDef{}.rest_height);
  EXPECT_EQ(to_json_text(capture_scene(plain)).find("rest_height"), std::string::npos);
}

// A ball dropped inelastically on the floor comes to rest once a bounce would rise less than the
// rest height: a larger rest height stops it sooner, in fewer contacts, and both end at rest.
TEST(SceneWorld, LargerRestHeightSettlesABouncingBallSooner) {
  const auto contacts_to_rest = [](const char* rest_height) {
    SceneWorld sw = make_world(parse_scene(std::string(R"({
      "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10], "restitution": 0.5,
                "gravity": [0, -9.81])") + rest_height +
                                           R"(},
      "balls": [{"position": [5, 5], "radius": 0.5}]})"));
    std::vector<ContactEvent> contacts;
    step_scene(sw, 10.0, &contacts);
    EXPECT_EQ(sw.world.velocity(sw.balls[0]), Vec2{}) << rest_height;
    EXPECT_NEAR(sw.world.position(sw.balls[0]).y, 0.5, 1e-9) << rest_height;
    return contacts.size();
  };
  const std::size_t by_default = contacts_to_rest("");
  const std::size_t coarse = contacts_to_rest(R"(, "rest_height": 0.1)");
  EXPECT_LT(coarse, by_default);
  EXPECT_GE(coarse, 1U);
}

}  // namespace
}  // namespace carom
