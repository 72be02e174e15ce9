// `carom run` on a table: without --until, --steps or --collisions it runs until every ball rests
// and every shot is struck; --events holds each change of motion state in its place; a run to rest
// stopped at a checkpoint and resumed ends byte for byte as the one never stopped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

TEST(RunTable, ABreakRunsUntilEveryBallRests) {
  const ScratchDir dir;
  const std::string events = (dir / "break.jsonl").string();
  const std::string end = (dir / "end.json").string();
  const ToolRun run = run_carom({"run", example("billiards.json"), "--events", events, "--save",
                                 end, "--stats", "--json", "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_GT(stats["collisions"].get<std::uint64_t>(), 16U);
  EXPECT_GT(stats["end_time"].get<double>(), 1.0);

  // Every ball of the end state (less those potted) still, no spin left and no shot to come.
  const auto scene = nlohmann::json::parse(read_file(end));
  EXPECT_FALSE(scene.contains("shots"));
  EXPECT_EQ(scene["balls"].size() + stats["potted"].get<std::size_t>(), 16U);
  EXPECT_GE(scene["balls"].size(), 1U);
  for (const auto& ball : scene["balls"]) {
    EXPECT_EQ(ball["velocity"], nlohmann::json::parse("[0, 0]")) << ball;
    EXPECT_FALSE(ball.contains("spin")) << ball;
  }

  // The events in time order, the changes of state among the contacts, each ball's last one to
  // rest.
  std::istringstream lines(read_file(events));
  std::string line;
  double previous = 0.0;
  std::size_t motions = 0;
  std::map<std::size_t, std::string> last_state;
  while (std::getline(lines, line)) {
    const auto event = nlohmann::json::parse(line);
    EXPECT_GE(event["time"].get<double>(), previous) << line;
    previous = event["time"].get<double>();
    if (event["kind"] == "motion") {
      ++motions;
      EXPECT_NE(event["from"], event["to"]) << line;
      last_state[event["ball"].get<std::size_t>()] = event["to"].get<std::string>();
    }
  }
  EXPECT_GT(motions, 16U);
  EXPECT_GE(last_state.size(), 10U);  // the break moves most of the rack
  // (A potted ball leaves the table sliding or rolling; every other ball's last state is rest.)
  std::size_t moving_at_the_end = 0;
  for (const auto& [ball, state] : last_state) moving_at_the_end += state != "stationary" ? 1U : 0U;
  EXPECT_LE(moving_at_the_end, stats["potted"].get<std::size_t>());
  // (The run ends when its queue runs dry: at or after the last ball's coming to rest, where a
  // contact predicted before it stopped falls due and is found stale.)
  EXPECT_LE(previous, stats["end_time"].get<double>());
}

TEST(RunTable, ASceneOffATableStillNeedsAMode) {
  const ToolRun run = run_carom({"run", example("billiards-frictionless.json"), "--quiet"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("world.table"));
}

TEST(RunTable, ARunToRestResumedFromACheckpointEndsByteForByte) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "break.ckpt").string();
  const ToolRun first =
      run_carom({"run", example("billiards.json"), "--every", "0.1", "--frames",
                 (dir / "first.csv").string(), "--checkpoint", checkpoint, "--checkpoint-every",
                 "2", "--save", (dir / "first.json").string(), "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ASSERT_TRUE(std::filesystem::exists(checkpoint + ".prev"));
  const ToolRun resumed = run_carom({"run", "--resume", checkpoint + ".prev", "--every", "0.1",
                                     "--frames", (dir / "resumed.csv").string(), "--save",
                                     (dir / "resumed.json").string(), "--quiet"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::string first_end = read_file(dir / "first.json");
  ASSERT_FALSE(first_end.empty());
  EXPECT_EQ(read_file(dir / "resumed.json"), first_end);
  // The resumed frames are the first run's last ones.
  const std::string first_frames = read_file(dir / "first.csv");
  const std::string resumed_frames = read_file(dir / "resumed.csv");
  const std::string resumed_rows = resumed_frames.substr(resumed_frames.find('\n') + 1);
  ASSERT_FALSE(resumed_rows.empty());
  EXPECT_EQ(first_frames.substr(first_frames.size() - resumed_rows.size()), resumed_rows);
}

}  // namespace
}  // namespace carom::cli::test
