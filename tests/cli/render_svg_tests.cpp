// `carom render SCENE --out FILE.svg`: one element per thing in the scene, whole documents only.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "carom/vec2.hpp"
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
  // An arrow is a shaft (<line>) and a head (<path>), each over a white outline of its own
  // shape: two moving balls, and the legend's mark (on white paper, without outline).
  EXPECT_EQ(count_of(svg, "<path"), 2 * 2 + 1);
  EXPECT_EQ(count_of(svg, "<line"), 6 + 2 * 2 + 1);
  EXPECT_THAT(svg, HasSubstr("later if nothing is hit"));
}

// The element (from `<` to `>`) at `at`.
std::string element_at(const std::string& svg, std::size_t at) {
  return svg.substr(at, svg.find('>', at) - at + 1);
}

TEST(RenderSvg, EachArrowLiesOnAWhiteOutlineWiderThanItself) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run = run_render(
      {"render", scene, "--color", "name", "--arrows", "--out", (dir / "every.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "every.svg");
  const std::string panel = svg.substr(0, svg.find("<g class=\"legend\">"));
  // In the picture, every arrow head (a filled path) follows its outline's head, and every
  // outline follows the shaft's outline line: white, and drawn first so that it lies below.
  int arrows = 0;
  for (std::size_t at = panel.find("<path d=\""); at != std::string::npos;
       at = panel.find("<path d=\"", at + 1)) {
    const std::string head = element_at(panel, at);
    if (head.find("stroke=") != std::string::npos) continue;  // an outline
    ++arrows;
    EXPECT_THAT(head, HasSubstr("fill=\"#c00000\""));
    // The outline's head comes just before this arrow's shaft, with the same path.
    const std::size_t shaft = panel.rfind("<line", at);
    const std::size_t outline_head = panel.rfind("<path", shaft);
    ASSERT_NE(outline_head, std::string::npos);
    const std::string outline = element_at(panel, outline_head);
    EXPECT_THAT(outline, HasSubstr("fill=\"#ffffff\" stroke=\"#ffffff\""));
    const std::string d = head.substr(0, head.find("\" fill"));
    EXPECT_EQ(outline.substr(0, outline.find("\" fill")), d);
    // The outline's shaft is wider than the arrow's: 3 line widths of 2 pixels against 1.
    const std::size_t outline_shaft = panel.rfind("<line", outline_head);
    EXPECT_THAT(element_at(panel, outline_shaft),
                HasSubstr("stroke=\"#ffffff\" stroke-width=\"6.00\""));
    EXPECT_THAT(element_at(panel, shaft), HasSubstr("stroke=\"#c00000\" stroke-width=\"2.00\""));
  }
  EXPECT_EQ(arrows, 2);
}

// The numbers of the first `<rect` with a width in the panel's clip path: x, y, width, height.
std::vector<double> clip_rect(const std::string& svg) {
  std::vector<double> numbers;
  const std::size_t at = svg.find("<clipPath");
  if (at == std::string::npos) return numbers;
  const std::string rect = element_at(svg, svg.find("<rect", at));
  for (const char* name : {"x=\"", "y=\"", "width=\"", "height=\""}) {
    const std::size_t value = rect.find(name) + std::string(name).size();
    numbers.push_back(std::stod(rect.substr(value, rect.find('"', value) - value)));
  }
  return numbers;
}

// Every point of a polyline's points="x,y x,y ..." in the document, in order.
std::vector<Vec2> polyline_vertices(const std::string& svg) {
  std::vector<Vec2> points;
  const std::string attribute = "<polyline points=\"";
  for (std::size_t at = svg.find(attribute); at != std::string::npos;
       at = svg.find(attribute, at + 1)) {
    const std::size_t begin = at + attribute.size();
    std::string list = svg.substr(begin, svg.find('"', begin) - begin);
    std::size_t start = 0;
    while (start < list.size()) {
      const std::size_t stop = std::min(list.find(' ', start), list.size());
      const std::string pair = list.substr(start, stop - start);
      const std::size_t comma = pair.find(',');
      points.push_back({std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1))});
      start = stop + 1;
    }
  }
  return points;
}

// Two balls fly apart in an open world: their trails reach back to where they started, outside
// the box of where the balls are now, and the picture's view holds them whole.
TEST(RenderSvg, AnOpenWorldsTrailsFitTheView) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  const ToolRun run = run_render(
      {"render", scene, "--at", "1", "--trails", "1", "--out", (dir / "two.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "two.svg");
  const std::vector<double> clip = clip_rect(svg);
  ASSERT_EQ(clip.size(), 4U);
  const std::vector<Vec2> points = polyline_vertices(svg);
  ASSERT_GE(points.size(), 4U);  // two trails, each bent at the contact
  for (const Vec2 p : points) {
    EXPECT_GE(p.x, clip[0]);
    EXPECT_LE(p.x, clip[0] + clip[2]);
    EXPECT_GE(p.y, clip[1]);
    EXPECT_LE(p.y, clip[1] + clip[3]);
  }
}

// Under gravity a trail follows the parabola, not the chord from where the ball was to where it
// is: a ball thrown level at 1 with g = 2 is at (t, −t²); half way the chord from (0, 0) to
// (1, −1) lies 0.125 of its length from the path.
TEST(RenderSvg, TrailsUnderGravityFollowTheParabola) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "throw.json", R"({
    "world": {"gravity": [0, -2]},
    "balls": [{"position": [0, 0], "velocity": [1, 0], "radius": 0.05}]})");
  const ToolRun run = run_render(
      {"render", scene, "--at", "1", "--trails", "1", "--out", (dir / "throw.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::vector<Vec2> points = polyline_vertices(read_file(dir / "throw.svg"));
  ASSERT_GE(points.size(), 65U);
  const Vec2 chord = points.back() - points.front();
  double farthest = 0.0;
  for (const Vec2 p : points) {
    const Vec2 d = p - points.front();
    farthest = std::max(farthest, std::abs(d.x * chord.y - d.y * chord.x) / length(chord));
  }
  EXPECT_NEAR(farthest / length(chord), 0.125, 0.002);
}

// --view: the panel shows that box, 640 pixels on its longer side, cut at its edge.
TEST(RenderSvg, ViewIsTheClippedPanel) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run = run_render({"render", scene, "--color", "name", "--view", "0,0,5,2.5",
                                  "--out", (dir / "half.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "half.svg");
  const std::vector<double> clip = clip_rect(svg);
  ASSERT_EQ(clip.size(), 4U);
  EXPECT_DOUBLE_EQ(clip[2], 640.0);
  EXPECT_DOUBLE_EQ(clip[3], 320.0);
  EXPECT_THAT(svg, HasSubstr("<g class=\"panel\" clip-path=\"url(#panel0)\">"));
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
