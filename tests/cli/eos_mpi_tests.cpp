// `carom eos` under MPI: `mpirun -n 3` gives the same files as the sweep on one machine, bit for
// bit, and the same JSON but for the wall-clock figures; rank 0 alone prints and writes, every
// rank keeps its runs' checkpoints; a sweep whose rank was killed, started again, gives the same
// files. Skipped, saying why, where the tool was built without MPI or mpirun is missing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

std::vector<std::string> ranked_sweep(const std::filesystem::path& out, bool as_json = true) {
  std::vector<std::string> args{
      "eos",     "--eta", "0.1:0.5:0.1", "--n", "64",    "--equilibrate", "5", "--collisions", "40",
      "--seeds", "2",     "--threads",   "1",   "--out", out.string()};
  if (as_json) args.emplace_back("--json");
  return args;
}

// The JSON without the wall-clock figures, which no two runs share.
json without_timings(json points) {
  for (json& point : points["points"]) {
    for (json& run : point["runs"]) {
      run.erase("wall_seconds");
      run.erase("collisions_per_second");
    }
  }
  return points;
}

TEST(EosMpi, ThreeRanksGiveTheFilesOfOneMachineBitForBit) {
  CAROM_SKIP_WITHOUT_MPI();
  const ScratchDir dir;
  const ToolRun serial = run_carom(ranked_sweep(dir / "serial"));
  ASSERT_EQ(serial.exit_code, 0) << serial.err;
  const ToolRun ranks = run_program(CAROM_MPIRUN, mpirun_args(ranked_sweep(dir / "mpi")));
  ASSERT_EQ(ranks.exit_code, 0) << ranks.err;
  for (const char* name : {"eos.csv", "eos.md", "eos.svg"}) {
    EXPECT_EQ(read_file(dir / "mpi" / name), read_file(dir / "serial" / name)) << name;
  }
  // One JSON document, from rank 0 alone.
  EXPECT_EQ(without_timings(json::parse(ranks.out)), without_timings(json::parse(serial.out)));
  EXPECT_EQ(json_files_in(dir / "mpi" / "points"), 10U);
}

TEST(EosMpi, ASweepWhoseRankWasKilledGoesOnToTheSameFiles) {
  CAROM_SKIP_WITHOUT_MPI();
  const ScratchDir dir;
  // Long enough runs that the kill falls in the middle.
  const auto args = [&dir](const std::string& name) {
    std::vector<std::string> a = ranked_sweep(dir / name, false);
    a[4] = "256";  // --n
    a[8] = "300";  // --collisions
    return a;
  };
  ASSERT_EQ(run_carom(args("serial")).exit_code, 0);
  const pid_t mpirun = start_program(CAROM_MPIRUN, mpirun_args(args("killed")));
  ASSERT_GT(mpirun, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while ((!std::filesystem::exists(dir / "killed" / "points") ||
          json_files_in(dir / "killed" / "points") < 1) &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  // A rank (a child of mpirun running the tool) killed: mpirun ends the whole job.
  bool killed = false;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    std::ifstream stat(entry.path() / "stat");
    std::string pid, name, state;
    pid_t parent = 0;
    if (!(stat >> pid >> name >> state >> parent) || parent != mpirun) continue;
    if (name.find("carom") == std::string::npos) continue;
    killed = ::kill(std::stoi(pid), SIGKILL) == 0;
    break;
  }
  EXPECT_TRUE(killed) << "no rank found to kill";
  EXPECT_NE(wait_for_exit(mpirun), 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "killed" / "eos.csv"));
  const std::size_t kept = json_files_in(dir / "killed" / "points");
  const ToolRun resumed = run_program(CAROM_MPIRUN, mpirun_args(args("killed")));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr(std::to_string(kept) + " of 10 runs read from"));
  for (const char* name : {"eos.csv", "eos.md", "eos.svg"}) {
    EXPECT_EQ(read_file(dir / "killed" / name), read_file(dir / "serial" / name)) << name;
  }
}

}  // namespace
}  // namespace carom::cli::test
