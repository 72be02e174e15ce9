// Every long verb stops on SIGINT or SIGTERM with its outputs complete up to there: gas and eos
// report the blocks and points completed, bench the timed collisions so far, render the picture
// at the time reached and the animation up to its last frame. And a run's progress is shown on a
// terminal even when no contact happens.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "options/exit_codes.hpp"
#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;

// Runs the tool, sends `signal` after `delay` (or once `started` exists, then the delay).
ToolRun stopped_after(int signal, const std::vector<std::string>& args,
                      std::chrono::milliseconds delay, const std::filesystem::path& started = {}) {
  RunningTool tool(args);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!started.empty() && !std::filesystem::exists(started) &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(delay);
  EXPECT_TRUE(tool.signal(signal));
  return tool.wait();
}

TEST(VerbStop, GasReportsTheBlocksCompleted) {
  const ScratchDir dir;
  // 1000 blocks of 100 collisions a disk: a block in about a tenth of a second, the whole far
  // beyond the signal.
  const ToolRun run =
      stopped_after(SIGTERM,
                    {"gas", "--n", "1000", "--eta", "0.3", "--equilibrate", "1", "--collisions",
                     "100000", "--blocks", "1000", "--json", "-o", (dir / "out").string()},
                    std::chrono::milliseconds(1500));
  ASSERT_EQ(run.exit_code, kExitTerminated) << run.err;
  if (run.out.empty()) {  // a slow (sanitizer) build may not finish a block in time
    EXPECT_THAT(run.err, HasSubstr("nothing was measured"));
    return;
  }
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["stopped"], "interrupted");
  EXPECT_GE(stats["blocks_done"].get<int>(), 1);
  EXPECT_LT(stats["blocks_done"].get<int>(), 1000);
  EXPECT_TRUE(stats["Z"].is_number());
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "rdf.csv"));
  EXPECT_THAT(run.err, HasSubstr("terminated (SIGTERM) after"));
}

TEST(VerbStop, EosWritesThePointsCompleted) {
  const ScratchDir dir;
  const ToolRun run = stopped_after(SIGINT,
                                    {"eos", "--eta", "0.1:0.5:0.1", "--n", "500", "--collisions",
                                     "3000", "--threads", "1", "--out", (dir / "eos").string()},
                                    std::chrono::milliseconds(1500));
  ASSERT_EQ(run.exit_code, kExitInterrupted) << run.err;
  EXPECT_THAT(run.err, HasSubstr("interrupted (Ctrl-C) with "));
  EXPECT_THAT(run.err, HasSubstr(" of 5 points complete"));
  if (run.err.find("nothing to write") != std::string::npos) return;  // a slow build
  const std::vector<std::string> rows = lines_of(read_file(dir / "eos" / "eos.csv"));
  ASSERT_GE(rows.size(), 2U);  // a header and the points completed
  EXPECT_LT(rows.size(), 6U);
}

TEST(VerbStop, BenchReportsTheTimedCollisionsSoFar) {
  const ToolRun run =
      stopped_after(SIGINT, {"bench", "--n", "4000", "--collisions-per-ball", "100000", "--json"},
                    std::chrono::milliseconds(1500));
  ASSERT_EQ(run.exit_code, kExitInterrupted) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["stopped"], "interrupted");
  EXPECT_GT(stats["collisions"].get<double>(), 0.0);
  EXPECT_LT(stats["collisions"].get<double>(), 4e8);
}

TEST(VerbStop, RenderDrawsThePictureAtTheTimeReached) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "orbit.json", kEndlessOrbitScene);
  const std::string out = (dir / "orbit.svg").string();
  const ToolRun run = stopped_after(SIGINT, {"render", scene, "--at", "1e12", "--out", out},
                                    std::chrono::milliseconds(500));
  ASSERT_EQ(run.exit_code, kExitInterrupted) << run.err;
  EXPECT_THAT(read_file(out), HasSubstr("<svg"));
  EXPECT_THAT(run.out, HasSubstr("picture: "));
  EXPECT_THAT(run.err, HasSubstr("up to there"));
}

TEST(VerbStop, RenderEndsTheAnimationAtTheLastFrameDrawn) {
  const ScratchDir dir;
  const std::string gif = (dir / "break.gif").string();
  // 6000 frames: far more than are drawn before the signal, which comes once ffmpeg has started.
  const ToolRun run = stopped_after(
      SIGTERM,
      {"render", example("billiards-frictionless.json"), "--animate", gif, "--until", "200"},
      std::chrono::milliseconds(300), gif + ".tmp");
  ASSERT_EQ(run.exit_code, kExitTerminated) << run.err;
  EXPECT_EQ(read_file(gif).substr(0, 6), "GIF89a");
  EXPECT_FALSE(std::filesystem::exists(gif + ".tmp"));
  EXPECT_THAT(run.out, HasSubstr("animation: "));
}

// What the tool shows on a terminal: it runs on a pseudo-terminal, which is read for
// `for_how_long`, then it is sent SIGINT and read to its end. Returns the text and the exit status.
std::pair<std::string, int> on_a_terminal(std::vector<std::string> words,
                                          std::chrono::milliseconds for_how_long) {
  words.insert(words.begin(), CAROM_CLI_PATH);
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  int terminal = -1;
  const pid_t child = ::forkpty(&terminal, nullptr, nullptr, nullptr);
  if (child < 0) return {"forkpty failed", -1};
  if (child == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  std::string seen;
  const auto until = std::chrono::steady_clock::now() + for_how_long;
  char buffer[4096];
  while (std::chrono::steady_clock::now() < until) {
    pollfd ready{terminal, POLLIN, 0};
    if (::poll(&ready, 1, 50) <= 0) continue;
    const ssize_t got = ::read(terminal, buffer, sizeof buffer);
    if (got <= 0) break;
    seen.append(buffer, static_cast<std::size_t>(got));
  }
  ::kill(child, SIGINT);
  for (;;) {  // the rest, until the tool closes the terminal
    const ssize_t got = ::read(terminal, buffer, sizeof buffer);
    if (got <= 0) break;
    seen.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(terminal);
  int status = 0;
  ::waitpid(child, &status, 0);
  return {seen, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

// On a terminal, a run that has no contact for ever still shows its progress: the time and the
// cell crossings.
TEST(VerbStop, ProgressIsShownDuringARunWithoutContacts) {
  const ScratchDir dir;
  const std::string scene = write_scene(dir, "orbit.json", kEndlessOrbitScene);
  const auto [seen, status] =
      on_a_terminal({"run", scene, "--collisions", "1"}, std::chrono::milliseconds(1500));
  EXPECT_EQ(status, kExitInterrupted) << seen;
  EXPECT_THAT(seen, HasSubstr("cell crossings"));
  EXPECT_THAT(seen, AnyOf(HasSubstr("t=1"), HasSubstr("t=2"), HasSubstr("t=3"), HasSubstr("t=4"),
                          HasSubstr("t=5"), HasSubstr("t=6"), HasSubstr("t=7"), HasSubstr("t=8"),
                          HasSubstr("t=9")));
}

// render --animate shows the frame it is drawing.
TEST(VerbStop, AnimationShowsItsProgress) {
  const ScratchDir dir;
  const std::string gif = (dir / "break.gif").string();
  const auto [seen, status] = on_a_terminal(
      {"render", example("billiards-frictionless.json"), "--animate", gif, "--until", "200"},
      std::chrono::milliseconds(1200));
  EXPECT_EQ(status, kExitInterrupted) << seen;
  EXPECT_THAT(seen, AnyOf(HasSubstr("surveying the run"), HasSubstr(" of 6001")));
}

}  // namespace
}  // namespace carom::cli::test
