// `carom bench`: a small run gives every figure, exactly K·N collisions and no drift; bad options
// give one message naming the option and the value, and exit status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <ostream>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

// Small enough to take milliseconds.
const std::vector<std::string> kSmallRun{
    "bench", "--n", "100", "--eta", "0.3", "--collisions-per-ball", "10", "--json"};

json run_json(const std::vector<std::string>& args) {
  const ToolRun run = run_carom(args);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  return json::parse(run.out);
}

TEST(BenchJson, IsOneObjectWithEveryFigure) {
  const json out = run_json(kSmallRun);
  ASSERT_TRUE(out.is_object());
  for (const char* key : {"n",
                          "eta",
                          "seed",
                          "box_side",
                          "lattice_columns",
                          "lattice_rows",
                          "setup_seconds",
                          "equilibration_collisions",
                          "equilibration_seconds",
                          "collisions",
                          "wall_seconds",
                          "collisions_per_second",
                          "nanoseconds_per_collision",
                          "bytes_per_ball",
                          "peak_rss_growth_bytes",
                          "energy_drift",
                          "momentum_drift",
                          "audit",
                          "audit_seconds",
                          "build_type",
                          "compiler",
                          "repetitions",
                          "repetition_nanoseconds_per_collision",
                          "median_nanoseconds_per_collision",
                          "best_nanoseconds_per_collision",
                          "machine"}) {
    EXPECT_TRUE(out.contains(key)) << key;
  }
}

TEST(BenchJson, ResolvesExactlyKTimesNCollisionsAfterTheEquilibration) {
  const json out = run_json(kSmallRun);
  EXPECT_EQ(out["n"], 100);
  EXPECT_EQ(out["eta"], 0.3);
  EXPECT_EQ(out["seed"], 1);  // the default
  EXPECT_EQ(out["collisions"], 1000);
  EXPECT_EQ(out["equilibration_collisions"], 200);  // the default, 2 per ball
  EXPECT_GT(out["wall_seconds"].get<double>(), 0.0);
  EXPECT_GT(out["collisions_per_second"].get<double>(), 0.0);
  EXPECT_GE(out["bytes_per_ball"].get<double>(), 0.0);
}

TEST(BenchJson, ElasticGasKeepsItsEnergyAndMomentum) {
  const json out = run_json(kSmallRun);
  EXPECT_LT(std::abs(out["energy_drift"].get<double>()), 1e-10);
  EXPECT_LT(std::abs(out["momentum_drift"].get<double>()), 1e-10);
}

TEST(BenchJson, BoxGivesThePackingFraction) {
  const json out = run_json(kSmallRun);
  const double side = out["box_side"].get<double>();
  EXPECT_NEAR(100.0 * std::acos(-1.0) / (4.0 * side * side), 0.3, 1e-12);
  EXPECT_GE(out["lattice_columns"].get<int>() * out["lattice_rows"].get<int>(), 100);
}

TEST(BenchJson, FractionalCollisionsPerBallRound) {
  const json out = run_json(
      {"bench", "--n", "100", "--collisions-per-ball", "2.5", "--equilibrate", "0.5", "--json"});
  EXPECT_EQ(out["collisions"], 250);
  EXPECT_EQ(out["equilibration_collisions"], 50);
}

TEST(BenchJson, NoEquilibrationIsAllowed) {
  const json out = run_json(
      {"bench", "--n", "100", "--collisions-per-ball", "1", "--equilibrate", "0", "--json"});
  EXPECT_EQ(out["equilibration_collisions"], 0);
  EXPECT_EQ(out["collisions"], 100);
}

// The same seed gives the same world and the same run: the energy's rounding drift repeats to
// the bit. Another seed gives another gas.
TEST(BenchJson, SameSeedSameRun) {
  std::vector<std::string> args = kSmallRun;
  args.insert(args.end(), {"--seed", "42"});
  const json first = run_json(args);
  const json second = run_json(args);
  EXPECT_EQ(first["seed"], 42);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(first["energy_drift"].get<double>()),
            std::bit_cast<std::uint64_t>(second["energy_drift"].get<double>()));
  args.back() = "43";
  const json other = run_json(args);
  EXPECT_NE(std::bit_cast<std::uint64_t>(first["energy_drift"].get<double>()),
            std::bit_cast<std::uint64_t>(other["energy_drift"].get<double>()));
}

// --repeat R: R timed runs of K·N collisions on the same gas, each one's rate listed, with their
// median and least; the totals are over all of them.
TEST(BenchJson, RepeatedRunsAreEachReportedWithTheirMedianAndLeast) {
  std::vector<std::string> args = kSmallRun;
  args.insert(args.end(), {"--repeat", "3"});
  const json out = run_json(args);
  EXPECT_EQ(out["collisions"], 3000);
  EXPECT_EQ(out["repetitions"], 3);
  const std::vector<double> each = out["repetition_nanoseconds_per_collision"];
  ASSERT_EQ(each.size(), 3u);
  for (const double ns : each) EXPECT_GT(ns, 0.0);
  std::vector<double> sorted = each;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(out["median_nanoseconds_per_collision"].get<double>(), sorted[1]);
  EXPECT_EQ(out["best_nanoseconds_per_collision"].get<double>(), sorted[0]);
  // The totals are over the three runs.
  EXPECT_NEAR(out["nanoseconds_per_collision"].get<double>(),
              out["wall_seconds"].get<double>() * 1e9 / 3000.0, 1e-9);
}

// The runs continue one gas: three runs of K·N collisions end in the very state one run of 3·K·N
// does (World's chunked runs are bit-identical to whole ones), so the drift over them is too.
TEST(BenchJson, RepeatedRunsContinueTheSameGas) {
  const json repeated =
      run_json({"bench", "--n", "100", "--collisions-per-ball", "4", "--repeat", "3", "--json"});
  const json whole = run_json({"bench", "--n", "100", "--collisions-per-ball", "12", "--json"});
  EXPECT_EQ(repeated["collisions"], whole["collisions"]);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(repeated["energy_drift"].get<double>()),
            std::bit_cast<std::uint64_t>(whole["energy_drift"].get<double>()));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(repeated["momentum_drift"].get<double>()),
            std::bit_cast<std::uint64_t>(whole["momentum_drift"].get<double>()));
  EXPECT_EQ(whole["repetitions"], 1);
}

// The host is part of every figure: the processor's name and the caches' sizes, as the system
// reports them (0 where it does not).
TEST(BenchJson, NamesTheMachine) {
  const json machine = run_json(kSmallRun)["machine"];
  ASSERT_TRUE(machine.is_object());
  EXPECT_TRUE(machine["cpu"].is_string());
  EXPECT_FALSE(machine["cpu"].get<std::string>().empty());
  EXPECT_GE(machine["logical_cpus"].get<int>(), 1);
  for (const char* key : {"l1d_cache_bytes", "l2_cache_bytes", "l3_cache_bytes"}) {
    EXPECT_TRUE(machine[key].is_number_unsigned()) << key;
  }
}

TEST(BenchJson, DenseGasRuns) {
  const json out =
      run_json({"bench", "--n", "400", "--eta", "0.7", "--collisions-per-ball", "5", "--json"});
  EXPECT_EQ(out["collisions"], 2000);
  EXPECT_LT(std::abs(out["energy_drift"].get<double>()), 1e-10);
}

TEST(BenchText, SaysTheRateTheMemoryAndTheDrift) {
  const ToolRun run = run_carom({"bench", "--n", "100", "--collisions-per-ball", "3"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_THAT(run.out, HasSubstr("100 equal disks"));
  EXPECT_THAT(run.out, HasSubstr("timed: 300 collisions"));
  EXPECT_THAT(run.out, HasSubstr("collisions/s"));
  EXPECT_THAT(run.out, HasSubstr("bytes per ball"));
  EXPECT_THAT(run.out, HasSubstr("energy"));
  EXPECT_THAT(run.out, HasSubstr("machine: "));
  EXPECT_THAT(run.out, Not(HasSubstr("timed runs")));
}

// Above 256 disks World::audit checks each disk's cell and its 3 x 3 block, as at 10^7.
TEST(BenchAudit, AfterTheTimedRunsWhenAskedForAndNullOtherwise) {
  const json audited = run_json(
      {"bench", "--n", "400", "--eta", "0.6", "--collisions-per-ball", "5", "--audit", "--json"});
  EXPECT_EQ(audited["audit"], "clean");
  EXPECT_GE(audited["audit_seconds"].get<double>(), 0.0);
  EXPECT_EQ(audited["collisions"], 2000);
  const json plain = run_json({"bench", "--n", "400", "--collisions-per-ball", "5", "--json"});
  EXPECT_TRUE(plain["audit"].is_null());
  const ToolRun text = run_carom({"bench", "--n", "400", "--collisions-per-ball", "2", "--audit"});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("audit after the timed runs: clean ("));
  const ToolRun quiet = run_carom({"bench", "--n", "400", "--collisions-per-ball", "2"});
  EXPECT_THAT(quiet.out, Not(HasSubstr("audit")));
}

TEST(BenchText, ListsRepeatedRuns) {
  const ToolRun run =
      run_carom({"bench", "--n", "100", "--collisions-per-ball", "3", "--repeat", "4"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("timed: 1200 collisions"));
  EXPECT_THAT(run.out, HasSubstr("4 timed runs, ns per collision: "));
  EXPECT_THAT(run.out, HasSubstr("median"));
  EXPECT_THAT(run.out, HasSubstr("drift over the timed runs"));
}

TEST(BenchHelp, NamesEveryOptionAndHowMemoryIsMeasured) {
  const ToolRun run = run_carom({"bench", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option : {"--n", "--eta", "--collisions-per-ball", "--equilibrate", "--seed",
                             "--repeat", "--json", "--audit"}) {
    EXPECT_THAT(run.out, HasSubstr(option)) << option;
  }
  EXPECT_THAT(run.out, HasSubstr("ru_maxrss"));
}

TEST(BenchHelp, ToolHelpNamesTheVerb) {
  const ToolRun run = run_carom({"--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr("bench"));
}

struct BadBench {
  std::string name;                        // the test's name
  std::vector<std::string> args;           // after "bench"
  std::vector<std::string> message_parts;  // what the message must contain
};

void PrintTo(const BadBench& input, std::ostream* os) { *os << input.name; }

class BenchBadInput : public ::testing::TestWithParam<BadBench> {};

TEST_P(BenchBadInput, OneMessageNamingOptionAndValueAndStatusTwo) {
  std::vector<std::string> args{"bench"};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  args.push_back("--json");
  const ToolRun run = run_carom(args);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  for (const std::string& part : GetParam().message_parts) {
    EXPECT_THAT(run.err, HasSubstr(part));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Values, BenchBadInput,
    ::testing::Values(
        BadBench{"NoBalls", {"--n", "0"}, {"--n", "\"0\"", "at least 2"}},
        BadBench{"OneBall", {"--n", "1"}, {"--n", "\"1\"", "at least 2"}},
        BadBench{"NegativeCount", {"--n", "-5"}, {"--n", "\"-5\"", "whole number"}},
        BadBench{"FractionalCount", {"--n", "1.5"}, {"--n", "\"1.5\"", "whole number"}},
        BadBench{"WordCount", {"--n", "many"}, {"--n", "\"many\""}},
        BadBench{"EmptyCount", {"--n", ""}, {"--n", "missing"}},
        BadBench{"HugeCount", {"--n", "99999999999999999999999"}, {"--n", "too large"}},
        BadBench{"TooManyBalls", {"--n", "1000000000"}, {"--n", "\"1000000000\"", "at most"}},
        BadBench{"ZeroEta", {"--eta", "0"}, {"--eta", "\"0\"", "0.9069"}},
        BadBench{"NegativeEta", {"--eta", "-0.1"}, {"--eta", "\"-0.1\""}},
        BadBench{"EtaBeyondDensest", {"--eta", "0.95"}, {"--eta", "\"0.95\"", "densest"}},
        BadBench{"NanEta", {"--eta", "nan"}, {"--eta", "\"nan\""}},
        BadBench{"LatticeCannotPlace",
                 {"--n", "100", "--eta", "0.9"},
                 {"--eta", "\"0.9\"", "less than a diameter", "at most"}},
        BadBench{"BoxTooSmall", {"--n", "3", "--eta", "0.5"}, {"--n", "\"3\"", "3 disk diameters"}},
        BadBench{"ZeroCollisions",
                 {"--collisions-per-ball", "0"},
                 {"--collisions-per-ball", "\"0\"", "> 0"}},
        BadBench{"NegativeCollisions",
                 {"--collisions-per-ball", "-1"},
                 {"--collisions-per-ball", "\"-1\""}},
        BadBench{"CollisionsRoundToZero",
                 {"--n", "100", "--collisions-per-ball", "0.001"},
                 {"--collisions-per-ball", "\"0.001\"", "rounds to 0"}},
        BadBench{"TooManyCollisions",
                 {"--collisions-per-ball", "1e300"},
                 {"--collisions-per-ball", "2^53"}},
        BadBench{
            "NegativeEquilibration", {"--equilibrate", "-1"}, {"--equilibrate", "\"-1\"", ">= 0"}},
        BadBench{"NegativeSeed", {"--seed", "-1"}, {"--seed", "\"-1\""}},
        BadBench{"WordSeed", {"--seed", "x"}, {"--seed", "\"x\""}},
        BadBench{"NoRepeats", {"--repeat", "0"}, {"--repeat", "\"0\"", "at least 1"}},
        BadBench{"TooManyRepeats", {"--repeat", "1001"}, {"--repeat", "\"1001\"", "at most 1000"}},
        BadBench{"NegativeRepeats", {"--repeat", "-2"}, {"--repeat", "\"-2\""}},
        BadBench{"FractionalRepeats", {"--repeat", "2.5"}, {"--repeat", "\"2.5\""}},
        BadBench{"RepeatsBeyondExactCounts",
                 {"--n", "1000", "--collisions-per-ball", "1e12", "--repeat", "100"},
                 {"--repeat", "\"100\"", "2^53"}},
        BadBench{"UnknownOption", {"--frobnicate", "3"}, {"--frobnicate", "--help"}}),
    [](const ::testing::TestParamInfo<BadBench>& param) { return param.param.name; });

}  // namespace
}  // namespace carom::cli::test
