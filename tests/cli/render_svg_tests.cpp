// `carom render SCENE --out FILE.svg`: one element per thing in the scene, whole documents only.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "render_scenes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(RenderSvg, OneElementPerBallPocketAndWall) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run =
      run_render({"render", scene, "--color", "name", "--out", (dir / "every.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("every.svg"));
  const std::string svg = read_file(dir / "every.svg");
  EXPECT_THAT(svg, StartsWith("<?xml"));
  EXPECT_THAT(svg, HasSubstr("</svg>\n"));
  // 3 balls and 1 pocket; no legend in name mode.
  EXPECT_EQ(count_of(svg, "<circle"), 4);
  // 4 sides of the box and 2 segments.
  EXPECT_EQ(count_of(svg, "<line"), 6);
  // The polyline and the arc.
  EXPECT_EQ(count_of(svg, "<polyline"), 2);
  // Balls in the scene's own colours, "red" and "#0a0" read as CSS colours.
  EXPECT_THAT(svg, HasSubstr("fill=\"#2060c0\""));
  EXPECT_THAT(svg, HasSubstr("fill=\"#ff0000\""));
  EXPECT_THAT(svg, HasSubstr("fill=\"#00aa00\""));
  EXPECT_THAT(svg, HasSubstr("t = 0 s, 3 balls"));
  EXPECT_FALSE(std::filesystem::exists(dir / "every.svg.tmp"));
}

TEST(RenderSvg, ArrowsForMovingBallsOnlyAndALegendEntry) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run = run_render(
      {"render", scene, "--color", "name", "--arrows", "--out", (dir / "every.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "every.svg");
  // An arrow is a shaft (<line>) and a head (<path>): two moving balls and the legend's mark.
  EXPECT_EQ(count_of(svg, "<path"), 3);
  EXPECT_EQ(count_of(svg, "<line"), 6 + 3);
  EXPECT_THAT(svg, HasSubstr("later if nothing is hit"));
}

TEST(RenderSvg, SpeedModeAddsAScaleLegend) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run =
      run_render({"render", scene, "--color", "speed", "--out", (dir / "every.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "every.svg");
  // 4 discs in the picture and 5 on the scale.
  EXPECT_EQ(count_of(svg, "<circle"), 4 + 5);
  // The scale runs from 0 to the fastest speed, 1 m/s.
  EXPECT_THAT(svg, HasSubstr("speed 0 m/s"));
  EXPECT_THAT(svg, HasSubstr("1 m/s or more"));
  // The resting ball is drawn in the scale's bottom colour, the moving ones in its top colour.
  EXPECT_EQ(count_of(svg, "fill=\"#440154\""), 2);  // resting ball and its legend disc
  EXPECT_EQ(count_of(svg, "fill=\"#fde725\""), 3);  // two moving balls and the legend disc
}

TEST(RenderSvg, TrailsFollowTheBallsPath) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run = run_render({"render", scene, "--color", "name", "--at", "1", "--trails",
                                  "0.5", "--out", (dir / "every.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "every.svg");
  // The polyline and arc, and one trail for each of the two moving balls.
  EXPECT_EQ(count_of(svg, "<polyline"), 2 + 2);
  EXPECT_THAT(svg, HasSubstr("t = 1 s"));
}

}  // namespace
}  // namespace carom::cli::test
