// `carom run`: the three ways to advance, the outputs it writes (frames, events, end state,
// summary), and Ctrl-C leaving complete files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(RunCommand, TwoBallsUntilWithStatsAsJson) {
  const ToolRun run =
      run_carom({"run", example("two-moving-balls.json"), "--until", "2", "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["collisions"], 1);  // they touch once, at t = 0.58347, and fly apart
  EXPECT_EQ(stats["end_time"], 2.0);
  EXPECT_EQ(stats["interrupted"], false);
  // One elastic bounce: energy and momentum are kept to a few roundings.
  EXPECT_LT(std::abs(stats["energy_change"].get<double>()), 1e-15);
  EXPECT_LT(stats["momentum_change"].get<double>(), 1e-15);
}

TEST(RunCommand, FramesAsCsvAtTheAskedTimes) {
  const ScratchDir dir;
  const std::string frames = (dir / "cradle.csv").string();
  const ToolRun run = run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--frames",
                                 frames, "--every", "2.5", "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  const std::vector<std::string> lines = lines_of(read_file(frames));
  // A header, then frames at 0, 2.5, 5, 7.5 and 10 of six balls each.
  ASSERT_EQ(lines.size(), 1U + 5U * 6U);
  EXPECT_EQ(lines[0], "time,index,name,x,y,vx,vy,radius");
  EXPECT_EQ(lines[1], "0,0,striker,3,3,2,0,1");
  EXPECT_THAT(lines[7], ::testing::StartsWith("2.5,0,striker,8,3,2,0,1"));
  // By t = 10 the striker has stopped at x = 10 and ball 5 moves at 2 (the chain reached it at
  // 3.5; it had 40 - 1 - 20 = 19 units of room, so it has not met the wall yet at 10 - 3.5).
  EXPECT_EQ(lines[25], "10,0,striker,10,3,0,0,1");
  EXPECT_THAT(lines[30], ::testing::StartsWith("10,5,ball5,33,3,2,0,1"));
  EXPECT_FALSE(std::filesystem::exists(frames + ".tmp"));
}

TEST(RunCommand, FramesAsExtendedXyz) {
  const ScratchDir dir;
  const std::string frames = (dir / "box.xyz").string();
  const ToolRun run = run_carom({"run", example("box-of-1000.json"), "--steps", "3", "--dt", "0.5",
                                 "--frames", frames, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> lines = lines_of(read_file(frames));
  // Four frames (start and each step) of a count line, a comment line and 1000 balls.
  ASSERT_EQ(lines.size(), 4U * 1002U);
  EXPECT_EQ(lines[0], "1000");
  EXPECT_THAT(lines[1], HasSubstr("Lattice=\"100 0 0 0 100 0 0 0 1\""));
  EXPECT_THAT(lines[1], HasSubstr("Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:index:I:1"));
  EXPECT_THAT(lines[1], HasSubstr("pbc=\"F F F\""));
  EXPECT_THAT(lines[1 + 1002], HasSubstr("Time=0.5"));
  EXPECT_THAT(lines[2], ::testing::StartsWith("big "));
  std::istringstream row(lines[2]);
  std::string species;
  double x = 0;
  double y = 0;
  double z = 1;
  row >> species >> x >> y >> z;
  EXPECT_EQ(z, 0.0);
  EXPECT_GE(x, 0.0);
  EXPECT_LE(x, 100.0);
}

TEST(RunCommand, EventsAsJsonLinesIncludingPotting) {
  const ScratchDir dir;
  const std::string events = (dir / "events.jsonl").string();
  const ToolRun run = run_carom({"run", example("billiards-frictionless.json"), "--until", "10",
                                 "--events", events, "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  const std::vector<std::string> lines = lines_of(read_file(events));
  // Every contact and every potting (a pocket's sensor taking a ball: no contact) is a line.
  EXPECT_EQ(lines.size(),
            stats["collisions"].get<std::size_t>() + stats["potted"].get<std::size_t>());
  std::size_t potted = 0;
  double last_time = 0.0;
  for (const std::string& line : lines) {
    const auto event = nlohmann::json::parse(line);
    EXPECT_GE(event["time"].get<double>(), last_time);  // in time order
    last_time = event["time"].get<double>();
    if (event["kind"] == "potted") {
      ++potted;
      EXPECT_TRUE(event.contains("pocket"));
    }
  }
  EXPECT_EQ(potted, stats["potted"].get<std::size_t>());
  EXPECT_GT(potted, 0U);
  EXPECT_EQ(stats["balls_at_end"].get<std::size_t>(), 16U - potted);
}

TEST(RunCommand, EventsIncludeSensorsInOrderAndAPocketSensorRemovesTheBall) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "gate.json", R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 10]},
    "balls": [{"position": [2, 5], "velocity": [4, 0], "radius": 0.5},
              {"position": [2, 2], "velocity": [0, 0], "radius": 0.5}],
    "sensors": [{"name": "gate", "shape": "segment", "a": [6, 0], "b": [6, 10]},
                {"shape": "disc", "center": [17, 5], "radius": 0.3, "action": "remove_ball"}]})");
  const ToolRun info = run_carom({"info", scene});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("sensors           2"));
  const std::string events = (dir / "events.jsonl").string();
  const ToolRun run =
      run_carom({"run", scene, "--until", "5", "--events", events, "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["balls_at_end"].get<std::size_t>(), 1U);
  const std::vector<std::string> lines = lines_of(read_file(events));
  ASSERT_EQ(lines.size(), 3U);  // no contact: the gate's enter and exit, the pocket's enter
  const auto enter = nlohmann::json::parse(lines[0]);
  EXPECT_EQ(enter["kind"], "sensor_enter");
  EXPECT_EQ(enter["ball"], 0);
  EXPECT_EQ(enter["sensor"], 0);
  EXPECT_NEAR(enter["time"].get<double>(), (5.5 - 2.0) / 4.0, 1e-11);
  EXPECT_EQ(nlohmann::json::parse(lines[1])["kind"], "sensor_exit");
  const auto potted = nlohmann::json::parse(lines[2]);
  EXPECT_EQ(potted["sensor"], 1);
  EXPECT_EQ(potted["removed"], true);
  EXPECT_NEAR(potted["time"].get<double>(), (16.2 - 2.0) / 4.0, 1e-11);
}

TEST(RunCommand, AMovingPaddleIsCountedHitsTheBallAndIsSavedWhereItIs) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "paddle.json", R"({
    "world": {"boundary": "box", "lower": [-5, -5], "upper": [5, 5]},
    "balls": [{"position": [0, 2], "radius": 0.5}],
    "segments": [{"a": [-1, 0], "b": [1, 0], "motion": {"velocity": [0, 1], "duration": 2.5}}]})");
  const ToolRun info = run_carom({"info", scene});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_THAT(info.out, HasSubstr("moving walls      1"));
  const std::string events = (dir / "events.jsonl").string();
  const std::string saved = (dir / "end.json").string();
  const ToolRun run =
      run_carom({"run", scene, "--until", "2", "--events", events, "--save", saved, "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The paddle, rising at 1, meets the ball at rest at t = 1.5 and sends it off at 2.
  const auto hit = nlohmann::json::parse(lines_of(read_file(events)).at(0));
  EXPECT_EQ(hit["kind"], "ball_wall");
  EXPECT_DOUBLE_EQ(hit["time"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(hit["approach_speed"].get<double>(), 1.0);
  // Saved at t = 2: the paddle at y = 2, half a time unit of its motion left.
  const auto end = nlohmann::json::parse(read_file(saved));
  EXPECT_EQ(end["segments"][0]["a"][1].get<double>(), 2.0);
  EXPECT_EQ(end["segments"][0]["motion"]["duration"].get<double>(), 0.5);
}

TEST(RunCommand, SaveThenContinueMatchesOneLongRun) {
  const ScratchDir dir;
  const std::string middle = (dir / "middle.json").string();
  const std::string end_a = (dir / "a.json").string();
  const std::string end_b = (dir / "b.json").string();
  ASSERT_EQ(run_carom({"run", example("pinball.json"), "--until", "4", "--save", end_a, "--quiet"})
                .exit_code,
            0);
  ASSERT_EQ(run_carom({"run", example("pinball.json"), "--until", "2", "--save", middle, "--quiet"})
                .exit_code,
            0);
  const ToolRun second = run_carom({"run", middle, "--until", "4", "--save", end_b, "--quiet"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const auto a = nlohmann::json::parse(read_file(end_a));
  const auto b = nlohmann::json::parse(read_file(end_b));
  EXPECT_EQ(a["time"], 4.0);
  EXPECT_EQ(b["time"], 4.0);
  ASSERT_EQ(a["balls"].size(), b["balls"].size());
  // The restart re-rounds each ball's position once (docs/world.md: a world keeps per-ball
  // clocks), so the two runs agree to rounding, not bit for bit; over 2 time units of a few
  // dozen contacts the difference stays far below 1e-9 of the bowl's size.
  for (std::size_t i = 0; i < a["balls"].size(); ++i) {
    EXPECT_NEAR(a["balls"][i]["position"][0].get<double>(),
                b["balls"][i]["position"][0].get<double>(), 1e-8);
    EXPECT_NEAR(a["balls"][i]["position"][1].get<double>(),
                b["balls"][i]["position"][1].get<double>(), 1e-8);
  }
}

TEST(RunCommand, CollisionsCountsExactly) {
  const ToolRun run =
      run_carom({"run", example("box-of-1000.json"), "--collisions", "5000", "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["collisions"], 5000);
  // Elastic box: energy kept to rounding over 5000 bounces.
  EXPECT_LT(std::abs(stats["energy_change"].get<double>()), 1e-12);
}

TEST(RunCommand, TextStatsNameEveryFigure) {
  const ToolRun run =
      run_carom({"run", example("newtons-cradle.json"), "--steps", "10", "--dt", "1", "--stats"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* part : {"collisions", "collisions/s", "wall time", "energy", "momentum"}) {
    EXPECT_THAT(run.out, HasSubstr(part));
  }
  // The progress bar is drawn only on a terminal; these tests' stderr is a file.
  EXPECT_EQ(run.err, "");
}

// Ctrl-C: the run stops within a few thousand events, and every output is complete.
TEST(RunCommand, InterruptLeavesCompleteFiles) {
  const ScratchDir dir;
  const std::string frames = (dir / "gas.csv").string();
  const std::string events = (dir / "gas.jsonl").string();
  const std::string save = (dir / "gas-end.json").string();
  const pid_t child =
      start_carom({"run", example("periodic-gas.json"), "--until", "5", "--frames", frames,
                   "--every", "0.05", "--events", events, "--save", save, "--quiet"});
  ASSERT_GT(child, 0);
  // Wait until the run is under way (its first frame is being written), then interrupt.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!std::filesystem::exists(frames + ".tmp")) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(child, SIGINT);
  const int exit_code = wait_for_exit(child);
  ASSERT_NE(exit_code, -1);  // it exited, rather than dying of the signal
  EXPECT_EQ(exit_code, 130);
  EXPECT_FALSE(std::filesystem::exists(frames + ".tmp"));
  EXPECT_FALSE(std::filesystem::exists(events + ".tmp"));
  // Frames: a header and whole frames of 10^5 rows, every row complete.
  const std::vector<std::string> rows = lines_of(read_file(frames));
  ASSERT_GE(rows.size(), 1U + 100000U);
  EXPECT_EQ((rows.size() - 1) % 100000U, 0U);
  EXPECT_EQ(std::count(rows.back().begin(), rows.back().end(), ','), 7);
  // Events: every line is a whole JSON object.
  for (const std::string& line : lines_of(read_file(events))) {
    EXPECT_TRUE(nlohmann::json::accept(line)) << line;
  }
  // The end state is a scene at the time the run stopped (0 if Ctrl-C came while the first frame
  // was still being written, as it can in a slow sanitizer build), and the last frame is of it.
  const auto saved = nlohmann::json::parse(read_file(save));
  EXPECT_GE(saved["time"].get<double>(), 0.0);
  EXPECT_EQ(std::strtod(rows.back().c_str(), nullptr), saved["time"].get<double>());
  EXPECT_LT(saved["time"].get<double>(), 10000.0);
  EXPECT_EQ(saved["balls"].size(), 100000U);
}

TEST(InfoCommand, CountsEnergyPackingAndSmallestGap) {
  const ToolRun run = run_carom({"info", example("periodic-gas.json"), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["balls"], 100000);
  EXPECT_EQ(stats["generated_balls"], 100000);
  EXPECT_NEAR(stats["packing_fraction"].get<double>(), 0.5, 1e-12);
  // Maxwell–Boltzmann at temperature 1 in 2D: E ≈ N·T, within a few standard deviations
  // (relative sd of the sum of 2·10⁵ squared normals is sqrt(2/2e5) = 0.003).
  EXPECT_NEAR(stats["kinetic_energy"].get<double>() / 1e5, 1.0, 5 * 0.003);
  EXPECT_GT(stats["smallest_gap"]["gap"].get<double>(), 0.0);
  EXPECT_EQ(stats["valid"], true);
}

TEST(InfoCommand, TextNamesTheClosestPair) {
  const ToolRun run = run_carom({"info", example("billiards-frictionless.json")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("balls             16 (0 generated, 0 immovable)"));
  EXPECT_THAT(run.out, HasSubstr("pockets           6"));
  // The racked balls are 1e-4 apart (examples/billiards-frictionless.json).
  EXPECT_THAT(run.out, HasSubstr("smallest gap      0.0001 ("));
  EXPECT_THAT(run.out, HasSubstr("valid             yes"));
}

// Without gravity the text has the one energy line; the JSON always gives every energy (potential
// 0).
TEST(RunCommand, StatsWithoutGravityAddTheEnergyOfGravityToJsonOnly) {
  const ToolRun text =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--stats"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("\nenergy          "));
  for (const char* absent : {"potential", "total", "kinetic", "gravity"}) {
    EXPECT_THAT(text.out, Not(HasSubstr(absent))) << absent;
  }
  const ToolRun as_json =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--stats", "--json"});
  ASSERT_EQ(as_json.exit_code, 0) << as_json.err;
  const auto stats = nlohmann::json::parse(as_json.out);
  EXPECT_EQ(stats["potential_energy_before"], 0.0);
  EXPECT_EQ(stats["potential_energy_after"], 0.0);
  EXPECT_EQ(stats["total_energy_before"], stats["energy_before"]);
  EXPECT_EQ(stats["total_energy_after"], stats["energy_after"]);
  EXPECT_EQ(stats["total_energy_change"], stats["energy_change"]);
  EXPECT_EQ(stats["total_energy_conserved"], true);
  EXPECT_EQ(stats["conservative"], true);
}

// A dilute elastic gas under gravity: kinetic and potential energy trade, the total stays to
// rounding. Needs the world's parabolic flight (it runs 20 s of falls and bounces).
TEST(RunCommand, GravityDropKeepsItsTotalEnergy) {
  const ToolRun run =
      run_carom({"run", example("gravity-drop.json"), "--until", "20", "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["balls_at_end"], 20);
  EXPECT_GT(stats["ball_wall"].get<int>(), 20);  // every ball reaches the floor
  // Scene heights 2 + 1.8·i, i < 20, unit masses: U = 9.81 · Σ y = 9.81 · 382, to rounding.
  EXPECT_NEAR(stats["potential_energy_before"].get<double>(), 9.81 * 382.0, 1e-9);
  EXPECT_EQ(stats["conservative"], false);  // gravity changes the kinetic energy and momentum
  EXPECT_EQ(stats["total_energy_conserved"], true);
  EXPECT_GT(std::abs(stats["energy_change"].get<double>()), 1.0);
  // Relative to the kinetic energy at the start (7.7 against a total of 3755): a few hundred
  // contacts each round the total by a few ulps of 3755, far below 1e-10 of it.
  EXPECT_LT(std::abs(stats["total_energy_change"].get<double>()), 1e-10);
  EXPECT_DOUBLE_EQ(
      stats["total_energy_after"].get<double>(),
      stats["energy_after"].get<double>() + stats["potential_energy_after"].get<double>());
  const ToolRun text = run_carom({"run", example("gravity-drop.json"), "--until", "20", "--stats"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("\nkinetic energy  7.695 -> "));
  EXPECT_THAT(text.out, HasSubstr("\npotential       3747.42 -> "));
  // (The total sits near 3755.115, so its last printed digit may go either way by rounding.)
  EXPECT_THAT(text.out, HasSubstr("\ntotal energy    3755.12 -> 3755.1"));
  EXPECT_THAT(text.out, HasSubstr(" (drift "));
  EXPECT_THAT(text.out, HasSubstr("\nmomentum        (1.7, 0) -> "));
}

TEST(InfoCommand, GravityIsNamedWithTheEnergyItHolds) {
  const ToolRun text = run_carom({"info", example("gravity-drop.json")});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("world             box [0, 20] x [0, 40], restitution 1, "
                                  "gravity (0, -9.81)\n"));
  EXPECT_THAT(text.out, HasSubstr("kinetic energy    7.695\n"
                                  "potential energy  3747.42\n"
                                  "total energy      3755.12\n"));
  const ToolRun as_json = run_carom({"info", example("gravity-drop.json"), "--json"});
  ASSERT_EQ(as_json.exit_code, 0) << as_json.err;
  const auto stats = nlohmann::json::parse(as_json.out);
  EXPECT_EQ(stats["gravity"], nlohmann::json::array({0.0, -9.81}));
  EXPECT_NEAR(stats["potential_energy"].get<double>(), 9.81 * 382.0, 1e-9);
  EXPECT_EQ(stats["total_energy"].get<double>(),
            stats["kinetic_energy"].get<double>() + stats["potential_energy"].get<double>());
}

TEST(InfoCommand, ARestHeightSetInTheSceneIsNamed) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "rest.json", R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10], "gravity": [0, -1],
              "rest_height": 0.01},
    "balls": [{"position": [5, 5]}]})");
  const ToolRun text = run_carom({"info", scene});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("gravity (0, -1), rest height 0.01 radii\n"));
  const ToolRun as_json = run_carom({"info", scene, "--json"});
  ASSERT_EQ(as_json.exit_code, 0) << as_json.err;
  EXPECT_EQ(nlohmann::json::parse(as_json.out)["rest_height"].get<double>(), 0.01);
  // The default is left out of the text.
  EXPECT_THAT(run_carom({"info", example("gravity-drop.json")}).out, Not(HasSubstr("rest height")));
}

TEST(InfoCommand, AGrowthRateIsNamed) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "grow.json", R"({
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [10, 10], "growth_rate": 0.25},
    "balls": [{"position": [5, 5]}]})");
  const ToolRun text = run_carom({"info", scene});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("restitution 1, growth rate 0.25 a time unit\n"));
  const ToolRun as_json = run_carom({"info", scene, "--json"});
  EXPECT_EQ(nlohmann::json::parse(as_json.out)["growth_rate"].get<double>(), 0.25);
}

TEST(InfoCommand, WithoutGravityTheTextNamesNone) {
  const ToolRun text = run_carom({"info", example("newtons-cradle.json")});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("world             box [0, 40] x [0, 6], restitution 1\n"));
  for (const char* absent : {"gravity", "potential", "total"}) {
    EXPECT_THAT(text.out, Not(HasSubstr(absent))) << absent;
  }
  const ToolRun as_json = run_carom({"info", example("newtons-cradle.json"), "--json"});
  const auto stats = nlohmann::json::parse(as_json.out);
  EXPECT_EQ(stats["gravity"], nlohmann::json::array({0.0, 0.0}));
  EXPECT_EQ(stats["potential_energy"], 0.0);
  EXPECT_EQ(stats["total_energy"], stats["kinetic_energy"]);
}

}  // namespace
}  // namespace carom::cli::test
