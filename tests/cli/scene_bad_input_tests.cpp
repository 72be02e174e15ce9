// `carom run` and `carom info` with bad scenes and bad outputs: one clear message on stderr
// naming where and what, exit status 2, nothing on stdout, no output file, never a crash.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>

#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

struct BadScene {
  std::string name;
  std::string text;                        // the scene file
  std::vector<std::string> message_parts;  // what the message must contain
};

void PrintTo(const BadScene& input, std::ostream* os) { *os << input.name; }

class SceneBadInput : public ::testing::TestWithParam<BadScene> {};

void expect_one_clear_error(const ToolRun& run, const std::vector<std::string>& parts) {
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  for (const std::string& part : parts) EXPECT_THAT(run.err, HasSubstr(part));
}

TEST_P(SceneBadInput, RunGivesOneMessageStatusTwoAndNoOutputFile) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "scene.json", GetParam().text);
  const std::string frames = (dir / "frames.csv").string();
  const std::string saved = (dir / "end.json").string();
  const ToolRun run =
      run_carom({"run", scene, "--until", "1", "--frames", frames, "--save", saved, "--stats"});
  expect_one_clear_error(run, GetParam().message_parts);
  EXPECT_THAT(run.err, HasSubstr("carom run: error: " + scene + ":"));
  EXPECT_FALSE(std::filesystem::exists(frames));
  EXPECT_FALSE(std::filesystem::exists(frames + ".tmp"));
  EXPECT_FALSE(std::filesystem::exists(saved));
}

TEST_P(SceneBadInput, InfoGivesTheSameMessage) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "scene.json", GetParam().text);
  const ToolRun run = run_carom({"info", scene});
  expect_one_clear_error(run, GetParam().message_parts);
}

const std::string kBox = R"("world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]})";

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneBadInput,
    ::testing::Values(
        BadScene{"MalformedJson",
                 "{\n  \"balls\": [\n    {\"position\": [1, 2],, \"radius\": 1}\n  ]\n}",
                 {"scene.json:3:25: malformed JSON", "unexpected ','"}},
        BadScene{"TruncatedJson",
                 "{\"balls\": [{\"position\": [1, 2]",
                 {"malformed JSON", "end of input"}},
        BadScene{"UnknownKey",
                 "{\"balls\": [{\"position\": [1, 2], \"radius\": 1},\n"
                 "           {\"position\": [5, 2], \"raduis\": 1}]}",
                 {"scene.json:2:33: balls[1].raduis", "unknown key", "did you mean \"radius\"?"}},
        BadScene{"UnknownTopLevelKey", "{\"bals\": []}", {"bals", "did you mean \"balls\"?"}},
        BadScene{"WrongType",
                 "{\"balls\": [{\"position\": \"here\"}]}",
                 {"balls[0].position = \"here\"", "must be an array of two numbers"}},
        BadScene{"NanAsString",
                 "{\"balls\": [{\"position\": [\"nan\", 0]}]}",
                 {"balls[0].position[0] = \"nan\"", "must be a number, not a string"}},
        BadScene{"InfinityAsString",
                 "{\"balls\": [{\"position\": [0, 0], \"velocity\": [\"inf\", 0]}]}",
                 {"balls[0].velocity[0] = \"inf\"", "must be a number"}},
        BadScene{"HugeNumber",
                 "{\"balls\": [{\"position\": [0, 0], \"velocity\": [1e400, 0]}]}",
                 {"balls[0].velocity[0] = 1e400", "beyond the range of a double"}},
        BadScene{"ZeroRadius",
                 "{\"balls\": [{\"position\": [0, 0], \"radius\": 0}]}",
                 {"balls[0].radius = 0", "must be > 0"}},
        BadScene{"NegativeMass",
                 "{\"balls\": [{\"position\": [0, 0], \"mass\": -2}]}",
                 {"balls[0].mass = -2", "must be > 0"}},
        BadScene{"RestitutionAboveOne",
                 "{\"balls\": [{\"position\": [0, 0], \"restitution\": 1.2}]}",
                 {"balls[0].restitution = 1.2", "must lie in [0, 1]"}},
        BadScene{"RestitutionNegative",
                 "{\"world\": {\"restitution\": -0.5}}",
                 {"world.restitution = -0.5", "must lie in [0, 1]"}},
        BadScene{"OverlappingBalls",
                 "{\"balls\": [{\"name\": \"cue\", \"position\": [0, 0], \"radius\": 1},\n"
                 "  {\"name\": \"eight\", \"position\": [1.5, 0], \"radius\": 1}]}",
                 {"scene.json:2:3: balls[1]", "\"eight\" overlaps balls[0] \"cue\" by 0.5"}},
        BadScene{"OverlappingUnnamedBalls",
                 "{\"balls\": [{\"position\": [0, 0]}, {\"position\": [9, 0]},"
                 " {\"position\": [0.5, 1]}]}",
                 {"balls[2] overlaps balls[0] by 0.88"}},
        BadScene{"BallOutsideBox",
                 "{" + kBox + ", \"balls\": [{\"position\": [9.5, 5]}]}",
                 {"balls[0]", "reaches outside the box [0, 10] x [0, 10]"}},
        BadScene{"BallAcrossWall",
                 "{\"segments\": [{\"a\": [0, -5], \"b\": [0, 5]}],"
                 " \"balls\": [{\"position\": [0.5, 0]}]}",
                 {"balls[0]", "lies across the wall segments[0]", "by 0.5"}},
        BadScene{
            "ImpossibleLatticePacking",
            "{" + kBox + ", \"generators\": [{\"count\": 100, \"packing_fraction\": 0.92}]}",
            {"generators[0]", "do not fit on a triangular lattice", "at most packing fraction"}},
        BadScene{"ImpossibleRandomPacking",
                 "{" + kBox +
                     ", \"generators\": [{\"placement\": \"random\", \"count\": 100,"
                     " \"packing_fraction\": 0.6}]}",
                 {"generators[0]", "random placement cannot reach packing fraction 0.6"}},
        BadScene{"GravityWithOneNumber",
                 "{\"world\": {\"boundary\": \"open\",\n  \"gravity\": [1]}}",
                 {"scene.json:2:14: world.gravity = [1]",
                  "must be an array of two numbers [x, y], not an array of 1"}},
        BadScene{
            "GravityAsAWord",
            "{\"world\": {\"gravity\": \"down\"}}",
            {"world.gravity = \"down\"", "must be an array of two numbers [x, y], not a string"}},
        BadScene{"GravityBeyondADouble",
                 "{\"world\": {\"gravity\": [0, 1e999]}}",
                 {"world.gravity[1] = 1e999", "beyond the range of a double"}},
        BadScene{"GravityInfinityAsString",
                 "{\"world\": {\"gravity\": [\"-Infinity\", 0]}}",
                 {"world.gravity[0] = \"-Infinity\"", "must be a number, not a string"}},
        BadScene{"GravityMisspelt",
                 "{\"world\": {\"gravty\": [0, -9.81]}}",
                 {"world.gravty", "unknown key", "did you mean \"gravity\"?"}},
        BadScene{"RestHeightZero",
                 "{\"world\": {\"boundary\": \"open\",\n  \"rest_height\": 0}}",
                 {"scene.json:2:18: world.rest_height = 0", "must be > 0"}},
        BadScene{"RestHeightNegative",
                 "{\"world\": {\"rest_height\": -0.01}}",
                 {"world.rest_height = -0.01", "must be > 0"}},
        BadScene{"RestHeightAsAWord",
                 "{\"world\": {\"rest_height\": \"low\"}}",
                 {"world.rest_height = \"low\"", "must be a number, not a string"}},
        BadScene{"RestHeightBeyondADouble",
                 "{\"world\": {\"rest_height\": 1e999}}",
                 {"world.rest_height = 1e999", "beyond the range of a double"}},
        BadScene{"RestHeightMisspelt",
                 "{\"world\": {\"rest_hieght\": 0.01}}",
                 {"world.rest_hieght", "unknown key", "did you mean \"rest_height\"?"}},
        BadScene{"NotAnObject", "[1, 2, 3]", {"must be an object, not an array"}}),
    [](const ::testing::TestParamInfo<BadScene>& param_info) { return param_info.param.name; });

TEST(SceneBadOutput, UnwritableOutputIsRefusedBeforeAnyWork) {
  const ScratchDir dir;
  for (const char* option : {"--frames", "--events", "--save"}) {
    const std::string path = (dir / "no-such-folder" / "out.csv").string();
    const ToolRun run =
        run_carom({"run", example("periodic-gas.json"), "--until", "100", option, path});
    expect_one_clear_error(run, {option, "cannot be written", "does not exist"});
    EXPECT_FALSE(std::filesystem::exists(dir / "no-such-folder"));
  }
}

TEST(SceneBadOutput, FramesNeedAKnownExtension) {
  const ScratchDir dir;
  const ToolRun run = run_carom({"run", example("two-moving-balls.json"), "--until", "1",
                                 "--frames", (dir / "frames.txt").string()});
  expect_one_clear_error(run, {"--frames", ".csv", ".xyz"});
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(SceneBadOutput, OutputThatIsAFolder) {
  const ScratchDir dir;
  const ToolRun run = run_carom(
      {"run", example("two-moving-balls.json"), "--until", "1", "--save", dir.path().string()});
  expect_one_clear_error(run, {"--save", "is a folder"});
}

TEST(SceneBadOutput, MissingSceneFile) {
  const ToolRun run = run_carom({"run", "/nonexistent/scene.json", "--until", "1"});
  expect_one_clear_error(run, {"/nonexistent/scene.json: cannot open"});
}

TEST(SceneBadOutput, BadRunOptions) {
  expect_one_clear_error(run_carom({"run", example("two-moving-balls.json")}),
                         {"give exactly one of --until T, --steps K"});
  expect_one_clear_error(run_carom({"run", example("two-moving-balls.json"), "--steps", "10"}),
                         {"--dt"});
  expect_one_clear_error(run_carom({"run", example("two-moving-balls.json"), "--until", "nan"}),
                         {"--until"});
  expect_one_clear_error(
      run_carom({"run", example("two-moving-balls.json"), "--steps", "3", "--dt", "-1"}),
      {"--dt", "must be > 0"});
  expect_one_clear_error(run_carom({"run", example("two-moving-balls.json"), "--collisions", "0"}),
                         {"--collisions", "at least 1"});
}

}  // namespace
}  // namespace carom::cli::test
