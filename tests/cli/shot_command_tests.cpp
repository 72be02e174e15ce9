// `carom shot`: a cue strike on a pool scene run until every ball rests — the summary, the events
// (ending at the rest), the end state at rest, the picture, the same bytes twice, and mistakes
// named by their option.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

TEST(ShotCommand, AStrikeRunsUntilEveryBallRests) {
  const ScratchDir dir;
  const std::string events = (dir / "shot.jsonl").string();
  const std::string end = (dir / "end.json").string();
  const std::vector<std::string> args{"shot",     example("billiards.json"),
                                      "--ball",   "cue",
                                      "--speed",  "3",
                                      "--side",   "0.01",
                                      "--height", "-0.01",
                                      "--events", events,
                                      "--save",   end,
                                      "--json"};
  const ToolRun run = run_carom(args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto summary = nlohmann::json::parse(run.out);
  EXPECT_TRUE(summary["at_rest"].get<bool>());
  EXPECT_GT(summary["ball_ball"].get<int>(), 10);
  // The last event is the last ball coming to rest, at the summary's time.
  const std::string text = read_file(events);
  const std::string last_line = text.substr(text.rfind('\n', text.size() - 2) + 1);
  const auto last = nlohmann::json::parse(last_line);
  EXPECT_EQ(last["kind"], "motion");
  EXPECT_EQ(last["to"], "stationary");
  EXPECT_EQ(last["time"].get<double>(), summary["rest_time"].get<double>());
  const auto scene = nlohmann::json::parse(read_file(end));
  EXPECT_FALSE(scene.contains("shots"));
  EXPECT_EQ(scene["balls"].size(), summary["balls_on_table"].get<std::size_t>());
  for (const auto& ball : scene["balls"]) {
    EXPECT_EQ(ball["velocity"], nlohmann::json::parse("[0, 0]")) << ball;
  }
  // The same shot again: the same events, byte for byte.
  std::vector<std::string> again = args;
  again[11] = (dir / "again.jsonl").string();
  again[13] = (dir / "again.json").string();
  ASSERT_EQ(run_carom(again).exit_code, 0);
  EXPECT_EQ(read_file(dir / "again.jsonl"), text);
}

TEST(ShotCommand, DrawsTheTableWithThePaths) {
  const ScratchDir dir;
  const std::string png = (dir / "shot.png").string();
  const ToolRun run = run_carom({"shot", example("billiards.json"), "--ball", "cue", "--speed", "2",
                                 "--out", png, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(read_file(png).substr(1, 3), "PNG");
  const std::string svg = (dir / "shot.svg").string();
  ASSERT_EQ(run_carom({"shot", example("billiards.json"), "--ball", "cue", "--speed", "2", "--out",
                       svg, "--quiet"})
                .exit_code,
            0);
  EXPECT_THAT(read_file(svg), HasSubstr("<polyline"));
}

TEST(ShotCommand, MistakesAreNamedByTheirOption) {
  const auto error_of = [](std::vector<std::string> args) {
    args.insert(args.begin(), "shot");
    const ToolRun run = run_carom(args);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    return run.err;
  };
  const std::string scene = example("billiards.json");
  EXPECT_THAT(error_of({example("billiards-frictionless.json"), "--ball", "cue", "--speed", "1"}),
              HasSubstr("world.table"));
  EXPECT_THAT(error_of({scene, "--ball", "eight", "--speed", "1"}),
              HasSubstr("--ball \"eight\": names no ball"));
  EXPECT_THAT(error_of({scene, "--ball", "cue", "--speed", "1", "--side", "0.03"}),
              HasSubstr("--side \"0.03\": must meet the ball"));
  EXPECT_THAT(error_of({scene, "--ball", "cue", "--speed", "-1"}), HasSubstr("--speed"));
  EXPECT_THAT(error_of({scene, "--ball", "cue"}), HasSubstr("--speed"));
  EXPECT_THAT(error_of({scene, "--ball", "cue", "--speed", "1", "--out", "table.jpg"}),
              HasSubstr("--out"));
}

}  // namespace
}  // namespace carom::cli::test
