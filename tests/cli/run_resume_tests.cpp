// `carom run --checkpoint / --resume`: a run stopped at a checkpoint and resumed ends bit for bit
// as the run that was never stopped; checkpoints rotate to FILE.prev; a damaged or missing
// checkpoint is refused with one clear message and exit 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

std::size_t line_count(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

// The first run checkpoints every 10 time units to 20 (checkpoints at 10 and 20: FILE.prev holds
// t = 10); the second resumes from t = 10. The box of 1000 has thousands of contacts in each half.
struct UntilRuns {
  ScratchDir dir;
  std::string checkpoint = (dir / "box.ckpt").string();
  ToolRun first =
      run_carom({"run", example("box-of-1000.json"), "--until", "20", "--checkpoint", checkpoint,
                 "--checkpoint-every", "10", "--save", (dir / "first.json").string(), "--events",
                 (dir / "first.jsonl").string(), "--quiet"});
};

TEST(RunResume, UntilRunResumedFromACheckpointEndsBitIdentical) {
  const UntilRuns runs;
  ASSERT_EQ(runs.first.exit_code, 0) << runs.first.err;
  ASSERT_TRUE(std::filesystem::exists(runs.checkpoint + ".prev"));
  const ToolRun resumed = run_carom({"run", "--resume", runs.checkpoint + ".prev", "--until", "20",
                                     "--save", (runs.dir / "resumed.json").string(), "--events",
                                     (runs.dir / "resumed.jsonl").string(), "--stats", "--json"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;

  const std::string first_end = read_file(runs.dir / "first.json");
  ASSERT_FALSE(first_end.empty());
  EXPECT_EQ(read_file(runs.dir / "resumed.json"), first_end);  // byte for byte

  // The resumed events are exactly the first run's events after t = 10.
  const std::string first_events = read_file(runs.dir / "first.jsonl");
  const std::string resumed_events = read_file(runs.dir / "resumed.jsonl");
  const std::size_t resumed_lines = line_count(resumed_events);
  EXPECT_GT(resumed_lines, 2000U);
  EXPECT_GT(line_count(first_events), resumed_lines + 2000U);
  ASSERT_LE(resumed_events.size(), first_events.size());
  EXPECT_EQ(first_events.substr(first_events.size() - resumed_events.size()), resumed_events);
  EXPECT_EQ(first_events[first_events.size() - resumed_events.size() - 1], '\n');
  const auto first_event =
      nlohmann::json::parse(resumed_events.substr(0, resumed_events.find('\n')));
  EXPECT_GE(first_event["time"].get<double>(), 10.0);

  // --stats covers the whole run: counts from the first run's start.
  const auto stats = nlohmann::json::parse(resumed.out);
  EXPECT_EQ(stats["collisions"].get<std::size_t>(), line_count(first_events));
  EXPECT_EQ(stats["start_time"], 0.0);
  EXPECT_EQ(stats["end_time"], 20.0);
}

TEST(RunResume, CollisionsRunResumedFromACheckpointEndsBitIdentical) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "box.ckpt").string();
  // 6000 contacts take the box of 1000 past t = 5 and short of t = 10 (checked below through the
  // checkpoint: FILE.prev is the one at t >= 5, FILE the end).
  const ToolRun first =
      run_carom({"run", example("box-of-1000.json"), "--collisions", "6000", "--checkpoint",
                 checkpoint, "--checkpoint-every", "5", "--save", (dir / "first.json").string(),
                 "--events", (dir / "first.jsonl").string(), "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ToolRun resumed = run_carom({"run", "--resume", checkpoint + ".prev", "--collisions",
                                     "6000", "--save", (dir / "resumed.json").string(), "--events",
                                     (dir / "resumed.jsonl").string(), "--stats", "--json"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "first.json"));
  const std::string first_events = read_file(dir / "first.jsonl");
  const std::string resumed_events = read_file(dir / "resumed.jsonl");
  EXPECT_EQ(line_count(first_events), 6000U);
  EXPECT_GT(line_count(resumed_events), 1000U);
  EXPECT_LT(line_count(resumed_events), 6000U);
  ASSERT_LE(resumed_events.size(), first_events.size());
  EXPECT_EQ(first_events.substr(first_events.size() - resumed_events.size()), resumed_events);
  EXPECT_EQ(nlohmann::json::parse(resumed.out)["collisions"], 6000);
}

TEST(RunResume, StepsRunResumedFromACheckpointEndsBitIdentical) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "box.ckpt").string();
  // 40 steps of 0.5 with checkpoints every 8: the last two at t = 16 and t = 20 (the end).
  const ToolRun first =
      run_carom({"run", example("box-of-1000.json"), "--steps", "40", "--dt", "0.5", "--checkpoint",
                 checkpoint, "--checkpoint-every", "8", "--save", (dir / "first.json").string(),
                 "--events", (dir / "first.jsonl").string(), "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ToolRun resumed = run_carom({"run", "--resume", checkpoint + ".prev", "--steps", "40",
                                     "--dt", "0.5", "--save", (dir / "resumed.json").string(),
                                     "--events", (dir / "resumed.jsonl").string(), "--quiet"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "first.json"));
  const std::string first_events = read_file(dir / "first.jsonl");
  const std::string resumed_events = read_file(dir / "resumed.jsonl");
  EXPECT_GT(line_count(resumed_events), 1000U);
  EXPECT_GT(line_count(first_events), line_count(resumed_events) + 1000U);
  EXPECT_EQ(first_events.substr(first_events.size() - resumed_events.size()), resumed_events);
}

// Pockets end a world's run at each pocket contact (a stop condition World::save leaves out);
// balls potted before and after the checkpoint.
TEST(RunResume, BilliardsWithPocketsResumedEndsBitIdentical) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "billiards.ckpt").string();
  const ToolRun first =
      run_carom({"run", example("billiards-frictionless.json"), "--until", "30", "--checkpoint",
                 checkpoint, "--checkpoint-every", "10", "--save", (dir / "first.json").string(),
                 "--events", (dir / "first.jsonl").string(), "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ToolRun resumed = run_carom({"run", "--resume", checkpoint + ".prev", "--until", "30",
                                     "--save", (dir / "resumed.json").string(), "--events",
                                     (dir / "resumed.jsonl").string(), "--quiet"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::string first_events = read_file(dir / "first.jsonl");
  const std::string resumed_events = read_file(dir / "resumed.jsonl");
  // Balls potted before t = 20 and after it (the break pots several; one more falls at 27.4).
  ASSERT_GT(resumed_events.size(), 0U);
  const std::string before = first_events.substr(0, first_events.size() - resumed_events.size());
  EXPECT_THAT(before, HasSubstr("\"potted\""));
  EXPECT_THAT(resumed_events, HasSubstr("\"potted\""));
  EXPECT_EQ(first_events.substr(first_events.size() - resumed_events.size()), resumed_events);
  EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "first.json"));
}

// Under gravity the resumed run ends as the straight one, and its --stats report the kinetic and
// potential energy at the first run's start, kept in the checkpoint.
TEST(RunResume, GravityRunResumedReportsTheEnergyAtTheFirstStart) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "drop.ckpt").string();
  const ToolRun first = run_carom({"run", example("gravity-drop.json"), "--until", "20",
                                   "--checkpoint", checkpoint, "--checkpoint-every", "10", "--save",
                                   (dir / "first.json").string(), "--stats", "--json"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ToolRun resumed =
      run_carom({"run", "--resume", checkpoint + ".prev", "--until", "20", "--save",
                 (dir / "resumed.json").string(), "--stats", "--json"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "first.json"));
  EXPECT_THAT(read_file(dir / "first.json"), HasSubstr("\"gravity\": [0.0, -9.81]"));
  const auto a = nlohmann::json::parse(first.out);
  const auto b = nlohmann::json::parse(resumed.out);
  for (const char* key :
       {"energy_before", "potential_energy_before", "total_energy_before", "energy_after",
        "potential_energy_after", "total_energy_after", "total_energy_change", "collisions"}) {
    EXPECT_EQ(a[key], b[key]) << key;
  }
  EXPECT_GT(b["potential_energy_before"].get<double>(), 3000.0);
}

TEST(RunResume, GrowingRunResumedEndsBitIdentical) {
  // Radii growing through the checkpoint: the world's growth (rate, start, re-planning time)
  // travels in it, and the resumed run ends on the same radii and places.
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "grow.json", R"({
    "world": {"boundary": "periodic", "lower": [0, 0], "upper": [30, 30], "growth_rate": 0.05},
    "generators": [{"name": "g", "placement": "random", "count": 100, "radius": 0.6,
                    "region": {"lower": [0, 0], "upper": [30, 30]},
                    "velocity": {"distribution": "uniform_direction", "speed": 1}, "seed": 1}]})");
  const std::string checkpoint = (dir / "grow.ckpt").string();
  const ToolRun first =
      run_carom({"run", scene, "--until", "4", "--checkpoint", checkpoint, "--checkpoint-every",
                 "2", "--save", (dir / "first.json").string()});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const ToolRun resumed = run_carom({"run", "--resume", checkpoint + ".prev", "--until", "4",
                                     "--save", (dir / "resumed.json").string()});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "first.json"));
  EXPECT_THAT(read_file(dir / "first.json"), HasSubstr("\"growth_rate\""));
}

TEST(RunResume, ThermostattedCompressionResumedEndsBitIdentical) {
  // The thermostat's steps fall on the scene clock's multiples of 0.7 (or on the collision
  // count's of 20), so a run resumed from a checkpoint at t = 2 takes the same steps.
  for (const char* every : {R"("interval": 0.7)", R"("collisions": 20)"}) {
    const ScratchDir dir;
    const std::string scene = write_scene(dir, "grow.json", std::string(R"({
      "world": {"boundary": "periodic", "lower": [0, 0], "upper": [30, 30], "growth_rate": 0.05},
      "thermostat": {"temperature": 0.5, )") + every + R"(},
      "generators": [{"name": "g", "placement": "random", "count": 100, "radius": 0.6,
                      "region": {"lower": [0, 0], "upper": [30, 30]},
                      "velocity": {"distribution": "uniform_direction", "speed": 1}, "seed": 1}]})");
    const std::string checkpoint = (dir / "grow.ckpt").string();
    const ToolRun first =
        run_carom({"run", scene, "--until", "4", "--checkpoint", checkpoint, "--checkpoint-every",
                   "2", "--save", (dir / "first.json").string(), "--stats", "--json"});
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_LT(nlohmann::json::parse(first.out)["thermostat_work"].get<double>(), 0.0) << every;
    const ToolRun resumed = run_carom({"run", "--resume", checkpoint + ".prev", "--until", "4",
                                       "--save", (dir / "resumed.json").string()});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "first.json")) << every;
    EXPECT_THAT(read_file(dir / "first.json"), HasSubstr("\"thermostat\""));
  }
}

TEST(RunResume, CheckpointsRotateToPrev) {
  const UntilRuns runs;
  ASSERT_EQ(runs.first.exit_code, 0) << runs.first.err;
  EXPECT_TRUE(std::filesystem::exists(runs.checkpoint));
  EXPECT_FALSE(std::filesystem::exists(runs.checkpoint + ".tmp"));
  // FILE is the end (nothing left to run), FILE.prev the one before (half the run left).
  const ToolRun from_last = run_carom({"run", "--resume", runs.checkpoint, "--until", "20",
                                       "--events", (runs.dir / "last.jsonl").string(), "--save",
                                       (runs.dir / "last.json").string(), "--quiet"});
  ASSERT_EQ(from_last.exit_code, 0) << from_last.err;
  EXPECT_EQ(read_file(runs.dir / "last.jsonl"), "");
  EXPECT_EQ(read_file(runs.dir / "last.json"), read_file(runs.dir / "first.json"));
  // Resumed at t = 10, a run writes the same checkpoint at t = 20 as the first run did.
  const std::string before = read_file(runs.checkpoint + ".prev");
  const ToolRun again = run_carom({"run", "--resume", runs.checkpoint + ".prev", "--until", "20",
                                   "--checkpoint", (runs.dir / "again.ckpt").string(), "--quiet"});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(read_file(runs.dir / "again.ckpt"), read_file(runs.checkpoint));
  EXPECT_EQ(read_file(runs.dir / "again.ckpt.prev"), "");  // one checkpoint written: no .prev
  EXPECT_FALSE(std::filesystem::exists(runs.dir / "again.ckpt.prev"));
  EXPECT_EQ(read_file(runs.checkpoint + ".prev"), before);
}

// One line on stderr, naming the file and the problem; exit 2; nothing written.
void expect_refused(const ToolRun& run, const std::string& file, const std::string& problem) {
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr(file));
  EXPECT_THAT(run.err, HasSubstr(problem));
  EXPECT_EQ(line_count(run.err), 1U) << run.err;
}

TEST(RunResume, DamagedCheckpointsAreRefused) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "cradle.ckpt").string();
  const ToolRun first = run_carom({"run", example("newtons-cradle.json"), "--until", "5",
                                   "--checkpoint", checkpoint, "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const std::string good = read_file(checkpoint);
  ASSERT_GT(good.size(), 100U);
  const std::string save = (dir / "end.json").string();
  const auto resume = [&](const std::string& bytes) {
    const std::string path = (dir / "damaged.ckpt").string();
    write_bytes(path, bytes);
    return run_carom({"run", "--resume", path, "--until", "5", "--save", save});
  };
  std::string flipped = good;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x10);
  expect_refused(resume(flipped), "damaged.ckpt", "checksum mismatch");
  expect_refused(resume(good.substr(0, good.size() - 7)), "damaged.ckpt", "truncated");
  expect_refused(resume(good.substr(0, 12)), "damaged.ckpt", "truncated");
  std::string magic = good;
  magic[0] = 'X';
  expect_refused(resume(magic), "damaged.ckpt", "not a carom checkpoint");
  expect_refused(resume(good + "x"), "damaged.ckpt", "unexpected bytes");
  expect_refused(resume(""), "damaged.ckpt", "not a carom checkpoint");
  EXPECT_FALSE(std::filesystem::exists(save));
  // The good one still resumes.
  EXPECT_EQ(resume(good).exit_code, 0);
}

TEST(RunResume, MissingCheckpointIsRefused) {
  const ScratchDir dir;
  const std::string path = (dir / "nowhere.ckpt").string();
  expect_refused(run_carom({"run", "--resume", path, "--until", "5"}), path, "cannot be read");
}

TEST(RunResume, OtherRunOptionsAreRefused) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "cradle.ckpt").string();
  ASSERT_EQ(run_carom({"run", example("newtons-cradle.json"), "--until", "5", "--checkpoint",
                       checkpoint, "--quiet"})
                .exit_code,
            0);
  const ToolRun other = run_carom({"run", "--resume", checkpoint, "--until", "6"});
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_THAT(other.err, HasSubstr("--until 5"));
  EXPECT_THAT(other.err, HasSubstr("same options"));
  const ToolRun both =
      run_carom({"run", example("newtons-cradle.json"), "--resume", checkpoint, "--until", "5"});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_THAT(both.err, HasSubstr("--resume"));
  const ToolRun lonely =
      run_carom({"run", example("newtons-cradle.json"), "--until", "5", "--checkpoint-every", "1"});
  EXPECT_EQ(lonely.exit_code, 2);
  EXPECT_THAT(lonely.err, HasSubstr("--checkpoint FILE"));
}

}  // namespace
}  // namespace carom::cli::test
