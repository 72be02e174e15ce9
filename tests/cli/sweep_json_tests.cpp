// `carom sweep --json`: the numbers are the library's, to the last bit.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "carom/bounce.hpp"
#include "carom/sweep.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using nlohmann::json;

// The Makefile's `make run` case.
const std::vector<std::string> kDefaultCase{"sweep", "--a",     "0,0,1", "--va",  "6,2",
                                            "--b",   "8,3,1.5", "--vb",  "-4,-1", "--json"};

json run_json(const std::vector<std::string>& args) {
  const ToolRun run = run_carom(args);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  return json::parse(run.out);
}

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

void expect_same_bits(const json& pair, Vec2 expected) {
  ASSERT_TRUE(pair.is_array());
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_EQ(bits(pair[0].get<double>()), bits(expected.x)) << pair;
  EXPECT_EQ(bits(pair[1].get<double>()), bits(expected.y)) << pair;
}

TEST(SweepJson, DefaultCaseIsTheLibrarysAnswerBitForBit) {
  const json out = run_json(kDefaultCase);
  const Impact impact = sweep_ball_ball({{0, 0}, 1}, {6, 2}, {{8, 3}, 1.5}, {-4, -1});
  ASSERT_TRUE(impact.hit);
  const BounceResult after = bounce({6, 2}, 1.0, {-4, -1}, 1.0, impact.normal, 1.0);

  EXPECT_EQ(out["hit"], true);
  EXPECT_EQ(out["overlapping"], false);
  EXPECT_EQ(bits(out["t"].get<double>()), bits(impact.t));
  expect_same_bits(out["a_at"], impact.a_at);
  expect_same_bits(out["b_at"], impact.b_at);
  expect_same_bits(out["normal"], impact.normal);
  expect_same_bits(out["point"], impact.point);
  expect_same_bits(out["v3"], {10, 3});
  expect_same_bits(out["va_after"], after.velocity_a);
  expect_same_bits(out["vb_after"], after.velocity_b);
  EXPECT_EQ(bits(out["impulse"].get<double>()), bits(after.impulse));
}

TEST(SweepJson, IsOneObjectWithEveryKey) {
  const json out = run_json(kDefaultCase);
  ASSERT_TRUE(out.is_object());
  for (const char* key : {"hit", "overlapping", "t", "a_at", "b_at", "normal", "point", "v3",
                          "va_after", "vb_after", "impulse"}) {
    EXPECT_TRUE(out.contains(key)) << key;
  }
}

TEST(SweepJson, MissHasHitFalseAndNullContact) {
  const json out = run_json(
      {"sweep", "--a", "0,0,1", "--va", "6,2", "--b", "8,3,1.5", "--vb", "-4,2", "--json"});
  EXPECT_EQ(out["hit"], false);
  EXPECT_EQ(out["overlapping"], false);
  for (const char* key :
       {"t", "a_at", "b_at", "normal", "point", "va_after", "vb_after", "impulse"}) {
    EXPECT_TRUE(out.at(key).is_null()) << key;
  }
  expect_same_bits(out["v3"], {10, 0});
}

TEST(SweepJson, HeadOnEqualMassesExchangeVelocitiesExactly) {
  const json out =
      run_json({"sweep", "--a", "0,0,1", "--va", "1,0", "--b", "3,0,1", "--vb", "-1,0", "--json"});
  EXPECT_EQ(out["hit"], true);
  EXPECT_EQ(out["t"].get<double>(), 0.5);
  expect_same_bits(out["normal"], {1, 0});
  expect_same_bits(out["va_after"], {-1, 0});
  expect_same_bits(out["vb_after"], {1, 0});
  EXPECT_EQ(out["impulse"].get<double>(), 2.0);
}

TEST(SweepJson, OverlappingAndSeparatingIsReportedWithoutHit) {
  const json out = run_json(
      {"sweep", "--a", "0,0,1", "--va", "-1,0", "--b", "1.5,0,1", "--vb", "0,0", "--json"});
  EXPECT_EQ(out["hit"], false);
  EXPECT_EQ(out["overlapping"], true);
  EXPECT_TRUE(out["t"].is_null());
}

TEST(SweepJson, ImmovableBallKeepsStillAndMassesAndRestitutionApply) {
  const json out = run_json({"sweep", "--a", "0,0,1", "--va", "4,0", "--b", "3,0,1", "--vb", "0,0",
                             "--mb", "immovable", "--e", "0.5", "--json"});
  EXPECT_EQ(out["hit"], true);
  expect_same_bits(out["vb_after"], {0, 0});
  // A arrives at 4 and leaves at e times that, backwards.
  expect_same_bits(out["va_after"], {-2, 0});
}

TEST(SweepJson, InfIsTheSameAsImmovable) {
  const json word = run_json({"sweep", "--a", "0,0,1", "--va", "4,1", "--b", "3,0,1", "--vb", "0,0",
                              "--ma", "2", "--mb", "immovable", "--json"});
  const json inf = run_json({"sweep", "--a", "0,0,1", "--va", "4,1", "--b", "3,0,1", "--vb", "0,0",
                             "--ma", "2", "--mb", "inf", "--json"});
  EXPECT_EQ(word, inf);
}

}  // namespace
}  // namespace carom::cli::test
