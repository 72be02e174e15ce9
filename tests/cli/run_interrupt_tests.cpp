// `carom run --checkpoint` around an interruption: a run stopped by Ctrl-C (SIGINT) leaves a
// checkpoint that resumes to the same end, byte for byte, as a run never stopped; and a run
// killed between the two renames of a checkpoint (FILE → FILE.prev, FILE.tmp → FILE) leaves two
// complete checkpoints, the missing FILE pointing at FILE.prev (docs/checkpoints.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "commands/run_command.hpp"
#include "options/exit_codes.hpp"
#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

// The box of 1000 to t = 20 with checkpoints every 10: FILE holds t = 20, FILE.prev t = 10.
TEST(RunInterrupt, KillBetweenTheTwoRenamesLeavesTwoCompleteCheckpoints) {
  const ScratchDir dir;
  const std::string checkpoint = (dir / "box.ckpt").string();
  const ToolRun first =
      run_carom({"run", example("box-of-1000.json"), "--until", "20", "--checkpoint", checkpoint,
                 "--checkpoint-every", "10", "--save", (dir / "first.json").string(), "--quiet"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  // Writing the checkpoint at t = 20 went: FILE.tmp written and synced; FILE (t = 10) renamed to
  // FILE.prev; FILE.tmp renamed to FILE. A kill between the two renames leaves FILE.prev (t = 10)
  // and FILE.tmp (t = 20), no FILE: undoing the second rename makes exactly that state (a real
  // kill cannot be timed into a gap of microseconds).
  std::filesystem::rename(checkpoint, checkpoint + ".tmp");

  const ToolRun missing = run_carom(
      {"run", "--resume", checkpoint, "--until", "20", "--save", (dir / "never.json").string()});
  EXPECT_EQ(missing.exit_code, kExitUsage);
  EXPECT_THAT(missing.err, HasSubstr(checkpoint + ".prev holds the checkpoint before it"));
  EXPECT_FALSE(std::filesystem::exists(dir / "never.json"));

  const std::string first_end = read_file(dir / "first.json");
  ASSERT_FALSE(first_end.empty());
  for (const std::string suffix : {".prev", ".tmp"}) {
    const std::string out = (dir / ("resumed" + suffix + ".json")).string();
    const ToolRun resumed = run_carom(
        {"run", "--resume", checkpoint + suffix, "--until", "20", "--save", out, "--quiet"});
    ASSERT_EQ(resumed.exit_code, 0) << suffix << ": " << resumed.err;
    EXPECT_EQ(read_file(out), first_end) << "resumed from FILE" << suffix;
  }
}

TEST(RunInterrupt, CtrlCLeavesACheckpointThatResumesBitIdentical) {
  const ScratchDir dir;
  // 300 time units of the box of 1000: >10⁵ contacts, a large fraction of a second at least.
  const ToolRun reference = run_carom({"run", example("box-of-1000.json"), "--until", "300",
                                       "--save", (dir / "reference.json").string(), "--quiet"});
  ASSERT_EQ(reference.exit_code, 0) << reference.err;

  // The same run with a checkpoint every time unit; Ctrl-C as soon as the first one (t = 1)
  // exists, so the run is stopped at some time near the start, wherever the signal lands.
  const std::string checkpoint = (dir / "box.ckpt").string();
  const pid_t child = start_carom({"run", example("box-of-1000.json"), "--until", "300",
                                   "--checkpoint", checkpoint, "--checkpoint-every", "1", "--save",
                                   (dir / "interrupted.json").string(), "--quiet"});
  ASSERT_GT(child, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!std::filesystem::exists(checkpoint) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(::kill(child, SIGINT), 0);
  const int status = wait_for_exit(child);
  // 130: stopped by the interrupt, with the checkpoint written at the stop. (0 would mean the
  // run finished before the signal arrived: the test's timing failed, not the tool.)
  ASSERT_EQ(status, kExitInterrupted) << "the run was not interrupted";

  const std::string resumed_end = (dir / "resumed.json").string();
  const ToolRun resumed = run_carom(
      {"run", "--resume", checkpoint, "--until", "300", "--save", resumed_end, "--quiet"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const std::string reference_end = read_file(dir / "reference.json");
  ASSERT_FALSE(reference_end.empty());
  EXPECT_EQ(read_file(resumed_end), reference_end);  // byte for byte
}

}  // namespace
}  // namespace carom::cli::test
