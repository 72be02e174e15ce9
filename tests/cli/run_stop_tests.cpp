// `carom run` stopping short: SIGINT and SIGTERM in every mode, even in a run with no contact at
// all (two balls on a periodic orbit that never meets, which follows cell crossings for ever), a
// second signal, --time-limit, and why a run stopped in its JSON summary.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "options/exit_codes.hpp"
#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

// How long a stopped run may take to exit after the signal: the tool promises a fifth of a second
// (a few thousand events); this allows for a sanitizer build on a loaded machine, and still fails
// a run that waits for a chunk that never ends.
constexpr auto kStopWithin = std::chrono::seconds(10);

// Waits until `path` exists (the tool has opened its outputs and started running).
void wait_for(const std::filesystem::path& path) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!std::filesystem::exists(path)) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << path << " never appeared";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

struct Stopped {
  ToolRun run;
  std::chrono::steady_clock::duration took{};
};

// Starts the tool, waits until `started` exists and `delay` more, sends `signal`, waits.
Stopped stop_with(int signal, const std::vector<std::string>& args,
                  const std::filesystem::path& started,
                  std::chrono::milliseconds delay = std::chrono::milliseconds(300)) {
  RunningTool tool(args);
  wait_for(started);
  std::this_thread::sleep_for(delay);
  const auto sent = std::chrono::steady_clock::now();
  EXPECT_TRUE(tool.signal(signal));
  Stopped stopped;
  stopped.run = tool.wait();
  stopped.took = std::chrono::steady_clock::now() - sent;
  return stopped;
}

struct Mode {
  const char* name;
  std::vector<std::string> args;
};

class RunStopsOnSignal : public ::testing::TestWithParam<int> {};

// Each mode, on the scene that never has a contact: the run stops soon after the signal, with the
// signal's status, "stopped": "interrupted", and complete outputs (start and stop frames, the
// checkpoint).
TEST_P(RunStopsOnSignal, InEveryModeEvenWithoutContacts) {
  const int signal = GetParam();
  const std::vector<Mode> modes{
      {"collisions", {"--collisions", "1"}},
      {"until", {"--until", "1e12"}},
      {"steps", {"--steps", "3", "--dt", "1e12"}},
  };
  for (const Mode& mode : modes) {
    SCOPED_TRACE(mode.name);
    const ScratchDir dir;
    const std::string scene = write_scene(dir, "orbit.json", kEndlessOrbitScene);
    const std::string frames = (dir / "frames.csv").string();
    const std::string checkpoint = (dir / "orbit.ckpt").string();
    std::vector<std::string> args{"run",          scene,      "--frames", frames,
                                  "--checkpoint", checkpoint, "--stats",  "--json"};
    args.insert(args.end(), mode.args.begin(), mode.args.end());
    const Stopped stopped = stop_with(signal, args, frames + ".tmp");
    EXPECT_EQ(stopped.run.exit_code, signal == SIGINT ? kExitInterrupted : kExitTerminated)
        << stopped.run.err;
    EXPECT_LT(stopped.took, kStopWithin);
    const auto stats = nlohmann::json::parse(stopped.run.out);
    EXPECT_EQ(stats["stopped"], "interrupted");
    EXPECT_EQ(stats["collisions"], 0);
    EXPECT_GT(stats["end_time"].get<double>(), 0.0);
    EXPECT_THAT(stopped.run.err,
                HasSubstr(signal == SIGINT ? "interrupted (Ctrl-C)" : "terminated (SIGTERM)"));
    // A header and two frames of two balls: the start and the stop.
    EXPECT_EQ(read_file(frames).find("time,index"), 0U);
    EXPECT_FALSE(std::filesystem::exists(frames + ".tmp"));
    EXPECT_TRUE(std::filesystem::exists(checkpoint));
  }
}

INSTANTIATE_TEST_SUITE_P(Signals, RunStopsOnSignal, ::testing::Values(SIGINT, SIGTERM),
                         [](const ::testing::TestParamInfo<int>& signal_info) {
                           return signal_info.param == SIGINT ? std::string("Sigint")
                                                              : std::string("Sigterm");
                         });

// A run stopped inside a step (--steps) or a chunk of contacts (--collisions) by a signal, then
// resumed from its checkpoint, ends byte for byte as a run never stopped.
TEST(RunStop, ARunStoppedInsideAStepOrChunkResumesToTheSameEnd) {
  const std::vector<Mode> modes{
      {"steps", {"--steps", "2", "--dt", "400"}},
      {"collisions", {"--collisions", "800000"}},
  };
  for (const Mode& mode : modes) {
    SCOPED_TRACE(mode.name);
    const ScratchDir dir;
    std::vector<std::string> reference_args{"run", example("box-of-1000.json"), "--save",
                                            (dir / "reference.json").string(), "--quiet"};
    reference_args.insert(reference_args.end(), mode.args.begin(), mode.args.end());
    const ToolRun reference = run_carom(reference_args);
    ASSERT_EQ(reference.exit_code, 0) << reference.err;

    const std::string checkpoint = (dir / "box.ckpt").string();
    const std::string frames = (dir / "frames.csv").string();
    std::vector<std::string> args{
        "run",    example("box-of-1000.json"), "--checkpoint", checkpoint, "--frames", frames,
        "--quiet"};
    args.insert(args.end(), mode.args.begin(), mode.args.end());
    // About 0.7 s of work in the dev build: the signal lands inside the first step or chunk.
    const Stopped stopped =
        stop_with(SIGINT, args, frames + ".tmp", std::chrono::milliseconds(100));
    ASSERT_EQ(stopped.run.exit_code, kExitInterrupted) << "the run ended before the signal";

    std::vector<std::string> resume{
        "run", "--resume", checkpoint, "--save", (dir / "resumed.json").string(), "--quiet"};
    resume.insert(resume.end(), mode.args.begin(), mode.args.end());
    const ToolRun resumed = run_carom(resume);
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(read_file(dir / "resumed.json"), read_file(dir / "reference.json"));
  }
}

// A second signal ends the tool at once and removes the temporary files of the outputs opened so
// far. The run is held at the opening of a FIFO that no one reads, after the frames file's
// temporary file was made.
TEST(RunStop, ASecondSignalEndsAtOnceAndRemovesTemporaryFiles) {
  const ScratchDir dir;
  const std::string frames = (dir / "frames.csv").string();
  const auto fifo = dir / "events.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  RunningTool tool({"run", example("newtons-cradle.json"), "--until", "10", "--frames", frames,
                    "--events", fifo.string()});
  wait_for(frames + ".tmp");
  ASSERT_TRUE(tool.signal(SIGINT));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(tool.signal(SIGINT));
  const ToolRun run = tool.wait();
  EXPECT_EQ(run.exit_code, kExitInterrupted);
  EXPECT_FALSE(std::filesystem::exists(frames + ".tmp"));
  EXPECT_FALSE(std::filesystem::exists(frames));
}

TEST(RunStop, CollisionsStopAtTheTimeLimitAndSaySo) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "orbit.json", kEndlessOrbitScene);
  const ToolRun run =
      run_carom({"run", scene, "--collisions", "1", "--time-limit", "5000", "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["stopped"], "time_limit");
  EXPECT_EQ(stats["end_time"], 5000.0);
  EXPECT_EQ(stats["collisions"], 0);

  const ToolRun text = run_carom({"run", scene, "--collisions", "1", "--time-limit", "5000"});
  EXPECT_THAT(text.out, HasSubstr("stopped at the --time-limit"));
  const ToolRun wrong = run_carom({"run", scene, "--until", "5", "--time-limit", "5000"});
  EXPECT_EQ(wrong.exit_code, kExitUsage);
  EXPECT_THAT(wrong.err, HasSubstr("--time-limit goes with --collisions"));
}

TEST(RunStop, ARunWithNoContactLeftSaysSo) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "apart.json", R"({
    "carom_scene": 1,
    "balls": [{"position": [0, 0], "velocity": [-1, 0]}, {"position": [5, 0], "velocity": [1, 0]}]
  })");
  const ToolRun run = run_carom({"run", scene, "--collisions", "3", "--stats", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["stopped"], "no_more_contacts");
  const ToolRun done =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--stats", "--json"});
  EXPECT_TRUE(nlohmann::json::parse(done.out)["stopped"].is_null());
}

}  // namespace
}  // namespace carom::cli::test
