// `carom pack`: the report's keys, the packed scene (exact round trip, no overlap, growth off), the
// picture, determinism, a signal's stop with the outputs of the compression so far, and bad values
// named with exit status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "carom/scene.hpp"
#include "options/exit_codes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

// Jams within a second or two: few disks, a fast rate, a low pressure limit.
const std::vector<std::string> kQuickJam{"pack",
                                         "--n",
                                         "150",
                                         "--mix",
                                         "1.4:0.5",
                                         "--rate",
                                         "0.01",
                                         "--until-jammed",
                                         "--pressure-limit",
                                         "1e8",
                                         "--seed",
                                         "4",
                                         "--json",
                                         "-q"};

TEST(PackJson, HasEveryKeyAndAJammedPacking) {
  const ToolRun run = run_carom(kQuickJam);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json out = json::parse(run.out);
  for (const char* key : {"n", "eta", "Z", "jammed", "contacts_mean", "rattlers", "psi6",
                          "collisions", "wall_seconds", "pressure", "end", "contacts"}) {
    EXPECT_TRUE(out.contains(key)) << key;
  }
  EXPECT_EQ(out["n"], 150);
  EXPECT_TRUE(out["jammed"].get<bool>());
  EXPECT_EQ(out["end"], "pressure");
  EXPECT_GE(out["pressure"].get<double>(), 1e8);
  EXPECT_GT(out["eta"].get<double>(), 0.8);
  EXPECT_LT(out["eta"].get<double>(), 0.87);
  EXPECT_GT(out["Z"].get<double>(), 3.0);
  EXPECT_LE(out["Z"].get<double>(), 6.0);
  // The same seed gives the same packing.
  const json again = json::parse(run_carom(kQuickJam).out);
  EXPECT_EQ(again["eta"], out["eta"]);
  EXPECT_EQ(again["collisions"], out["collisions"]);
}

TEST(PackOut, WritesTheScenePackedAndItsPicture) {
  const ScratchDir dir;
  const std::string scene_path = (dir / "packed.json").string();
  const std::string png = (dir / "packed.png").string();
  const std::string svg = (dir / "packed.svg").string();
  const ToolRun run =
      run_carom({"pack", "--n", "120", "--rate", "0.01", "--eta", "0.7", "--boundary", "box",
                 "--aspect", "2", "--json", "-q", "--out", scene_path, "--picture", png});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json out = json::parse(run.out);
  EXPECT_NEAR(out["eta"].get<double>(), 0.7, 1e-12);
  EXPECT_EQ(out["end"], "target");
  EXPECT_FALSE(out["jammed"].get<bool>());

  const Scene scene = load_scene(scene_path);
  ASSERT_EQ(scene.balls.size(), 120U);
  EXPECT_EQ(scene.world.boundary, Boundary::box);
  EXPECT_EQ(scene.world.growth_rate, 0.0);
  EXPECT_DOUBLE_EQ(
      (scene.world.upper.y - scene.world.lower.y) / (scene.world.upper.x - scene.world.lower.x),
      2.0);
  // Written exactly: the scene's packing fraction is the report's, and it writes back the same.
  double covered = 0.0;
  for (const SceneBall& ball : scene.balls) covered += std::numbers::pi * ball.radius * ball.radius;
  const Vec2 side = scene.world.upper - scene.world.lower;
  EXPECT_NEAR(covered / (side.x * side.y), out["eta"].get<double>(), 1e-15);
  EXPECT_EQ(to_json_text(scene), read_file(scene_path));
  const SceneWorld built = make_world(scene);
  EXPECT_EQ(built.world.audit_all_pairs(), std::nullopt);
  EXPECT_EQ(read_file(png).substr(1, 3), "PNG");

  const ToolRun drawn =
      run_carom({"pack", "--n", "100", "--rate", "0.01", "--eta", "0.6", "-q", "--picture", svg});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_THAT(read_file(svg), HasSubstr("<svg"));
  EXPECT_THAT(read_file(svg), HasSubstr("rattlers"));
}

TEST(PackStop, ASignalWritesTheCompressionSoFar) {
  const ScratchDir dir;
  const std::string scene_path = (dir / "partial.json").string();
  RunningTool tool({"pack", "--n", "2000", "--rate", "1e-5", "--eta", "0.85", "-q", "--json",
                    "--out", scene_path});
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  ASSERT_TRUE(tool.signal(SIGINT));
  const ToolRun run = tool.wait();
  ASSERT_EQ(run.exit_code, kExitInterrupted) << run.err;
  EXPECT_THAT(run.err, HasSubstr("interrupted (Ctrl-C) at packing fraction"));
  const json out = json::parse(run.out);
  EXPECT_EQ(out["end"], "interrupted");
  EXPECT_LT(out["eta"].get<double>(), 0.85);
  // The scene still grows: `carom run` on it continues the compression.
  const Scene scene = load_scene(scene_path);
  EXPECT_GT(scene.world.growth_rate, 0.0);
}

struct BadPackOption {
  std::vector<std::string> args;
  std::string says;
};

TEST(PackErrors, NameTheOptionAndExitWithTwo) {
  const std::vector<BadPackOption> cases{
      {{"pack", "--rate", "-1", "--until-jammed"}, "--rate \"-1\""},
      {{"pack", "--rate", "nan", "--until-jammed"}, "--rate \"nan\""},
      {{"pack", "--rate", "inf", "--until-jammed"}, "--rate \"inf\""},
      {{"pack", "--eta", "0.9069"}, "--eta \"0.9069\""},
      {{"pack", "--eta", "0.95"}, "pi/(2*sqrt(3))"},
      {{"pack", "--eta", "0.2"}, "above the start's packing fraction"},
      {{"pack"}, "either --eta"},
      {{"pack", "--eta", "0.5", "--until-jammed"}, "either --eta"},
      {{"pack", "--n", "1", "--until-jammed"}, "--n \"1\""},
      {{"pack", "--n", "5", "--until-jammed"}, "too few for a periodic cell"},
      {{"pack", "--mix", "1.4", "--until-jammed"}, "--mix \"1.4\""},
      {{"pack", "--boundary", "open", "--until-jammed"}, "--boundary \"open\""},
      {{"pack", "--aspect", "0", "--until-jammed"}, "--aspect \"0\""},
      {{"pack", "--start-eta", "0.6", "--until-jammed"}, "--start-eta \"0.6\""},
      {{"pack", "--pressure-limit", "1", "--until-jammed"}, "--pressure-limit \"1\""},
      {{"pack", "--contact-tolerance", "-1", "--until-jammed"}, "--contact-tolerance \"-1\""},
      {{"pack", "--until-jammed", "--picture", "a.jpg"}, "--picture \"a.jpg\""},
  };
  for (const BadPackOption& bad : cases) {
    const ToolRun run = run_carom(bad.args);
    EXPECT_EQ(run.exit_code, kExitUsage) << bad.args.back() << ": " << run.err;
    EXPECT_THAT(run.err, HasSubstr(bad.says)) << bad.args.back();
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

}  // namespace
}  // namespace carom::cli::test
