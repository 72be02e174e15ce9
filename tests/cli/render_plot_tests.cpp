// `carom render SCENE --plot energy|momentum|rate --until T --out FILE.svg`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "drawing/label_placement.hpp"
#include "drawing/render_plot.hpp"
#include "drawing/svg_plot.hpp"
#include "render_scenes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Pointwise;

// The number of points in the first <polyline> after `after`.
int polyline_points(const std::string& svg, std::size_t after = 0) {
  const std::size_t start = svg.find("<polyline points=\"", after);
  if (start == std::string::npos) return 0;
  const std::size_t begin = start + 18;
  const std::size_t end = svg.find('"', begin);
  return count_of(svg.substr(begin, end - begin), " ") + 1;
}

TEST(RenderPlot, EnergyOfAnElasticBoxIsFlatAtEverySample) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "every.json", kEveryKindScene);
  const ToolRun run = run_render({"render", scene, "--plot", "energy", "--until", "20", "--out",
                                  (dir / "energy.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("energy.svg"));
  const std::string svg = read_file(dir / "energy.svg");
  EXPECT_THAT(svg, HasSubstr("Kinetic energy: every.json"));
  EXPECT_THAT(svg, HasSubstr("energy (kg·m²/s²)"));
  EXPECT_EQ(count_of(svg, "<polyline"), 1);
  EXPECT_EQ(polyline_points(svg), kPlotSamples + 1);
  // Elastic contacts in a box keep the energy to rounding; the plot says how close.
  EXPECT_THAT(svg, HasSubstr("largest change |E(t) − E(0)| / E(0) = "));
  EXPECT_THAT(svg, ::testing::Not(HasSubstr("potted")));
}

// Under gravity the plot shows the kinetic, potential and total energy; the total is what elastic
// contacts keep, measured against the largest kinetic energy (the potential's zero is arbitrary).
TEST(RenderPlot, EnergyUnderGravityShowsEachPartAndTheTotal) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "drop.json", R"({
    "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 20], "gravity": [0, -10]},
    "balls": [{"position": [3, 15]}, {"position": [7, 5], "velocity": [1, 0]}]})");
  const ToolRun run = run_render({"render", scene, "--plot", "energy", "--until", "5", "--out",
                                  (dir / "energy.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "energy.svg");
  EXPECT_THAT(svg, HasSubstr("Energy: drop.json"));
  for (const char* series : {">kinetic energy<", ">potential energy<", ">total energy<"}) {
    EXPECT_THAT(svg, HasSubstr(series)) << series;
  }
  EXPECT_EQ(count_of(svg, "<polyline"), 3);
  EXPECT_EQ(polyline_points(svg), kPlotSamples + 1);
  EXPECT_THAT(svg, HasSubstr("largest change |T(t) − T(0)| / max K = "));
}

TEST(RenderPlot, RateCountsTheOneContactOfTheTwoBalls) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  const ToolRun run = run_render(
      {"render", scene, "--plot", "rate", "--until", "1", "--out", (dir / "rate.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "rate.svg");
  EXPECT_THAT(svg, HasSubstr("1 contact in 1 s"));
  // Two step lines (ball–ball, ball–wall), each with two points per bin less one, plus the end.
  EXPECT_EQ(count_of(svg, "<polyline"), 2);
  EXPECT_EQ(polyline_points(svg), 2 * kRateBins + 1);
}

TEST(RenderPlot, MomentumOfAnOpenWorldIsKept) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  const ToolRun run = run_render(
      {"render", scene, "--plot", "momentum", "--until", "2", "--out", (dir / "p.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "p.svg");
  EXPECT_EQ(count_of(svg, "<polyline"), 3);  // x, y and the length
  EXPECT_THAT(svg, HasSubstr("largest change |p(t) − p(0)| = "));
}

// Each <text> element's x, font size and text, in the order written.
struct Text {
  double x;
  double size;
  std::string content;
};
std::vector<Text> texts(const std::string& svg) {
  std::vector<Text> out;
  const auto number = [&](std::size_t at, const std::string& name) {
    const std::size_t value = svg.find(name, at) + name.size();
    return std::stod(svg.substr(value, svg.find('"', value) - value));
  };
  for (std::size_t at = svg.find("<text"); at != std::string::npos;
       at = svg.find("<text", at + 1)) {
    const std::size_t begin = svg.find('>', at) + 1;
    out.push_back({number(at, " x=\""), number(at, "font-size=\""),
                   svg.substr(begin, svg.find("</text>", begin) - begin)});
  }
  return out;
}

// The momentum plot's subtitle is a long sentence: it wraps, every line inside the picture's
// 760 pixels at an average character width of 0.6 font sizes, none of its words lost.
TEST(RenderPlot, MomentumSubtitleWrapsInsideThePicture) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  const ToolRun run = run_render(
      {"render", scene, "--plot", "momentum", "--until", "2", "--out", (dir / "p.svg").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string svg = read_file(dir / "p.svg");
  EXPECT_THAT(svg, HasSubstr("width=\"760.00\""));
  std::string subtitle;
  for (const Text& t : texts(svg)) {
    EXPECT_LE(t.x + 0.6 * t.size * static_cast<double>(count_characters(t.content)), 760.0)
        << t.content;
    if (t.content.rfind("largest change", 0) == 0 || !subtitle.empty()) {
      if (subtitle.find("keeps it)") == std::string::npos) {
        subtitle += (subtitle.empty() ? "" : " ") + t.content;
      }
    }
  }
  EXPECT_THAT(subtitle, ::testing::MatchesRegex(
                            "largest change \\|p\\(t\\) − p\\(0\\)\\| = .* \\(walls and pockets "
                            "take momentum; a periodic or open world keeps it\\)"));
}

TEST(RoundTicks, OneTwoOrFiveTimesAPowerOfTen) {
  // Ticks are k × step: equal to the decimal numbers up to one rounding.
  const auto near = ::testing::DoubleNear(1e-15);
  EXPECT_THAT(round_ticks(0.0, 2.0, 6), Pointwise(near, {0.0, 0.5, 1.0, 1.5, 2.0}));
  EXPECT_THAT(round_ticks(0.0, 100.0, 6), Pointwise(near, {0.0, 20.0, 40.0, 60.0, 80.0, 100.0}));
  EXPECT_THAT(round_ticks(-0.3, 0.3, 6), Pointwise(near, {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3}));
  EXPECT_THAT(round_ticks(3.0, 3.0, 6), ElementsAre(3.0));
}

}  // namespace
}  // namespace carom::cli::test
