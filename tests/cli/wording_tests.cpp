// What the tool says to people: messages that name what the user typed, and numbers rounded to
// what they mean (JSON keeps every digit).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "options/exit_codes.hpp"
#include "options/readable_number.hpp"
#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

TEST(Wording, AnOptionBeforeTheVerbIsNamedNotTheVerb) {
  const ToolRun version = run_carom({"-V"});
  EXPECT_EQ(version.exit_code, kExitUsage);
  EXPECT_THAT(version.err, StartsWith("carom: error: \"-V\" is not an option of carom itself"));
  EXPECT_THAT(version.err, HasSubstr("did you mean --version?"));
  EXPECT_THAT(version.err, Not(HasSubstr("subcommand")));

  const ToolRun verbose = run_carom({"--verbose", "run", "x.json"});
  EXPECT_EQ(verbose.exit_code, kExitUsage);
  EXPECT_THAT(verbose.err, StartsWith("carom: error: \"--verbose\""));
  EXPECT_THAT(verbose.err, HasSubstr("a verb's options come after the verb: carom run --verbose"));

  const ToolRun none = run_carom({});
  EXPECT_THAT(none.err, HasSubstr("give a verb: sweep, bench"));
}

TEST(Wording, AMessageWithoutAValueQuotesNoEmptyString) {
  const ToolRun run = run_carom({"run", example("two-moving-balls.json")});
  EXPECT_EQ(run.exit_code, kExitUsage);
  EXPECT_THAT(run.err, HasSubstr("--until/--steps/--collisions: give exactly one"));
  EXPECT_THAT(run.err, Not(HasSubstr("\"\"")));
}

TEST(Wording, WholeNumbersWrittenOtherwiseAreExplained) {
  const ToolRun exponent = run_carom({"gas", "--n", "1e9"});
  EXPECT_EQ(exponent.exit_code, kExitUsage);
  EXPECT_THAT(exponent.err, HasSubstr("--n \"1e9\": write it in digits: 1000000000"));
  const ToolRun negative = run_carom({"gas", "--n", "-5"});
  EXPECT_THAT(negative.err, HasSubstr("--n \"-5\": must not be negative"));
  const ToolRun fraction = run_carom({"gas", "--n", "2.5"});
  EXPECT_THAT(fraction.err, HasSubstr("--n \"2.5\": not a whole number"));
}

TEST(Wording, SweepTakesAStandingBallWithoutVb) {
  const ToolRun run = run_carom({"sweep", "--a", "0,0,1", "--va", "4,0", "--b", "3,0,1"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("touch at t = 0.25"));
}

TEST(Wording, DashIsNoFolder) {
  for (const char* verb : {"gas", "eos"}) {
    const ToolRun run = run_carom({verb, "--n", "100", "--out", "-"});
    EXPECT_EQ(run.exit_code, kExitUsage) << verb;
    EXPECT_THAT(run.err, HasSubstr("--out \"-\": names a folder")) << verb;
  }
}

TEST(Wording, DashOIsOut) {
  const ScratchDir dir;
  const std::string out = (dir / "cradle.svg").string();
  const ToolRun run = run_carom({"render", example("newtons-cradle.json"), "-o", out});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(read_file(out), HasSubstr("<svg"));
}

// A scene that loses energy by design says "change"; one that conserves it says "drift".
TEST(Wording, ChangesAreDriftOnlyWhereTheSceneConservesThem) {
  const ToolRun lossy = run_carom(
      {"run", example("billiards-frictionless.json"), "--until", "10", "--stats", "--quiet"});
  ASSERT_EQ(lossy.exit_code, 0) << lossy.err;
  EXPECT_THAT(lossy.out, HasSubstr("(change "));
  EXPECT_THAT(lossy.out, Not(HasSubstr("drift")));
  const ToolRun elastic =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--stats", "--json"});
  const auto stats = nlohmann::json::parse(elastic.out);
  EXPECT_EQ(stats["conservative"], true);
  const ToolRun text =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--stats"});
  EXPECT_THAT(text.out, HasSubstr("(drift "));
}

TEST(ReadableNumbers, FiguresForPeopleAreRoundedToWhatTheyMean) {
  EXPECT_EQ(rounded(1.19048), "1.19");
  EXPECT_EQ(rounded(0.000138216), "0.000138");
  EXPECT_EQ(rounded(1119.6), "1120");
  EXPECT_EQ(rounded(-0.0), "0");
  EXPECT_EQ(readable_count(723.0), "723");
  EXPECT_EQ(readable_count(7240.0), "7.24 thousand");
  EXPECT_EQ(readable_count(1.05534e6), "1.06 million");
  EXPECT_EQ(readable_count(999'700.0), "1 million");
  EXPECT_EQ(readable_count(2.5e9), "2.5 billion");
  EXPECT_EQ(with_error(2.06951, 0.0137684), "2.070 ± 0.014");
  EXPECT_EQ(with_error(0.520888, 0.00555324), "0.5209 ± 0.0056");
  EXPECT_EQ(with_error(1234.4, 56.2), "1234 ± 56");
  EXPECT_EQ(with_error(123456.0, 789.0), "123460 ± 790");
  EXPECT_EQ(with_error(1.5, 0.0), "1.5 ± 0");
  EXPECT_EQ(readable_bytes(512.0), "512 bytes");
  EXPECT_EQ(readable_bytes(3.2e6), "3.2 MB");
  EXPECT_EQ(readable_bytes(1.0505e9), "1.05 GB");
}

TEST(ReadableNumbers, EosPointsAreTheDecimalsTheUserWrote) {
  const ToolRun run =
      run_carom({"eos", "--eta", "0.1:0.7:0.3", "--n", "200", "--collisions", "20", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto points = nlohmann::json::parse(run.out)["points"];
  ASSERT_EQ(points.size(), 3U);
  EXPECT_EQ(points[1]["eta"].get<double>(), 0.4);  // 0.1 + 0.3 is 0.4000000000000001
  EXPECT_EQ(points[2]["eta"].get<double>(), 0.7);
}

}  // namespace
}  // namespace carom::cli::test
