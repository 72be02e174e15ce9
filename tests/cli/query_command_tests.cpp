// `carom query`: the world's queries asked of a scene from the command line agree with the library
// asked of the same scene, name balls and pockets by their scene index, run the scene first when
// asked, and refuse bad values naming the option with exit status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "options/exit_codes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

const std::string kBilliards = std::string(CAROM_EXAMPLES_DIR) + "/billiards-frictionless.json";

json query_json(const std::vector<std::string>& args) {
  std::vector<std::string> all{"query", kBilliards};
  all.insert(all.end(), args.begin(), args.end());
  all.emplace_back("--json");
  const ToolRun run = run_carom(all);
  EXPECT_EQ(run.exit_code, kExitSuccess) << run.err;
  return json::parse(run.out);
}

TEST(QueryCommand, TheAimLineIsTheLibrarysBallCast) {
  const json out = query_json({"--ball", "0.635,0.635,0.028575,2,0", "--ignore", "cue"});
  const json& hit = out["results"][0]["answer"];
  SceneWorld sw = make_world(load_scene(kBilliards));
  QueryFilter filter;
  filter.ignore = sw.by_name.at("cue");
  const QueryHit expected = sw.world.cast_ball({0.635, 0.635}, 0.028575, {2.0, 0.0}, filter);
  ASSERT_TRUE(expected);
  EXPECT_EQ(hit["kind"], "ball");
  EXPECT_EQ(hit["ball"], *sw.index_of(expected.ball));
  EXPECT_EQ(hit["fraction"].get<double>(), expected.fraction);
  EXPECT_EQ(hit["center"][0].get<double>(), expected.center.x);
  // Unfiltered, the cast starts inside the cue ball.
  const json inside = query_json({"--ball", "0.635,0.635,0.028575,2,0"});
  EXPECT_EQ(inside["results"][0]["answer"]["ball"], 0);
  EXPECT_EQ(inside["results"][0]["answer"]["overlapping"], true);
}

TEST(QueryCommand, EveryHitOfARayInOrderAndOverlapQueries) {
  const json out = query_json({"--ray", "0,0.6,2.54,0", "--all", "--point", "0,0", "--circle",
                               "1.9,0.63,0.1", "--box", "0,0,1,1"});
  const json& hits = out["results"][0]["answer"];
  ASSERT_GE(hits.size(), 3u);
  for (std::size_t k = 1; k < hits.size(); ++k) {
    EXPECT_LE(hits[k - 1]["fraction"].get<double>(), hits[k]["fraction"].get<double>());
  }
  // The corner pocket: a sensor, which queries do not see.
  EXPECT_EQ(out["results"][1]["answer"], json::array());
  EXPECT_GE(out["results"][2]["answer"].size(), 3u);  // the rack's front
  EXPECT_EQ(out["time"], 0.0);
}

TEST(QueryCommand, AfterARunTheBallsAreWhereTheRunLeftThem) {
  const json start = query_json({"--circle", "0.635,0.635,0.01"});
  EXPECT_EQ(start["results"][0]["answer"], json::array({0}));  // the cue ball on its spot
  const json later = query_json({"--time", "0.05", "--circle", "0.635,0.635,0.01"});
  EXPECT_EQ(later["time"], 0.05);
  EXPECT_EQ(later["results"][0]["answer"], json::array());  // it has moved 0.3 m on
}

TEST(QueryCommand, BadValuesAreRefusedNamingTheOption) {
  for (const auto& [args, option] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--ray", "1,2"}, "--ray"},
           {{"--ball", "0,0,-1,1,0"}, "--ball"},
           {{"--box", "1,1,0,0"}, "--box"},
           {{"--ignore", "nobody", "--point", "0,0"}, "--ignore"},
           {{"--time", "-1", "--point", "0,0"}, "--time"},
           {{}, "--ray"}}) {
    std::vector<std::string> all{"query", kBilliards};
    all.insert(all.end(), args.begin(), args.end());
    const ToolRun run = run_carom(all);
    EXPECT_EQ(run.exit_code, kExitUsage) << option;
    EXPECT_THAT(run.err, HasSubstr(option));
    EXPECT_TRUE(run.out.empty() || run.out.find("results") == std::string::npos);
  }
}

}  // namespace
}  // namespace carom::cli::test
