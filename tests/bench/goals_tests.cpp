// carom_bench_goals: the plan of gases, the arguments each runs with, the verdicts their figures
// give (each limit on both sides) and the reports. The gases themselves take about a minute, so
// the program is run end to end with a stand-in for the tool (goals_program_tests.sh).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "goals.hpp"

namespace carom::goals::test {
namespace {

using ::testing::HasSubstr;

GasFigures gas(std::uint64_t n, double eta, std::vector<double> nanoseconds,
               double bytes_per_ball = 116.0) {
  return {n, eta, std::move(nanoseconds), bytes_per_ball};
}

// Figures that meet every goal: 10^4 at 300 ns (3.3 M/s), 10^5 at 500 (2 M/s), 10^6 at 550.
std::vector<GasFigures> all_met() {
  std::vector<GasFigures> gases;
  for (const double eta : {0.3, 0.6}) {
    gases.push_back(gas(10'000, eta, {300, 310, 290}));
    gases.push_back(gas(100'000, eta, {500, 500, 500}));
    gases.push_back(gas(1'000'000, eta, {550, 560, 540}));
  }
  return gases;
}

std::vector<GoalVerdict> judged(const std::vector<GasFigures>& gases) { return judge_goals(gases); }

TEST(BenchGoals, PlanRunsEachDensitysSizesWithTenThousandBeforeAndAfterTheMillion) {
  const std::vector<GoalGas> plan = goal_plan();
  ASSERT_EQ(plan.size(), 8U);
  const std::uint64_t sizes[] = {10'000, 100'000, 1'000'000, 10'000};
  for (std::size_t k = 0; k < plan.size(); ++k) {
    EXPECT_EQ(plan[k].n, sizes[k % 4]) << k;
    EXPECT_EQ(plan[k].eta, k < 4 ? 0.3 : 0.6) << k;
    EXPECT_GT(plan[k].collisions_per_ball, 0.0);
    EXPECT_GE(plan[k].repeats, 3U);  // a median of at least three
  }
}

TEST(BenchGoals, EachGasRunsAsTheToolsBenchWithTheUsersSeedAndEquilibration) {
  const std::vector<GoalGas> plan = goal_plan();
  EXPECT_EQ(bench_arguments(plan[0], "7", "0.5"),
            (std::vector<std::string>{"bench", "--n", "10000", "--eta", "0.3",
                                      "--collisions-per-ball", "20", "--repeat", "5", "--seed", "7",
                                      "--equilibrate", "0.5", "--json"}));
  const std::vector<std::string> large = bench_arguments(plan[6], "1", "2");
  EXPECT_EQ(large[2], "1000000");
  EXPECT_EQ(large[4], "0.6");
  EXPECT_EQ(large[6], "2");
  EXPECT_EQ(large[8], "3");
  // The values are read back exactly, whatever they are.
  const std::vector<std::string> odd = bench_arguments({12345, 0.1 + 0.2, 2.5, 4}, "1", "2");
  EXPECT_EQ(std::stod(odd[4]), 0.1 + 0.2);
  EXPECT_EQ(odd[6], "2.5");
}

TEST(BenchGoals, FiguresThatMeetEveryGoalAreJudgedSo) {
  const std::vector<GoalVerdict> verdicts = judged(all_met());
  ASSERT_EQ(verdicts.size(), 7U);
  for (const GoalVerdict& verdict : verdicts) EXPECT_TRUE(verdict.met) << verdict.goal;
  EXPECT_THAT(verdicts[0].goal, HasSubstr("2.5 M collisions/s at 10^4, eta 0.3"));
  EXPECT_THAT(verdicts[3].goal, HasSubstr("1.5 M collisions/s at 10^5, eta 0.6"));
  EXPECT_THAT(verdicts[4].goal, HasSubstr("10^6's cost <= 2 x 10^4's, eta 0.3"));
  EXPECT_THAT(verdicts[6].goal, HasSubstr("128 bytes a ball"));
  EXPECT_DOUBLE_EQ(verdicts[0].value, 1e3 / 300.0);  // M/s of the median
  EXPECT_DOUBLE_EQ(verdicts[4].value, 550.0 / 300.0);
}

TEST(BenchGoals, TheRateGoalsHoldAtTheirLimitAndFailJustPastIt) {
  std::vector<GasFigures> gases = all_met();
  gases[0].nanoseconds = {400, 400, 400};  // exactly 2.5 M/s
  gases[4].nanoseconds = {1e3 / 1.5};      // 10^5 at eta 0.6, exactly 1.5 M/s
  std::vector<GoalVerdict> verdicts = judged(gases);
  EXPECT_TRUE(verdicts[0].met);
  EXPECT_TRUE(verdicts[3].met);
  gases[0].nanoseconds = {401, 399, 402};  // median 401: 2.494 M/s
  gases[4].nanoseconds = {670};
  verdicts = judged(gases);
  EXPECT_FALSE(verdicts[0].met);
  EXPECT_FALSE(verdicts[3].met);
  EXPECT_TRUE(verdicts[1].met);  // the other gases are untouched
  EXPECT_TRUE(verdicts[2].met);
}

TEST(BenchGoals, TenThousandsRunsArePooledAcrossItsGasesForItsRateAndTheRatio) {
  std::vector<GasFigures> gases = all_met();
  gases[0].nanoseconds = {380, 390, 395};
  gases.push_back(gas(10'000, 0.3, {420, 430, 440}));  // the run after 10^6, slower
  const std::vector<GoalVerdict> verdicts = judged(gases);
  // Six runs pooled: the median is the mean of 395 and 420.
  EXPECT_DOUBLE_EQ(verdicts[0].value, 1e3 / 407.5);
  EXPECT_DOUBLE_EQ(verdicts[4].value, 550.0 / 407.5);
  EXPECT_THAT(verdicts[0].measured, HasSubstr("of 6 runs"));
}

TEST(BenchGoals, TheMillionMayCostTwiceTenThousandButNoMore) {
  std::vector<GasFigures> gases = all_met();
  gases[2].nanoseconds = {600, 600, 600};  // eta 0.3: exactly 2 × 300
  gases[5].nanoseconds = {601, 590, 700};  // eta 0.6: 601 / 300
  const std::vector<GoalVerdict> verdicts = judged(gases);
  EXPECT_TRUE(verdicts[4].met);
  EXPECT_FALSE(verdicts[5].met);
  EXPECT_THAT(verdicts[5].measured, HasSubstr("601"));
}

TEST(BenchGoals, MemoryIsTheLargerOfTheMillionsFiguresAndSmallerWorldsDoNotCount) {
  std::vector<GasFigures> gases = all_met();
  gases[0].bytes_per_ball = 200.0;  // 10^4: fixed allocations, not judged
  gases[2].bytes_per_ball = 128.0;  // the limit itself
  std::vector<GoalVerdict> verdicts = judged(gases);
  EXPECT_TRUE(verdicts[6].met);
  EXPECT_DOUBLE_EQ(verdicts[6].value, 128.0);
  gases[5].bytes_per_ball = 128.5;
  verdicts = judged(gases);
  EXPECT_FALSE(verdicts[6].met);
  EXPECT_DOUBLE_EQ(verdicts[6].value, 128.5);
}

TEST(BenchGoals, AMissingGasIsNamed) {
  std::vector<GasFigures> gases = all_met();
  gases.erase(gases.begin() + 4);  // 10^5 at eta 0.6
  EXPECT_THAT([&] { (void)judged(gases); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("10^5 disks at eta 0.6")));
}

TEST(BenchGoals, ReadsABenchObjectAndNamesTheFieldItLacks) {
  const nlohmann::json bench = {{"n", 10000},
                                {"eta", 0.3},
                                {"repetition_nanoseconds_per_collision", {410.0, 420.5}},
                                {"bytes_per_ball", 158.5}};
  const GasFigures figures = gas_figures(bench);
  EXPECT_EQ(figures.n, 10000U);
  EXPECT_EQ(figures.eta, 0.3);
  EXPECT_EQ(figures.nanoseconds, (std::vector<double>{410.0, 420.5}));
  EXPECT_EQ(figures.bytes_per_ball, 158.5);
  nlohmann::json lacking = bench;
  lacking.erase("bytes_per_ball");
  EXPECT_THAT([&] { (void)gas_figures(lacking); },
              ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("\"bytes_per_ball\"")));
  nlohmann::json wrong = bench;
  wrong["n"] = "many";
  EXPECT_THROW((void)gas_figures(wrong), std::invalid_argument);
}

std::vector<nlohmann::ordered_json> benches_of(const std::vector<GasFigures>& gases) {
  std::vector<nlohmann::ordered_json> out;
  for (const GasFigures& g : gases) {
    out.push_back({{"n", g.n},
                   {"eta", g.eta},
                   {"repetition_nanoseconds_per_collision", g.nanoseconds},
                   {"bytes_per_ball", g.bytes_per_ball}});
  }
  return out;
}

TEST(BenchGoals, ReportsSayWhichGoalsAreMet) {
  std::vector<GasFigures> gases = all_met();
  gases[2].nanoseconds = {900, 900, 900};  // 3 × 10^4's cost
  const auto benches = benches_of(gases);
  const std::vector<GoalVerdict> verdicts = judged(gases);

  const std::string text = goals_text(benches, verdicts, "  machine: test\n");
  EXPECT_THAT(text, HasSubstr("10^6, eta 0.3"));
  EXPECT_THAT(text, HasSubstr("NO   3 x"));
  EXPECT_THAT(text, HasSubstr("6 of 7 goals met"));
  EXPECT_THAT(text, HasSubstr("machine: test"));

  const nlohmann::ordered_json report = goals_json(benches, verdicts);
  EXPECT_EQ(report["gases"].size(), gases.size());
  ASSERT_EQ(report["goals"].size(), 7U);
  EXPECT_EQ(report["goals"][4]["met"], false);
  EXPECT_EQ(report["goals"][4]["value"], 3.0);
  EXPECT_EQ(report["goals"][4]["limit"], 2.0);
  EXPECT_EQ(report["all_met"], false);
  EXPECT_EQ(goals_json(benches_of(all_met()), judged(all_met()))["all_met"], true);
}

TEST(BenchGoals, TheFooterNamesTheToolItsBuildAndTheMachineItReported) {
  const nlohmann::json bench = {{"n", 10000},
                                {"build_type", "Release"},
                                {"compiler", "GNU 12.2.0"},
                                {"machine",
                                 {{"cpu", "Test CPU"},
                                  {"logical_cpus", 2},
                                  {"l1d_cache_bytes", 49152},
                                  {"l2_cache_bytes", 2097152},
                                  {"l3_cache_bytes", 0}}}};
  EXPECT_EQ(tool_text("build/release/apps/carom/carom", bench),
            "  build: Release, GNU 12.2.0 (the tool build/release/apps/carom/carom)\n"
            "  machine: Test CPU, 2 logical CPUs; caches L1d 48 KiB, L2 2 MiB, L3 unknown\n");
  nlohmann::json bare = bench;
  bare["build_type"] = "";
  bare.erase("machine");
  EXPECT_EQ(tool_text("carom", bare),
            "  build: (no build type), GNU 12.2.0 (the tool carom)\n"
            "  machine: unknown, 0 logical CPUs; caches L1d unknown, L2 unknown, L3 unknown\n");
}

}  // namespace
}  // namespace carom::goals::test
