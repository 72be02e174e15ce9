// `carom gas` and `carom eos`: a small run gives every key of the report, --out writes every
// file, and bad options give one message naming the option and value, with exit status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::vector<std::string> kSmallGas{"gas",           "--n", "64",           "--eta", "0.3",
                                         "--equilibrate", "5",   "--collisions", "40",    "--json"};

TEST(GasJson, HasEveryKeyOfTheIssue) {
  const ToolRun run = run_carom(kSmallGas);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json out = json::parse(run.out);
  for (const char* key : {"n", "eta", "collisions", "time", "kT", "Z", "Z_err", "collision_rate",
                          "mean_free_path", "v4_over_v2sq", "g_contact", "psi6", "diffusion",
                          "energy_drift", "wall_seconds", "collisions_per_second"}) {
    EXPECT_TRUE(out.contains(key)) << key;
  }
  EXPECT_EQ(out["n"], 64);
  // The velocities are scaled to kT = 1, which the elastic run keeps to its rounding: a few
  // thousand contacts move the energy by some 10⁻¹⁵ (the world's conservation tests hold 10⁻¹⁰
  // over 10⁷), so 10⁻¹² is far above the rounding and far below any real change.
  EXPECT_NEAR(out["kT"].get<double>(), 1.0, 1e-12);
  EXPECT_GT(out["Z"].get<double>(), 1.0);
  EXPECT_GT(out["collisions"].get<double>(), 0.0);
}

TEST(GasOut, WritesHistogramsAndPlots) {
  const ScratchDir dir;
  std::vector<std::string> args = kSmallGas;
  args.insert(args.end(), {"--out", (dir / "run").string()});
  const ToolRun run = run_carom(args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name : {"rdf.csv", "speed.csv", "psi6_local.csv", "msd.csv", "disks.csv",
                           "rdf.svg", "speed.svg", "psi6_map.svg", "msd.svg"}) {
    EXPECT_FALSE(read_file(dir / "run" / name).empty()) << name;
  }
  EXPECT_THAT(read_file(dir / "run" / "speed.svg"), HasSubstr("Maxwell"));
}

struct BadOption {
  std::vector<std::string> args;
  std::string says;
};

TEST(GasErrors, NameTheOptionAndExitWithTwo) {
  const std::vector<BadOption> cases{
      {{"gas", "--n", "1"}, "--n \"1\": at least 2 disks"},
      {{"gas", "--eta", "0.95"}, "--eta \"0.95\""},
      {{"gas", "--n", "10", "--eta", "0.8"}, "this gas can start at packing fraction"},
      {{"gas", "--n", "2", "--eta", "0.3"}, "periodic box is only"},
      {{"gas", "--mix", "1.4"}, "the colon between D and F is missing"},
      {{"gas", "--mix", "1.4:1.5"}, "the fraction must lie in (0, 1)"},
      {{"gas", "--collisions", "0"}, "--collisions \"0\""},
      {{"gas", "--blocks", "1"}, "--blocks \"1\""},
      {{"eos", "--eta", "0.3:0.1:0.1"}, "TO must not be below FROM"},
      {{"eos", "--eta", "0.1:0.2:0"}, "the step must be > 0"},
      {{"eos", "--threads", "0"}, "--threads \"0\""},
      {{"gas", "--start", "melt"}, "--start \"melt\": must be lattice or compress"},
  };
  for (const BadOption& bad : cases) {
    const ToolRun run = run_carom(bad.args);
    EXPECT_EQ(run.exit_code, 2) << bad.args[1] << ' ' << run.err;
    EXPECT_THAT(run.err, HasSubstr(bad.says));
    EXPECT_EQ(run.out, "");
  }
}

// A compressed start reaches a packing fraction no lattice of 10 disks holds, and says so.
TEST(GasStart, CompressReachesDenseStatesAndSaysSo) {
  const ToolRun refused = run_carom({"gas", "--n", "10", "--eta", "0.8"});
  ASSERT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("--start compress reaches denser states"));
  const ToolRun run = run_carom({"gas", "--n", "64", "--eta", "0.74", "--start", "compress",
                                 "--equilibrate", "5", "--collisions", "40", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json out = json::parse(run.out);
  EXPECT_EQ(out["start"], "compress");
  EXPECT_GT(out["compression_collisions"].get<double>(), 0.0);
  EXPECT_NEAR(out["kT"].get<double>(), 1.0, 1e-9);
  EXPECT_GT(out["Z"].get<double>(), 5.0);  // dense: Henderson gives 9 at 0.74
  EXPECT_EQ(json::parse(run_carom(kSmallGas).out)["start"], "lattice");
}

TEST(Eos, RunsEveryPointInOrderOnTwoThreads) {
  const ScratchDir dir;
  const ToolRun run =
      run_carom({"eos", "--eta", "0.1:0.3:0.1", "--n", "64", "--equilibrate", "5", "--collisions",
                 "40", "--threads", "2", "--json", "--out", (dir / "eos").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json out = json::parse(run.out);
  ASSERT_EQ(out["points"].size(), 3U);
  EXPECT_DOUBLE_EQ(out["points"][0]["eta"].get<double>(), 0.1);
  EXPECT_DOUBLE_EQ(out["points"][2]["eta"].get<double>(), 0.1 + 2 * 0.1);
  // Each point is the same run as `carom gas` at that η: one World per thread changes nothing.
  const ToolRun single = run_carom(
      {"gas", "--eta", "0.2", "--n", "64", "--equilibrate", "5", "--collisions", "40", "--json"});
  EXPECT_EQ(json::parse(single.out)["Z"], out["points"][1]["Z"]);
  EXPECT_THAT(read_file(dir / "eos" / "eos.svg"), HasSubstr("Henderson"));
  EXPECT_FALSE(read_file(dir / "eos" / "eos.csv").empty());
}

}  // namespace
}  // namespace carom::cli::test
