// `carom pack --seeds K`: K packings, each the very packing `carom pack --seed S` makes (report and
// scene), their means and errors between the seeds; kept in --out as they end and read back by a
// new start; the same under mpirun; bad options refused naming them.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {
// (Named: the tests compile in unity groups, where another file's helpers may share a name.)
namespace pack_seeds {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

// About a tenth of a second a packing (jammed at a reduced pressure of 10^6).
const std::vector<std::string> kJamming{"pack",
                                        "--n",
                                        "120",
                                        "--mix",
                                        "1.4:0.5",
                                        "--rate",
                                        "0.01",
                                        "--until-jammed",
                                        "--pressure-limit",
                                        "1e6",
                                        "-q"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::trunc) << text;
}

json run_json(const std::vector<std::string>& args) {
  const ToolRun run = run_carom(with(args, {"--json"}));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return json::parse(run.out);
}

// A report without the wall-clock figures, which no two runs share.
json without_timings(json report) {
  report.erase("wall_seconds");
  report.erase("collisions_per_second");
  return report;
}

json ensemble_without_timings(json ensemble) {
  for (json& run : ensemble["runs"]) run = without_timings(run);
  return ensemble;
}

TEST(PackSeeds, EachRunIsThatSeedsPackingAndTheMeansAreTheirs) {
  const json ensemble = run_json(with(kJamming, {"--seed", "5", "--seeds", "3", "--threads", "2"}));
  EXPECT_EQ(ensemble["seeds"], 3);
  EXPECT_EQ(ensemble["first_seed"], 5);
  EXPECT_EQ(ensemble["completed"], 3);
  ASSERT_EQ(ensemble["runs"].size(), 3U);
  double sum = 0.0;
  std::vector<double> etas;
  for (std::size_t k = 0; k < 3; ++k) {
    etas.push_back(ensemble["runs"][k]["eta"].get<double>());
    sum += etas.back();
  }
  // The first and the last are their seeds' packings alone (the middle one too; two keep the
  // sanitizer build's suite short).
  for (const std::size_t k : {std::size_t{0}, std::size_t{2}}) {
    const json alone = run_json(with(kJamming, {"--seed", std::to_string(5 + k)}));
    EXPECT_EQ(without_timings(ensemble["runs"][k]), without_timings(alone)) << "seed " << 5 + k;
  }
  const double mean = sum / 3.0;
  EXPECT_NEAR(ensemble["eta"].get<double>(), mean, 1e-15);
  double squares = 0.0;
  for (const double eta : etas) squares += (eta - mean) * (eta - mean);
  EXPECT_NEAR(ensemble["eta_seed_err"].get<double>(), std::sqrt(squares / 2.0 / 3.0), 1e-15);
  EXPECT_GT(ensemble["eta"].get<double>(), 0.8);  // a bidisperse jam: about 0.84
  EXPECT_EQ(ensemble["jammed"], 3);
  for (const char* key : {"Z", "rattler_fraction", "psi6", "pressure"}) {
    EXPECT_TRUE(ensemble[key].is_number()) << key;
    EXPECT_TRUE(ensemble[std::string(key) + "_seed_err"].is_number()) << key;
  }
}

TEST(PackSeeds, TheTextListsEverySeedAndTheMeans) {
  const ToolRun run = run_carom(with(kJamming, {"--seeds", "2"}));
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("2 of 2 packings (seeds 1 to 2) of 120 disks, 2 jammed"));
  EXPECT_THAT(run.out, HasSubstr("mean over the seeds, with the standard error between them"));
  EXPECT_THAT(run.out, HasSubstr("rattler_fraction"));
}

TEST(PackSeeds, OutKeepsEachPackingAndANewStartReadsThem) {
  const ScratchDir dir;
  const std::string out = (dir / "jams").string();
  const json first = run_json(with(kJamming, {"--seeds", "3", "--out", out}));
  for (int seed = 1; seed <= 3; ++seed) {
    EXPECT_TRUE(
        std::filesystem::is_regular_file(dir / ("jams/seed-" + std::to_string(seed) + ".json")));
    EXPECT_TRUE(std::filesystem::is_regular_file(
        dir / ("jams/runs/seed-" + std::to_string(seed) + ".json")));
  }
  // Each scene is the one `carom pack --seed S --out FILE` writes, byte for byte.
  const std::string alone = (dir / "alone.json").string();
  ASSERT_EQ(run_carom(with(kJamming, {"--seed", "2", "--out", alone})).exit_code, 0);
  EXPECT_EQ(read_file(dir / "jams/seed-2.json"), read_file(alone));
  // A seed lost (killed before its checkpoint) is made again; the others are read.
  std::filesystem::remove(dir / "jams/runs/seed-3.json");
  const ToolRun again = run_carom(with(kJamming, {"--seeds", "3", "--out", out, "--json"}));
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("2 of 3 packings read from"));
  EXPECT_EQ(json::parse(again.out)["runs"][0], first["runs"][0]);  // read: timings and all
  EXPECT_EQ(ensemble_without_timings(json::parse(again.out)), ensemble_without_timings(first));
  // Other options: nothing read.
  const ToolRun other =
      run_carom({"pack", "--n", "120", "--mix", "1.4:0.5", "--rate", "0.02", "--until-jammed",
                 "--pressure-limit", "1e6", "-q", "--seeds", "2", "--out", out});
  EXPECT_EQ(other.exit_code, 0) << other.err;
  EXPECT_THAT(other.err, Not(HasSubstr("read from")));
}

TEST(PackSeeds, AKeptReportCutShortOrAlteredIsMadeAgain) {
  const ScratchDir dir;
  const std::string out = (dir / "jams").string();
  const json first = run_json(with(kJamming, {"--seeds", "3", "--out", out}));
  const std::string kept = read_file(dir / "jams/runs/seed-1.json");
  write_file(dir / "jams/runs/seed-1.json", kept.substr(0, kept.size() / 2));
  json altered = json::parse(read_file(dir / "jams/runs/seed-2.json"));
  altered["report"].erase("Z");
  altered["report"]["rattlers"] = "many";
  write_file(dir / "jams/runs/seed-2.json", altered.dump());
  const ToolRun again = run_carom(with(kJamming, {"--seeds", "3", "--out", out, "--json"}));
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("1 of 3 packings read from"));
  EXPECT_EQ(ensemble_without_timings(json::parse(again.out)), ensemble_without_timings(first));
  EXPECT_NE(read_file(dir / "jams/runs/seed-2.json").find("\"Z\""), std::string::npos)
      << "seed 2's report is whole again";
}

// Ctrl-C in the middle: the packings completed are reported, exit status 130; the same command
// then makes only the rest.
TEST(PackSeeds, ASignalReportsThePackingsDoneAndANewStartMakesTheRest) {
  const ScratchDir dir;
  const std::vector<std::string> args{"pack",
                                      "--n",
                                      "200",
                                      "--mix",
                                      "1.4:0.5",
                                      "--rate",
                                      "0.01",
                                      "--until-jammed",
                                      "--pressure-limit",
                                      "1e6",
                                      "-q",
                                      "--seeds",
                                      "3",
                                      "--threads",
                                      "1",
                                      "--out",
                                      (dir / "jams").string()};
  RunningTool tool(args);
  // The first packing (a third of a second here, longer under a sanitizer) ends before the
  // signal, which comes well within the second.
  for (int waited = 0; waited < 3000 && !std::filesystem::exists(dir / "jams/runs/seed-1.json");
       ++waited) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(std::filesystem::exists(dir / "jams/runs/seed-1.json"));
  ASSERT_TRUE(tool.signal(SIGINT));
  const ToolRun stopped = tool.wait();
  EXPECT_EQ(stopped.exit_code, 130) << stopped.err;
  EXPECT_THAT(stopped.out, HasSubstr(" of 3 packings (seeds 1 to 3)"));
  EXPECT_THAT(stopped.err, HasSubstr("the same command makes the rest"));
  EXPECT_FALSE(std::filesystem::exists(dir / "jams/runs/seed-3.json"));
  const ToolRun rest = run_carom(args);
  EXPECT_EQ(rest.exit_code, 0) << rest.err;
  EXPECT_THAT(rest.err, HasSubstr("packings read from"));
  EXPECT_THAT(rest.out, HasSubstr("3 of 3 packings"));
}

TEST(PackSeeds, ThreeRanksGiveWhatOneProcessGives) {
  CAROM_SKIP_WITHOUT_MPI();
  const ScratchDir dir;
  const ToolRun ranks = run_program(
      CAROM_MPIRUN, mpirun_args(with(kJamming, {"--seeds", "3", "--threads", "1", "--out",
                                                (dir / "mpi").string(), "--json"})));
  ASSERT_EQ(ranks.exit_code, 0) << ranks.err;
  const json alone = run_json(with(kJamming, {"--seeds", "3"}));
  EXPECT_EQ(ensemble_without_timings(json::parse(ranks.out)), ensemble_without_timings(alone));
  for (int seed = 1; seed <= 3; ++seed) {
    EXPECT_TRUE(std::filesystem::is_regular_file(
        dir / ("mpi/runs/seed-" + std::to_string(seed) + ".json")));
  }
}

struct BadSeeds {
  const char* name;
  std::vector<std::string> args;
  const char* message;
};

class PackSeedsBadInput : public ::testing::TestWithParam<BadSeeds> {};

TEST_P(PackSeedsBadInput, RefusedNamingTheOptionWithStatusTwo) {
  const ToolRun run = run_carom(with(kJamming, GetParam().args));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr(GetParam().message));
  EXPECT_EQ(run.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    Options, PackSeedsBadInput,
    ::testing::Values(
        BadSeeds{"NoSeeds", {"--seeds", "0"}, "--seeds"},
        BadSeeds{"TooManySeeds", {"--seeds", "1001"}, "--seeds"},
        BadSeeds{"NoThreads", {"--seeds", "2", "--threads", "0"}, "--threads"},
        BadSeeds{"NoThreadsForOne", {"--threads", "0"}, "--threads"},
        BadSeeds{"SeedsPastTheLast", {"--seed", "18446744073709551615", "--seeds", "2"}, "--seeds"},
        BadSeeds{"PictureOfMany", {"--seeds", "2", "--picture", "p.png"}, "--picture"},
        BadSeeds{"StandardOutputAsFolder", {"--seeds", "2", "--out", "-"}, "--out"},
        BadSeeds{"BadStartBeforeAnyRun", {"--seeds", "2", "--start-eta", "0.9"}, "--start-eta"}),
    [](const ::testing::TestParamInfo<BadSeeds>& tested) { return tested.param.name; });

}  // namespace pack_seeds
}  // namespace
}  // namespace carom::cli::test
