// `carom render` with bad input: one message on stderr naming what is wrong and where, exit
// status 2, nothing on stdout, and no output file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ostream>

#include "render_scenes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

struct BadRender {
  std::string name;
  std::vector<std::string> args;  // after "render SCENE"; OUT stands for the output's path
  std::vector<std::string> message_parts;
  std::string scene = kTwoBallsScene;
};

void PrintTo(const BadRender& input, std::ostream* os) { *os << input.name; }

class RenderBadInput : public ::testing::TestWithParam<BadRender> {};

TEST_P(RenderBadInput, OneMessageStatusTwoAndNoFile) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "scene.json", GetParam().scene);
  std::vector<std::string> args{"render", scene};
  for (const std::string& arg : GetParam().args) {
    args.push_back(arg.rfind("OUT", 0) == 0 ? (dir / ("out" + arg.substr(3))).string() : arg);
  }
  const ToolRun run = run_render(args);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(count_of(run.err, "\n"), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("carom render: error: "));
  for (const std::string& part : GetParam().message_parts) EXPECT_THAT(run.err, HasSubstr(part));
  // Nothing but the scene is left in the folder.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

constexpr const char* kBadColourScene = R"({
  "carom_scene": 1,
  "balls": [{"position": [0, 0], "radius": 1, "color": "blurple"}]
})";

INSTANTIATE_TEST_SUITE_P(
    Values, RenderBadInput,
    ::testing::Values(
        BadRender{"UnknownColouring",
                  {"--color", "rainbow", "--out", "OUT.svg"},
                  {"--color \"rainbow\"", "speed, name or auto"}},
        BadRender{"NegativeTime", {"--at", "-1", "--out", "OUT.png"}, {"--at \"-1\"", ">= 0"}},
        BadRender{"NanTime", {"--at", "nan", "--out", "OUT.png"}, {"--at \"nan\""}},
        BadRender{"NegativeUntil",
                  {"--until", "-2", "--plot", "energy", "--out", "OUT.svg"},
                  {"--until \"-2\"", ">= 0"}},
        BadRender{"ZeroUntil",
                  {"--until", "0", "--plot", "energy", "--out", "OUT.svg"},
                  {"--until \"0\"", "> 0"}},
        BadRender{"UnwritablePath",
                  {"--out", "/nonexistent-dir/x.png"},
                  {"--out \"/nonexistent-dir/x.png\"", "does not exist"}},
        BadRender{
            "UnknownPictureFormat", {"--out", "OUT.jpg"}, {"--out", "out.jpg", ".svg or .png"}},
        BadRender{"UnknownAnimationFormat",
                  {"--animate", "OUT.avi", "--until", "1"},
                  {"--animate", ".gif or .mp4"}},
        BadRender{"AnimationWithoutUntil", {"--animate", "OUT.gif"}, {"--until", "--until T"}},
        BadRender{"PlotWithoutUntil", {"--plot", "energy", "--out", "OUT.svg"}, {"--until"}},
        BadRender{"UnknownPlot",
                  {"--plot", "entropy", "--until", "1", "--out", "OUT.svg"},
                  {"--plot \"entropy\"", "energy, momentum, rate"}},
        BadRender{"PlotAsPng",
                  {"--plot", "energy", "--until", "1", "--out", "OUT.png"},
                  {"--out", "must end in .svg"}},
        BadRender{"NothingToWrite", {"--at", "1"}, {"--out", "--animate"}},
        BadRender{"NegativeTrails", {"--trails", "-1", "--out", "OUT.svg"}, {"--trails \"-1\""}},
        BadRender{"ZeroFps",
                  {"--fps", "0", "--until", "1", "--plot", "rate", "--out", "OUT.svg"},
                  {"--fps \"0\"", "out of range"}},
        BadRender{"TooManyFrames",
                  {"--fps", "240", "--until", "1e9", "--animate", "OUT.gif"},
                  {"--fps \"240\"", "frames"}},
        BadRender{"WidthNotWhole", {"--width", "12.5", "--out", "OUT.png"}, {"--width \"12.5\""}},
        BadRender{"WidthTooSmall", {"--width", "10", "--out", "OUT.png"}, {"--width \"10\""}},
        BadRender{"ViewOfThreeNumbers",
                  {"--view", "0,0,5", "--out", "OUT.png"},
                  {"--view \"0,0,5\"", "3 comma-separated parts", "XMIN,YMIN,XMAX,YMAX"}},
        BadRender{"ViewNotANumber",
                  {"--view", "0,0,five,5", "--out", "OUT.png"},
                  {"--view \"0,0,five,5\"", "XMIN,YMIN,XMAX,YMAX"}},
        BadRender{"ViewNan", {"--view", "nan,0,5,5", "--out", "OUT.png"}, {"--view \"nan,0,5,5\""}},
        BadRender{"ViewOfNoWidth",
                  {"--view", "2,0,2,5", "--out", "OUT.png"},
                  {"--view \"2,0,2,5\"", "XMIN must be less than XMAX"}},
        BadRender{"ViewUpsideDown",
                  {"--view", "0,5,5,0", "--out", "OUT.svg"},
                  {"--view \"0,5,5,0\"", "YMIN must be less than YMAX"}},
        BadRender{"ViewTooLarge",
                  {"--view", "-1e308,0,1e308,1", "--out", "OUT.png"},
                  {"--view \"-1e308,0,1e308,1\"", "too large"}},
        BadRender{"ViewEmpty", {"--view", "", "--out", "OUT.png"}, {"--view: ", "empty"}},
        BadRender{"BadSceneColour",
                  {"--out", "OUT.svg"},
                  {"scene.json", "balls[0].color", "blurple", "not a colour"},
                  kBadColourScene},
        BadRender{"MalformedScene",
                  {"--out", "OUT.svg"},
                  {"scene.json:1:", "carom render: error"},
                  "{\"carom_scene\": 1,,}"}),
    [](const ::testing::TestParamInfo<BadRender>& param) { return param.param.name; });

TEST(RenderErrors, MissingSceneFileIsNamed) {
  const ScratchDir dir;
  const ToolRun run =
      run_render({"render", (dir / "no-such.json").string(), "--out", (dir / "x.svg").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(count_of(run.err, "\n"), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("no-such.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.svg"));
}

TEST(RenderErrors, UnwritableOutputIsReportedBeforeTheSceneIsRead) {
  const ScratchDir dir;
  // The scene is missing too; the output is checked first, so it is what the message is about.
  const ToolRun run =
      run_render({"render", (dir / "no-such.json").string(), "--out", "/nonexistent-dir/x.svg"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("/nonexistent-dir/x.svg"));
  EXPECT_THAT(run.err, ::testing::Not(HasSubstr("no-such.json")));
}

TEST(RenderErrors, AFolderInTheWayIsNamed) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  std::filesystem::create_directory(dir / "x.svg");
  const ToolRun run = run_render({"render", scene, "--out", (dir / "x.svg").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("is a folder"));
  EXPECT_TRUE(std::filesystem::is_directory(dir / "x.svg"));
}

TEST(RenderErrors, AFailedRenderKeepsTheOldFile) {
  const ScratchDir dir;
  const std::string good = write_test_scene(dir, "good.json", kTwoBallsScene);
  const std::string bad = write_test_scene(dir, "bad.json", kBadColourScene);
  const std::string out = (dir / "x.svg").string();
  ASSERT_EQ(run_render({"render", good, "--out", out}).exit_code, 0);
  const std::string before = read_file(out);
  EXPECT_EQ(run_render({"render", bad, "--out", out}).exit_code, 2);
  EXPECT_EQ(read_file(out), before);
}

}  // namespace
}  // namespace carom::cli::test
