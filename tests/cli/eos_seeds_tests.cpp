// `carom eos --seeds K`: each point is K runs, each the very `carom gas` run of its seed; the
// point's mean and its two errors follow their formulas from those runs; one seed changes
// nothing; the error between seeds and the block-average error agree where the blocks are long;
// bad counts are refused by name. across_seeds is checked on numbers worked by hand.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "carom/science/block_average.hpp"
#include "gas/seed_ensemble.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::vector<std::string> kSmallEos{"eos", "--eta",         "0.3", "--n",
                                         "64",  "--equilibrate", "5",   "--collisions",
                                         "40",  "--threads",     "2",   "--json"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(EosSeeds, EachRunIsThatSeedsGasRunAndThePointCombinesThem) {
  const ToolRun run = run_carom(with(kSmallEos, {"--seeds", "4", "--seed", "7"}));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json point = json::parse(run.out)["points"].at(0);
  EXPECT_EQ(point["seeds"], 4);
  EXPECT_EQ(point["first_seed"], 7);
  ASSERT_EQ(point["runs"].size(), 4U);
  double sum = 0.0;
  double squared_errors = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    const json& each = point["runs"][k];
    // The same numbers as the gas of that seed alone, bit for bit.
    const ToolRun single =
        run_carom({"gas", "--eta", "0.3", "--n", "64", "--equilibrate", "5", "--collisions", "40",
                   "--seed", std::to_string(7 + k), "--json"});
    ASSERT_EQ(single.exit_code, 0) << single.err;
    EXPECT_EQ(json::parse(single.out)["Z"], each["Z"]) << "seed " << 7 + k;
    sum += each["Z"].get<double>();
    squared_errors += std::pow(each["Z_err"].get<double>(), 2);
  }
  const double mean = sum / 4;
  double spread = 0.0;
  for (const json& each : point["runs"]) spread += std::pow(each["Z"].get<double>() - mean, 2);
  // The formulas of seed_ensemble.hpp, summed in another order: a few roundings apart.
  EXPECT_NEAR(point["Z"].get<double>(), mean, 1e-14);
  EXPECT_NEAR(point["Z_err"].get<double>(), std::sqrt(squared_errors) / 4, 1e-14);
  EXPECT_NEAR(point["Z_seed_err"].get<double>(), std::sqrt(spread / 3 / 4), 1e-14);
  EXPECT_GT(point["Z_seed_err"].get<double>(), 0.0);
  // The collisions of all four runs.
  long total = 0;
  for (const json& each : point["runs"]) total += each["collisions"].get<long>();
  EXPECT_EQ(point["collisions"].get<long>(), total);
}

TEST(EosSeeds, OneSeedIsTheRunWithoutTheOption) {
  const ToolRun plain = run_carom(kSmallEos);
  const ToolRun one = run_carom(with(kSmallEos, {"--seeds", "1"}));
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(one.exit_code, 0) << one.err;
  // Everything but the wall-clock figures.
  json a = json::parse(plain.out);
  json b = json::parse(one.out);
  for (json* out : {&a, &b}) {
    for (json& point : (*out)["points"]) {
      point.erase("wall_seconds");
      point.erase("collisions_per_second");
    }
  }
  EXPECT_EQ(a, b);
  EXPECT_FALSE(a["points"][0].contains("seeds"));
}

TEST(EosSeeds, OutWritesTheSeedErrorsAndTheTableShowsBoth) {
  const ScratchDir dir;
  std::vector<std::string> args = kSmallEos;
  args.pop_back();  // no --json: the table
  const ToolRun run = run_carom(with(args, {"--seeds", "3", "--out", (dir / "eos").string()}));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("| η | Z | ± blocks | ± seeds | Henderson |"));
  const std::string csv = read_file(dir / "eos" / "eos.csv");
  EXPECT_THAT(csv, HasSubstr("eta,seeds,Z,Z_err,Z_seed_err,Z_henderson,"));
  EXPECT_THAT(csv, HasSubstr("\n0.29999999999999999,3,"));
  EXPECT_THAT(read_file(dir / "eos" / "eos.svg"), HasSubstr("3 seeds a point"));
}

// With blocks far longer than the gas's correlation time (hundreds of collisions a disk), each
// run's block error is an honest standard error, and the spread of 8 independent runs estimates
// the same thing: their ratio follows √(χ²₇/7), inside [0.42, 1.62] with 98 % probability.
// The seeds are fixed, so the test gives the same answer every time.
TEST(EosSeeds, TheErrorBetweenSeedsAgreesWithTheBlockErrorWhereBlocksAreLong) {
  const ToolRun run = run_carom({"eos", "--eta", "0.3:0.5:0.2", "--n", "100", "--equilibrate", "20",
                                 "--collisions", "200", "--seeds", "8", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json out = json::parse(run.out);
  for (const json& point : out["points"]) {
    const double ratio = point["Z_seed_err"].get<double>() / point["Z_err"].get<double>();
    EXPECT_GT(ratio, 0.42) << "eta " << point["eta"];
    EXPECT_LT(ratio, 1.62) << "eta " << point["eta"];
    // And the mean agrees with Henderson's equation of state within a few of its errors (the
    // equation is good to about 0.3 % at these densities).
    EXPECT_NEAR(point["Z"].get<double>(), point["Z_henderson"].get<double>(),
                4 * point["Z_seed_err"].get<double>() + 0.005 * point["Z"].get<double>());
  }
}

TEST(EosSeeds, BadCountsAreRefusedByName) {
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"eos", "--seeds", "0"}, "--seeds \"0\": it must be from 1 to 1000"},
           {{"eos", "--seeds", "1001"}, "--seeds \"1001\": it must be from 1 to 1000"},
           {{"eos", "--seeds", "two"}, "--seeds \"two\""},
           {{"eos", "--seeds", "2", "--seed", "18446744073709551615"},
            "the last seed would pass 2^64 - 1"}}) {
    const ToolRun run = run_carom(args);
    EXPECT_EQ(run.exit_code, 2) << args[2];
    EXPECT_THAT(run.err, HasSubstr(says));
    EXPECT_EQ(run.out, "");
  }
}

TEST(AcrossSeeds, MeanAndBothErrorsByHand) {
  // Means 1, 2, 3 with block errors 0.3, 0.4, 1.2: mean 2; √(0.09 + 0.16 + 1.44)/3 = 1.3/3;
  // standard deviation 1, so 1/√3 between seeds.
  const std::vector<science::BlockEstimate> runs{{1.0, 0.3, 16}, {2.0, 0.4, 16}, {3.0, 1.2, 16}};
  const SeedEstimate e = across_seeds(runs);
  EXPECT_DOUBLE_EQ(e.mean, 2.0);
  EXPECT_DOUBLE_EQ(e.block_error, 1.3 / 3.0);
  EXPECT_DOUBLE_EQ(e.seed_error, 1.0 / std::sqrt(3.0));
  // One run: its own block error, and no spread to speak of.
  const SeedEstimate one = across_seeds(std::vector<science::BlockEstimate>{{5.0, 0.5, 16}});
  EXPECT_EQ(one.mean, 5.0);
  EXPECT_EQ(one.block_error, 0.5);
  EXPECT_EQ(one.seed_error, 0.0);
  EXPECT_TRUE(std::isnan(across_seeds({}).mean));
}

}  // namespace
}  // namespace carom::cli::test
