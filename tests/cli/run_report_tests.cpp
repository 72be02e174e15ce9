// The summary of `carom run --stats`, called directly: which figures each form holds, and that the
// energy of gravity is added without changing what a world without gravity reports.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run/run_report.hpp"

namespace carom::cli {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

RunOutcome outcome_without_gravity() {
  RunOutcome o;
  o.scene = "box.json";
  o.end_time = 10.0;
  o.balls_at_start = 2;
  o.balls_at_end = 2;
  o.collisions = 7;
  o.ball_ball = 3;
  o.ball_wall = 4;
  o.energy_before = 4.0;
  o.energy_after = 4.0;
  o.momentum_before = {1.0, 0.0};
  o.momentum_after = {-1.0, 0.0};
  o.movable_mass = 2.0;
  return o;
}

// Two balls of mass 1 falling under g = (0, -10): 60 of potential energy turned into kinetic.
RunOutcome outcome_with_gravity() {
  RunOutcome o = outcome_without_gravity();
  o.gravity = true;
  o.conservative = false;
  o.total_energy_conserved = true;
  o.energy_before = 4.0;
  o.energy_after = 64.0;
  o.potential_before = 100.0;
  o.potential_after = 40.0;
  return o;
}

TEST(RunReport, JsonKeysKeepTheirOrderAndAddTheEnergyOfGravity) {
  const nlohmann::ordered_json report = run_json(outcome_without_gravity());
  std::vector<std::string> keys;
  for (const auto& item : report.items()) keys.push_back(item.key());
  const std::vector<std::string> expected{"scene",
                                          "start_time",
                                          "end_time",
                                          "interrupted",
                                          "stopped",
                                          "balls_at_start",
                                          "balls_at_end",
                                          "collisions",
                                          "ball_ball",
                                          "ball_wall",
                                          "potted",
                                          "collisions_per_second",
                                          "wall_seconds",
                                          "setup_seconds",
                                          "energy_before",
                                          "energy_after",
                                          "conservative",
                                          "energy_change",
                                          "potential_energy_before",
                                          "potential_energy_after",
                                          "total_energy_before",
                                          "total_energy_after",
                                          "total_energy_conserved",
                                          "total_energy_change",
                                          "momentum_before",
                                          "momentum_after",
                                          "momentum_change",
                                          "frames",
                                          "thermostat_work"};
  EXPECT_EQ(keys, expected);
  // Without gravity the total is the kinetic energy, bit for bit, and so is its change.
  EXPECT_EQ(report["potential_energy_before"], 0.0);
  EXPECT_EQ(report["potential_energy_after"], 0.0);
  EXPECT_EQ(report["total_energy_before"], report["energy_before"]);
  EXPECT_EQ(report["total_energy_after"], report["energy_after"]);
  EXPECT_EQ(report["total_energy_change"], report["energy_change"]);
  EXPECT_EQ(report["total_energy_conserved"], report["conservative"]);
}

TEST(RunReport, JsonWithGravityGivesEachEnergy) {
  const nlohmann::ordered_json report = run_json(outcome_with_gravity());
  EXPECT_EQ(report["energy_before"], 4.0);
  EXPECT_EQ(report["energy_after"], 64.0);
  EXPECT_EQ(report["energy_change"], 15.0);
  EXPECT_EQ(report["potential_energy_before"], 100.0);
  EXPECT_EQ(report["potential_energy_after"], 40.0);
  EXPECT_EQ(report["total_energy_before"], 104.0);
  EXPECT_EQ(report["total_energy_after"], 104.0);
  EXPECT_EQ(report["total_energy_change"], 0.0);
  EXPECT_EQ(report["conservative"], false);
  EXPECT_EQ(report["total_energy_conserved"], true);
}

// The potential's zero is arbitrary: the total's change is measured against the kinetic energy
// at the start, or at the end when the balls start at rest.
TEST(RunReport, TotalEnergyChangeIsRelativeToTheKineticEnergy) {
  RunOutcome o = outcome_with_gravity();
  o.potential_after = 40.5;
  EXPECT_DOUBLE_EQ(o.total_energy_change(), 0.5 / 4.0);
  o.energy_before = 0.0;
  o.potential_before = 104.0;
  EXPECT_DOUBLE_EQ(o.total_energy_change(), 0.5 / 64.0);
  o.energy_after = 0.0;
  EXPECT_EQ(o.total_energy_change(), 0.0);
}

TEST(RunReport, TextWithoutGravityHasOneEnergyLine) {
  const std::string text = run_text(outcome_without_gravity());
  EXPECT_THAT(text, HasSubstr("\nenergy          4 -> 4 (drift 0)\n"));
  EXPECT_THAT(text, HasSubstr("\nmomentum        (1, 0) -> (-1, 0) (drift 0.5)\n"));
  EXPECT_THAT(text, Not(HasSubstr("potential")));
  EXPECT_THAT(text, Not(HasSubstr("total")));
  EXPECT_THAT(text, Not(HasSubstr("kinetic")));
}

TEST(RunReport, TextWithGravityShowsEachEnergyAndTheTotalsDrift) {
  const std::string text = run_text(outcome_with_gravity());
  EXPECT_THAT(text, HasSubstr("\nkinetic energy  4 -> 64 (change 15)\n"
                              "potential       100 -> 40\n"
                              "total energy    104 -> 104 (drift 0)\n"
                              "momentum        (1, 0) -> (-1, 0) (change 0.5)\n"));
  EXPECT_THAT(text, Not(HasSubstr("\nenergy ")));
  // Where contacts lose energy, the total's change is physics too.
  RunOutcome lossy = outcome_with_gravity();
  lossy.total_energy_conserved = false;
  lossy.potential_after = 30.0;
  EXPECT_THAT(run_text(lossy), HasSubstr("total energy    104 -> 94 (change -2.5)\n"));
}

}  // namespace
}  // namespace carom::cli
