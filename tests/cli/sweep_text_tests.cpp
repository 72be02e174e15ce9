// `carom sweep` as text, and the tool's --help and --version.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

TEST(SweepText, SaysWhenTheyTouchAndWhere) {
  const ToolRun run =
      run_carom({"sweep", "--a", "0,0,1", "--va", "1,0", "--b", "3,0,1", "--vb", "-1,0"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_THAT(run.out, HasSubstr("touch at t = 0.5 of the step"));
  EXPECT_THAT(run.out, HasSubstr("A at (0.5, 0)"));
  EXPECT_THAT(run.out, HasSubstr("B at (2.5, 0)"));
  EXPECT_THAT(run.out, HasSubstr("normal (A to B) (1, 0)"));
  EXPECT_THAT(run.out, HasSubstr("velocities after: A (-1, 0)   B (1, 0)   impulse 2"));
}

TEST(SweepText, DefaultCaseShowsT) {
  const ToolRun run =
      run_carom({"sweep", "--a", "0,0,1", "--va", "6,2", "--b", "8,3,1.5", "--vb", "-4,-1"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("t = 0.58347"));
}

TEST(SweepText, MissSaysTheyDoNotTouch) {
  const ToolRun run =
      run_carom({"sweep", "--a", "0,0,1", "--va", "6,2", "--b", "8,3,1.5", "--vb", "-4,2"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("do not touch during the step"));
}

TEST(SweepText, OverlapAtTheStartIsSaid) {
  const ToolRun run =
      run_carom({"sweep", "--a", "0,0,1", "--va", "-1,0", "--b", "1.5,0,1", "--vb", "0,0"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("overlap at the start and are separating"));
}

TEST(Help, ToolHelpExitsZeroAndNamesTheVerbs) {
  const ToolRun run = run_carom({"--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr("sweep"));
}

TEST(Help, SweepHelpExitsZeroAndNamesEveryOption) {
  const ToolRun run = run_carom({"sweep", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option :
       {"--a", "--va", "--b", "--vb", "--ma", "--mb", "--e", "--json", "--svg"}) {
    EXPECT_THAT(run.out, HasSubstr(option)) << option;
  }
}

TEST(Version, PrintsTheProjectVersion) {
  const ToolRun run = run_carom({"--version"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr(CAROM_VERSION));
}

}  // namespace
}  // namespace carom::cli::test
