// `carom table`: a standard pool table written as a scene that the other verbs take (a shot from
// standard input), and a size or rack it does not know refused with exit 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

TEST(TableCommand, WritesATableThatAShotTakes) {
  const ScratchDir dir;
  const std::string file = (dir / "nine.json").string();
  const ToolRun table = run_carom({"table", "--size", "8ft", "--rack", "nine", "--out", file});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  const auto scene = nlohmann::json::parse(read_file(file));
  EXPECT_EQ(scene["balls"].size(), 10U);
  EXPECT_EQ(scene["pockets"].size(), 6U);
  EXPECT_TRUE(scene["world"].contains("table"));
  const ToolRun shot =
      run_carom({"shot", "-", "--ball", "cue", "--speed", "4", "--json"}, read_file(file));
  ASSERT_EQ(shot.exit_code, 0) << shot.err;
  EXPECT_TRUE(nlohmann::json::parse(shot.out)["at_rest"].get<bool>());
}

TEST(TableCommand, AnUnknownSizeOrRackIsRefused) {
  const ToolRun size = run_carom({"table", "--size", "10ft"});
  EXPECT_EQ(size.exit_code, 2);
  EXPECT_THAT(size.err, HasSubstr("--size"));
  const ToolRun rack = run_carom({"table", "--rack", "ten"});
  EXPECT_EQ(rack.exit_code, 2);
  EXPECT_THAT(rack.err, HasSubstr("--rack"));
}

}  // namespace
}  // namespace carom::cli::test
