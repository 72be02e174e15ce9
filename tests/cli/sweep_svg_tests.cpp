// `carom sweep --svg FILE`: a whole picture or none, and never a result without its picture.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::vector<std::string> default_case_drawn_to(const std::filesystem::path& file) {
  return {"sweep",   "--a",  "0,0,1", "--va",  "6,2",        "--b",
          "8,3,1.5", "--vb", "-4,-1", "--svg", file.string()};
}

TEST(SweepSvg, WritesAWholeDocumentAndNoTemporaryFile) {
  const ScratchDir dir;
  const ToolRun run = run_carom(default_case_drawn_to(dir / "two.svg"));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr((dir / "two.svg").string()));

  const std::string svg = read_file(dir / "two.svg");
  EXPECT_THAT(svg, StartsWith("<?xml"));
  EXPECT_THAT(svg, HasSubstr("<svg xmlns=\"http://www.w3.org/2000/svg\""));
  EXPECT_THAT(svg, HasSubstr("<circle"));
  EXPECT_THAT(svg, HasSubstr("t = 0.58347"));
  EXPECT_THAT(svg, HasSubstr("</svg>\n"));
  EXPECT_FALSE(std::filesystem::exists(dir / "two.svg.tmp"));
}

TEST(SweepSvg, MissSaysNoContact) {
  const ScratchDir dir;
  const ToolRun run = run_carom({"sweep", "--a", "0,0,1", "--va", "6,2", "--b", "8,3,1.5", "--vb",
                                 "-4,2", "--svg", (dir / "miss.svg").string(), "--json"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(read_file(dir / "miss.svg"), HasSubstr("No contact during the step"));
}

TEST(SweepSvg, ReplacesAnOldFile) {
  const ScratchDir dir;
  ASSERT_EQ(run_carom(default_case_drawn_to(dir / "two.svg")).exit_code, 0);
  const ToolRun run = run_carom({"sweep", "--a", "0,0,1", "--va", "6,2", "--b", "8,3,1.5", "--vb",
                                 "-4,2", "--svg", (dir / "two.svg").string()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(read_file(dir / "two.svg"), HasSubstr("No contact during the step"));
}

TEST(SweepSvg, UnwritablePathIsAnErrorBeforeAnyResult) {
  const ToolRun run = run_carom(default_case_drawn_to("/nonexistent-dir/x.svg"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr("--svg"));
  EXPECT_THAT(run.err, HasSubstr("/nonexistent-dir/x.svg"));
}

TEST(SweepSvg, AFolderInTheWayIsAnErrorAndLeavesNoTemporaryFile) {
  const ScratchDir dir;
  std::filesystem::create_directory(dir / "taken");
  const ToolRun run = run_carom(default_case_drawn_to(dir / "taken"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr("--svg"));
  EXPECT_FALSE(std::filesystem::exists(dir / "taken.tmp"));
}

TEST(SweepSvg, EmptyFileNameIsAnError) {
  const ToolRun run = run_carom(default_case_drawn_to(""));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr("--svg"));
}

}  // namespace
}  // namespace carom::cli::test
