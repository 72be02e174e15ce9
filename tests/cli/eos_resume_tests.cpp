// A sweep's checkpoints: every run `carom eos --out DIR` finishes is kept in DIR/points, exactly
// (gas_record.hpp: every number the reports read, to the bit); a sweep started again with the
// same options reads the runs kept and makes only the others, and its outputs are the same bytes
// as a sweep never stopped — after a partial sweep, and after one killed outright. A file of
// another run, or one cut short, is run again; a run that fails is reported and its point left
// out while the others are written.
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

#include "gas/gas_options.hpp"
#include "gas/gas_record.hpp"
#include "gas/gas_report.hpp"
#include "gas/gas_session.hpp"
#include "options/exit_codes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

std::vector<std::string> resumable_sweep(const std::string& etas,
                                         const std::filesystem::path& out) {
  return {"eos",     etas, "--n",       "64", "--equilibrate", "5",         "--collisions", "40",
          "--seeds", "2",  "--threads", "2",  "--out",         out.string()};
}

TEST(GasRecord, KeepsEveryNumberTheReportsRead) {
  GasOptionText text;
  text.n = "64";
  text.eta = "0.4";
  text.equilibrate = "5";
  text.collisions = "40";
  const GasSpec spec = parse_gas_spec(text);
  const GasOutcome outcome = run_gas_session(spec);
  const json record = gas_record(outcome);
  // Through text, as a checkpoint file or a message carries it.
  const GasOutcome back = gas_outcome_from_record(json::parse(record.dump()));
  EXPECT_EQ(gas_json(spec, back), gas_json(spec, outcome));
  EXPECT_EQ(back.results.z.mean, outcome.results.z.mean);
  EXPECT_EQ(back.results.z.blocks, outcome.results.z.blocks);
  EXPECT_EQ(gas_record(back), record);
  json broken = record;
  broken.erase("time");
  EXPECT_THROW(static_cast<void>(gas_outcome_from_record(broken)), std::runtime_error);
  broken = record;
  broken["collisions"] = "many";
  EXPECT_THROW(static_cast<void>(gas_outcome_from_record(broken)), std::runtime_error);
}

TEST(EosResume, APartialSweepGoesOnToTheSameOutputs) {
  const ScratchDir dir;
  const ToolRun whole = run_carom(resumable_sweep("--eta=0.1:0.3:0.1", dir / "whole"));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(json_files_in(dir / "whole" / "points"), 6U);  // 3 points of 2 seeds
  // The first point alone, then the whole sweep in the same folder: 2 runs read, 4 made.
  ASSERT_EQ(run_carom(resumable_sweep("--eta=0.1", dir / "resumed")).exit_code, 0);
  const ToolRun resumed = run_carom(resumable_sweep("--eta=0.1:0.3:0.1", dir / "resumed"));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("2 of 6 runs read from"));
  for (const char* name : {"eos.csv", "eos.md", "eos.svg"}) {
    EXPECT_EQ(read_file(dir / "resumed" / name), read_file(dir / "whole" / name)) << name;
  }
  // Started again once more: every run read, nothing made, the same outputs.
  const ToolRun again = run_carom(resumable_sweep("--eta=0.1:0.3:0.1", dir / "resumed"));
  EXPECT_THAT(again.err, HasSubstr("6 of 6 runs read from"));
  EXPECT_EQ(read_file(dir / "resumed" / "eos.csv"), read_file(dir / "whole" / "eos.csv"));
  // Other options are other runs: nothing is read for them.
  std::vector<std::string> longer = resumable_sweep("--eta=0.1", dir / "resumed");
  longer[7] = "41";  // --collisions
  const ToolRun other = run_carom(longer);
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_THAT(other.err, ::testing::Not(HasSubstr("runs read from")));
}

TEST(EosResume, AKilledSweepGoesOnToTheSameOutputs) {
  const ScratchDir dir;
  // Runs of tens of milliseconds (seconds under the sanitizers), one at a time: the kill, once
  // the first run is kept, falls in the middle of the sweep.
  const auto args = [&dir](const std::string& name) {
    return std::vector<std::string>{
        "eos",          "--eta", "0.1:0.4:0.1", "--n", "100",   "--equilibrate",      "5",
        "--collisions", "300",   "--threads",   "1",   "--out", (dir / name).string()};
  };
  const ToolRun whole = run_carom(args("whole"));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  {
    RunningTool tool(args("killed"));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while ((!std::filesystem::exists(dir / "killed" / "points") ||
            json_files_in(dir / "killed" / "points") < 1) &&
           std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(tool.signal(SIGKILL));
    EXPECT_EQ(tool.wait().exit_code, -1);  // killed: no outputs written
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "killed" / "eos.csv"));
  const std::size_t kept = json_files_in(dir / "killed" / "points");
  ASSERT_GE(kept, 1U);
  const ToolRun resumed = run_carom(args("killed"));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr(std::to_string(kept) + " of 4 runs read from"));
  EXPECT_EQ(read_file(dir / "killed" / "eos.csv"), read_file(dir / "whole" / "eos.csv"));
  EXPECT_EQ(read_file(dir / "killed" / "eos.md"), read_file(dir / "whole" / "eos.md"));
}

TEST(EosResume, AFileOfAnotherRunOrCutShortIsRunAgain) {
  const ScratchDir dir;
  ASSERT_EQ(run_carom(resumable_sweep("--eta=0.2", dir / "a")).exit_code, 0);
  const std::string reference = read_file(dir / "a" / "eos.csv");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "a" / "points")) {
    files.push_back(entry.path());
  }
  ASSERT_EQ(files.size(), 2U);
  // One cut short, the other made to claim another seed.
  const std::string text = read_file(files[0]);
  std::ofstream(files[0], std::ios::trunc) << text.substr(0, text.size() / 2);
  json other = json::parse(read_file(files[1]));
  other["spec"]["seed"] = 999;
  std::ofstream(files[1], std::ios::trunc) << other.dump();
  const ToolRun again = run_carom(resumable_sweep("--eta=0.2", dir / "a"));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, ::testing::Not(HasSubstr("runs read from")));
  EXPECT_EQ(read_file(dir / "a" / "eos.csv"), reference);
}

}  // namespace
}  // namespace carom::cli::test
