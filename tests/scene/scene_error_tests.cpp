// Every kind of bad scene gets one SceneError that names where (line, column, JSON path), the
// value as written and what is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "carom/scene.hpp"

namespace carom {
namespace {

using ::testing::HasSubstr;

SceneError::Details error_of(const std::string& text) {
  try {
    static_cast<void>(parse_scene(text, "test.json"));
  } catch (const SceneError& error) {
    return error.details();
  }
  ADD_FAILURE() << "no error for " << text;
  return {};
}

std::string message_of(const std::string& text) {
  try {
    static_cast<void>(parse_scene(text, "test.json"));
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(SceneErrors, MalformedJsonGivesLineAndColumn) {
  const auto d = error_of("{\n  \"balls\": [\n    {\"position\": [1, 2],, \"radius\": 1}\n  ]\n}");
  EXPECT_EQ(d.file, "test.json");
  EXPECT_EQ(d.line, 3U);
  EXPECT_EQ(d.column, 25U);  // the second comma
  EXPECT_THAT(d.problem, HasSubstr("malformed JSON"));
  EXPECT_THAT(message_of("{\n  \"balls\": [\n    {\"position\": [1, 2],, \"radius\": 1}\n  ]\n}"),
              HasSubstr("test.json:3:25: malformed JSON"));
}

TEST(SceneErrors, ColumnsCountCharactersNotBytes) {
  // "é" is two bytes in UTF-8 but one column.
  const auto d = error_of("{\"description\": \"\xc3\xa9\", x}");
  EXPECT_EQ(d.line, 1U);
  EXPECT_EQ(d.column, 22U);  // the x, the 23rd byte
}

TEST(SceneErrors, TruncatedFile) {
  const auto d = error_of("{\"balls\": [");
  EXPECT_EQ(d.line, 1U);
  EXPECT_THAT(d.problem, HasSubstr("unexpected end of input"));
}

TEST(SceneErrors, UnknownKeyNamesPathAndNearestKey) {
  const auto d = error_of(
      "{\"balls\": [{\"position\": [0, 0]}, {\"position\": [5, 0]}, {\"position\": [9, 0]},\n"
      "  {\"position\": [20, 0], \"raduis\": 2}]}");
  EXPECT_EQ(d.path, "balls[3].raduis");
  EXPECT_EQ(d.suggestion, "radius");
  EXPECT_EQ(d.line, 2U);
  EXPECT_EQ(d.column, 25U);
  EXPECT_EQ(d.problem, "unknown key");
  EXPECT_THAT(message_of("{\"wrold\": {}}"),
              HasSubstr("test.json:1:2: wrold = \"wrold\": unknown key (did you mean \"world\"?)"));
}

TEST(SceneErrors, UnknownKeyFarFromAnyGetsNoSuggestion) {
  const auto d = error_of("{\"zzzzzzzzzz\": 1}");
  EXPECT_EQ(d.suggestion, "");
}

TEST(SceneErrors, WrongType) {
  const auto d = error_of("{\"balls\": [{\"position\": [0, 0], \"radius\": \"big\"}]}");
  EXPECT_EQ(d.path, "balls[0].radius");
  EXPECT_EQ(d.value, "\"big\"");
  EXPECT_EQ(d.problem, "must be a number, not a string (JSON numbers have no NaN or infinity)");
  EXPECT_EQ(error_of("{\"balls\": {}}").problem, "must be an array, not an object");
  EXPECT_EQ(error_of("{\"balls\": [{\"position\": [0]}]}").path, "balls[0].position");
  EXPECT_EQ(error_of("[]").problem, "must be an object, not an array");
}

TEST(SceneErrors, NanAndInfinityAsStrings) {
  for (const char* spelling : {"\"nan\"", "\"NaN\"", "\"inf\"", "\"-Infinity\""}) {
    const auto d = error_of(std::string("{\"balls\": [{\"position\": [0, ") + spelling +
                            "], \"radius\": 1}]}");
    EXPECT_EQ(d.path, "balls[0].position[1]") << spelling;
    EXPECT_EQ(d.value, spelling);
    EXPECT_THAT(d.problem, HasSubstr("must be a number")) << spelling;
  }
  // Bare NaN is not JSON at all.
  EXPECT_THAT(error_of("{\"time\": NaN}").problem, HasSubstr("malformed JSON"));
}

TEST(SceneErrors, NumberBeyondDoubleRange) {
  const auto d = error_of("{\"balls\": [{\"position\": [0, 0],\n \"velocity\": [1e400, 0]}]}");
  EXPECT_EQ(d.path, "balls[0].velocity[0]");
  EXPECT_EQ(d.value, "1e400");
  EXPECT_EQ(d.line, 2U);
  EXPECT_EQ(d.column, 15U);
  EXPECT_THAT(d.problem, HasSubstr("beyond the range of a double"));
  EXPECT_EQ(error_of("{\"time\": -2e308}").path, "time");
}

TEST(SceneErrors, RadiusAndMassMustBePositive) {
  EXPECT_EQ(error_of("{\"balls\": [{\"position\": [0, 0], \"radius\": 0}]}").problem,
            "must be > 0");
  EXPECT_EQ(error_of("{\"balls\": [{\"position\": [0, 0], \"radius\": -1}]}").path,
            "balls[0].radius");
  const auto d = error_of("{\"balls\": [{\"position\": [0, 0], \"mass\": -0.5}]}");
  EXPECT_EQ(d.path, "balls[0].mass");
  EXPECT_EQ(d.value, "-0.5");
  EXPECT_EQ(d.problem, "must be > 0");
  EXPECT_THAT(error_of("{\"balls\": [{\"position\": [0, 0], \"mass\": \"heavy\"}]}").problem,
              HasSubstr("\"immovable\""));
}

TEST(SceneErrors, RestitutionOutsideUnitInterval) {
  const auto d = error_of("{\"balls\": [{\"position\": [0, 0], \"restitution\": 1.5}]}");
  EXPECT_EQ(d.path, "balls[0].restitution");
  EXPECT_EQ(d.value, "1.5");
  EXPECT_EQ(d.problem, "must lie in [0, 1]");
  EXPECT_EQ(error_of("{\"world\": {\"restitution\": -0.1}}").path, "world.restitution");
}

TEST(SceneErrors, GravityMustBeTwoFiniteNumbers) {
  const auto one = error_of("{\"world\": {\"boundary\": \"open\",\n  \"gravity\": [1]}}");
  EXPECT_EQ(one.file, "test.json");
  EXPECT_EQ(one.line, 2U);
  EXPECT_EQ(one.column, 14U);  // the value
  EXPECT_EQ(one.path, "world.gravity");
  EXPECT_EQ(one.value, "[1]");
  EXPECT_EQ(one.problem, "must be an array of two numbers [x, y], not an array of 1");
  EXPECT_EQ(message_of("{\"world\": {\"boundary\": \"open\",\n  \"gravity\": [1]}}"),
            "test.json:2:14: world.gravity = [1]: must be an array of two numbers [x, y], not an "
            "array of 1");
  EXPECT_EQ(error_of("{\"world\": {\"gravity\": [0, -9.81, 0]}}").problem,
            "must be an array of two numbers [x, y], not an array of 3");

  const auto word = error_of("{\"world\": {\"gravity\": \"down\"}}");
  EXPECT_EQ(word.path, "world.gravity");
  EXPECT_EQ(word.value, "\"down\"");
  EXPECT_EQ(word.problem, "must be an array of two numbers [x, y], not a string");
  EXPECT_THAT(error_of("{\"world\": {\"gravity\": -9.81}}").problem, HasSubstr("not a number"));

  // Beyond a double it would read as infinity.
  const auto huge = error_of("{\"world\": {\"gravity\": [0, 1e999]}}");
  EXPECT_EQ(huge.path, "world.gravity[1]");
  EXPECT_EQ(huge.value, "1e999");
  EXPECT_THAT(huge.problem, HasSubstr("beyond the range of a double"));
  EXPECT_EQ(error_of("{\"world\": {\"gravity\": [-1e999, 0]}}").path, "world.gravity[0]");
  const auto infinite = error_of("{\"world\": {\"gravity\": [0, \"-inf\"]}}");
  EXPECT_EQ(infinite.path, "world.gravity[1]");
  EXPECT_EQ(infinite.value, "\"-inf\"");
  EXPECT_EQ(infinite.problem,
            "must be a number, not a string (JSON numbers have no NaN or infinity)");
  EXPECT_EQ(error_of("{\"world\": {\"gravity\": [null, 0]}}").path, "world.gravity[0]");
}

TEST(SceneErrors, MisspeltGravityIsSuggested) {
  const auto d = error_of("{\"world\": {\"boundary\": \"open\", \"gravty\": [0, -9.81]}}");
  EXPECT_EQ(d.path, "world.gravty");
  EXPECT_EQ(d.problem, "unknown key");
  EXPECT_EQ(d.suggestion, "gravity");
  EXPECT_EQ(error_of("{\"world\": {\"Gravity\": [0, -1]}}").suggestion, "gravity");
  // The other world keys are still suggested with gravity among the known ones.
  EXPECT_EQ(error_of("{\"world\": {\"restitutoin\": 1}}").suggestion, "restitution");
}

TEST(SceneErrors, RestHeightMustBeAFiniteNumberAboveZero) {
  const auto zero = error_of("{\"world\": {\"boundary\": \"open\",\n  \"rest_height\": 0}}");
  EXPECT_EQ(zero.file, "test.json");
  EXPECT_EQ(zero.line, 2U);
  EXPECT_EQ(zero.column, 18U);  // the value
  EXPECT_EQ(zero.path, "world.rest_height");
  EXPECT_EQ(zero.value, "0");
  EXPECT_EQ(zero.problem, "must be > 0");
  EXPECT_EQ(message_of("{\"world\": {\"boundary\": \"open\",\n  \"rest_height\": 0}}"),
            "test.json:2:18: world.rest_height = 0: must be > 0");
  const auto negative = error_of("{\"world\": {\"rest_height\": -1e-3}}");
  EXPECT_EQ(negative.value, "-1e-3");
  EXPECT_EQ(negative.problem, "must be > 0");
  EXPECT_EQ(error_of("{\"world\": {\"rest_height\": -0.0}}").problem, "must be > 0");

  const auto word = error_of("{\"world\": {\"rest_height\": \"low\"}}");
  EXPECT_EQ(word.path, "world.rest_height");
  EXPECT_EQ(word.value, "\"low\"");
  EXPECT_EQ(word.problem, "must be a number, not a string (JSON numbers have no NaN or infinity)");
  EXPECT_THAT(error_of("{\"world\": {\"rest_height\": [0.001]}}").problem,
              HasSubstr("not an array"));
  EXPECT_EQ(error_of("{\"world\": {\"rest_height\": null}}").path, "world.rest_height");

  // Beyond a double it would read as infinity.
  const auto huge = error_of("{\"world\": {\"rest_height\": 1e999}}");
  EXPECT_EQ(huge.path, "world.rest_height");
  EXPECT_EQ(huge.value, "1e999");
  EXPECT_THAT(huge.problem, HasSubstr("beyond the range of a double"));
  EXPECT_EQ(error_of("{\"world\": {\"rest_height\": \"inf\"}}").path, "world.rest_height");
}

TEST(SceneErrors, MisspeltRestHeightIsSuggested) {
  const auto d = error_of("{\"world\": {\"boundary\": \"open\", \"rest_hieght\": 0.01}}");
  EXPECT_EQ(d.path, "world.rest_hieght");
  EXPECT_EQ(d.problem, "unknown key");
  EXPECT_EQ(d.suggestion, "rest_height");
  EXPECT_EQ(error_of("{\"world\": {\"restheight\": 0.01}}").suggestion, "rest_height");
  EXPECT_EQ(error_of("{\"world\": {\"rest_hight\": 0.01}}").suggestion, "rest_height");
  // Its neighbours among the world keys are still suggested for their own misspellings.
  EXPECT_EQ(error_of("{\"world\": {\"restitutoin\": 1}}").suggestion, "restitution");
  EXPECT_EQ(error_of("{\"world\": {\"gravty\": [0, -1]}}").suggestion, "gravity");
}

TEST(SceneErrors, OverlappingBallsNameBothAndTheOverlap) {
  const std::string message = message_of(
      "{\"balls\": [{\"name\": \"cue\", \"position\": [0, 0], \"radius\": 1},\n"
      "            {\"position\": [5, 0], \"radius\": 1},\n"
      "            {\"name\": \"eight\", \"position\": [1.5, 0], \"radius\": 1}]}");
  EXPECT_THAT(message, HasSubstr("test.json:3:13: balls[2] = "));
  EXPECT_THAT(message, HasSubstr("balls[2] \"eight\" overlaps balls[0] \"cue\" by 0.5"));
}

TEST(SceneErrors, BallOutsideClosedBox) {
  const auto d = error_of(
      "{\"world\": {\"boundary\": \"box\", \"lower\": [0, 0], \"upper\": [10, 10]},\n"
      " \"balls\": [{\"position\": [9.5, 5], \"radius\": 1}]}");
  EXPECT_EQ(d.path, "balls[0]");
  EXPECT_EQ(d.line, 2U);
  EXPECT_THAT(d.problem, HasSubstr("reaches outside the box [0, 10] x [0, 10]"));
}

TEST(SceneErrors, BallAcrossAWall) {
  const auto d = error_of(
      "{\"segments\": [{\"a\": [0, -5], \"b\": [0, 5]}],\n"
      " \"balls\": [{\"name\": \"a\", \"position\": [0.25, 0], \"radius\": 1}]}");
  EXPECT_EQ(d.path, "balls[0]");
  EXPECT_THAT(d.problem, HasSubstr("lies across the wall segments[0]: it overlaps it by 0.75"));
  const auto arc = error_of(
      "{\"arcs\": [{\"center\": [0, 0], \"radius\": 10, \"start_angle\": 0, \"end_angle\": 3}],\n"
      " \"balls\": [{\"position\": [0, 9.5], \"radius\": 1}]}");
  EXPECT_THAT(arc.problem, HasSubstr("arcs[0]"));
}

TEST(SceneErrors, ArcAngleBeyondTwoToTheForty) {
  const auto d = error_of(
      "{\"arcs\": [{\"center\": [0, 0], \"radius\": 10, \"start_angle\": 1e45,\n"
      " \"end_angle\": 1e45}]}");
  EXPECT_EQ(d.path, "arcs[0].start_angle");
  EXPECT_THAT(d.problem, HasSubstr("must lie in [-2^40, 2^40] radians"));
}

TEST(SceneErrors, ImpossiblePackingFraction) {
  const auto d = error_of(
      "{\"world\": {\"boundary\": \"periodic\", \"lower\": [0, 0], \"upper\": [100, 100]},\n"
      " \"generators\": [{\"count\": 1000, \"packing_fraction\": 0.95}]}");
  EXPECT_EQ(d.path, "generators[0]");
  EXPECT_EQ(d.line, 2U);
  EXPECT_THAT(d.problem, HasSubstr("do not fit on a triangular lattice"));
  const auto random = error_of(
      "{\"world\": {\"boundary\": \"box\", \"lower\": [0, 0], \"upper\": [100, 100]},\n"
      " \"generators\": [{\"placement\": \"random\", \"count\": 1000, \"packing_fraction\": "
      "0.7}]}");
  EXPECT_THAT(random.problem, HasSubstr("random placement cannot reach packing fraction 0.7"));
  EXPECT_EQ(error_of("{\"generators\": [{\"count\": 10, \"packing_fraction\": 1.5}]}").problem,
            "must lie in (0, 1)");
  EXPECT_THAT(error_of("{\"generators\": [{\"count\": 10, \"radius\": 1}]}").problem,
              HasSubstr("needs a region"));
}

TEST(SceneErrors, DuplicateNames) {
  const auto d = error_of(
      "{\"balls\": [{\"name\": \"a\", \"position\": [0, 0]}, {\"name\": \"a\", \"position\": [5, "
      "0]}]}");
  EXPECT_EQ(d.path, "balls[1].name");
  EXPECT_THAT(d.problem, HasSubstr("taken already by balls[0]"));
}

TEST(SceneErrors, GeneratedNamesMayNotRepeat) {
  // A generator names its balls NAME#i: two generators of one name, or a ball named like a
  // generated one, would give two balls one name, and the saved scene would not load.
  const std::string generator =
      R"({"name": "a", "count": 3, "radius": 1, "region": {"lower": [0, 0], "upper": [50, 50]}})";
  const auto twice = error_of(R"({"generators": [)" + generator + ", " + generator + "]}");
  EXPECT_EQ(twice.path, "generators[1].name");
  EXPECT_THAT(twice.problem, HasSubstr("taken already by generators[0]"));
  const auto ball = error_of(R"({"balls": [{"name": "a#2", "position": [60, 60]}],
                                "generators": [)" +
                             generator + "]}");
  EXPECT_EQ(ball.path, "balls[0].name");
  EXPECT_THAT(ball.problem, HasSubstr("taken already by generators[0]'s ball 2"));
  // Names the generator does not write are free: past its count, or with a leading zero.
  for (const char* free : {"a#3", "a#02", "a#", "a#x", "b#0"}) {
    EXPECT_NO_THROW(static_cast<void>(parse_scene(R"({"balls": [{"name": ")" + std::string(free) +
                                                  R"(", "position": [60, 60]}],
                                "generators": [)" +
                                                  generator + "]}")))
        << free;
  }
}

TEST(SceneErrors, GrowthRateIsNonNegativeAndNotWithGravity) {
  const auto negative = error_of(R"({"world": {"growth_rate": -0.5}})");
  EXPECT_EQ(negative.path, "world.growth_rate");
  const auto with_gravity = error_of(R"({"world": {"growth_rate": 0.5, "gravity": [0, -1]}})");
  EXPECT_EQ(with_gravity.path, "world.growth_rate");
  EXPECT_THAT(with_gravity.problem, HasSubstr("grow or fall"));
}

TEST(SceneErrors, ThermostatTakesATemperatureAndOneInterval) {
  EXPECT_EQ(error_of(R"({"thermostat": {"temperature": 0, "interval": 1}})").path,
            "thermostat.temperature");
  const auto both = error_of(R"({"thermostat": {"interval": 1, "collisions": 5}})");
  EXPECT_EQ(both.path, "thermostat.collisions");
  EXPECT_THAT(both.problem, HasSubstr("exactly one of interval and collisions"));
  EXPECT_EQ(error_of(R"({"thermostat": {"temperature": 1}})").path, "thermostat.interval");
  EXPECT_EQ(error_of(R"({"thermostat": {"interval": -1}})").path, "thermostat.interval");
  EXPECT_EQ(error_of(R"({"thermostat": {"collisions": 0}})").path, "thermostat.collisions");
  EXPECT_EQ(error_of(R"({"thermostat": {"collisions": 1.5}})").path, "thermostat.collisions");
  const auto unknown = error_of(R"({"thermostat": {"interval": 1, "temprature": 2}})");
  EXPECT_EQ(unknown.path, "thermostat.temprature");
  EXPECT_EQ(unknown.suggestion, "temperature");
}

TEST(SceneErrors, MissingField) {
  const auto d = error_of("{\"balls\": [{\"radius\": 1}]}");
  EXPECT_EQ(d.path, "balls[0].position");
  EXPECT_EQ(d.problem, "is missing");
  EXPECT_EQ(d.column, 12U);  // located at the object that lacks it
}

TEST(SceneErrors, UnreadableFile) {
  try {
    static_cast<void>(load_scene("/nonexistent/scene.json"));
    FAIL();
  } catch (const SceneError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("/nonexistent/scene.json: cannot open"));
  }
}

}  // namespace
}  // namespace carom
