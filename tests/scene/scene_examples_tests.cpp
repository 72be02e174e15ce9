// Every scene in examples/ loads, builds, runs a little and stays valid: the examples are shared
// by the docs, the CLI and the benchmarks, so a broken one is caught here first.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "carom/scene.hpp"

namespace carom {
namespace {

std::vector<std::filesystem::path> example_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(CAROM_EXAMPLES_DIR)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

constexpr std::size_t kAuditLimit = 5000;

TEST(SceneExamples, TheSharedScenesAreThere) {
  std::vector<std::string> names;
  for (const auto& file : example_files()) names.push_back(file.stem().string());
  for (const char* wanted :
       {"two-moving-balls", "newtons-cradle", "billiards", "billiards-frictionless", "box-of-1000",
        "pinball", "periodic-gas", "gravity-drop", "pinball-gravity", "marble-pile", "compression",
        "stirred-box"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), wanted), names.end()) << wanted;
  }
}

TEST(SceneExamples, EachLoadsRunsAndPassesTheAudit) {
  for (const auto& file : example_files()) {
    SCOPED_TRACE(file.string());
    const Scene scene = load_scene(file);
    SceneWorld built = make_world(scene);
    // World::audit compares every pair; for the 10⁵-disk gas the grid-based check of
    // parse_scene on the saved state (below) does the same job in O(N).
    const bool audit = built.balls.size() <= kAuditLimit;
    // With gravity the kinetic energy trades with the potential: their sum is what is kept.
    const auto energy = [&built] {
      return built.world.kinetic_energy() + built.world.potential_energy();
    };
    const double energy_before = energy();
    // The potential's zero is arbitrary, so tolerances are relative to both parts' sizes.
    const double scale = built.world.kinetic_energy() + std::abs(built.world.potential_energy());
    if (scene.world.boundary == Boundary::open) {
      // Open scenes have few contacts (the two balls meet once, then fly apart): they run for a
      // time, where a count of contacts would end by the proof that no more will come, which is
      // World::run_collisions's own business (WorldStop.*, the "When nothing will happen" tests).
      static_cast<void>(step_scene(built, 1.0));
    } else {
      // A few contacts per ball at most, so the 10⁵-disk gas stays quick.
      // (A shot runs to rest.)
      const std::uint64_t collisions =
          !scene.shots.empty()
              ? std::numeric_limits<std::uint64_t>::max()
              : std::min<std::uint64_t>(2000, 5 * static_cast<std::uint64_t>(built.balls.size()));
      static_cast<void>(run_scene_collisions(built, collisions));
    }
    if (audit) {
      const auto problem = built.world.audit();
      EXPECT_FALSE(problem.has_value()) << *problem;
    }
    // Elastic scenes keep their energy to rounding; the others can only lose it (pockets take
    // balls away, restitution < 1 dissipates, and a ball resting under gravity has lost the
    // bounce it would have had), never gain more than a rounding.
    const bool elastic =
        scene.world.restitution == 1.0 && scene.pockets.empty() &&
        std::all_of(built.scene.balls.begin(), built.scene.balls.end(),
                    [](const SceneBall& b) { return b.restitution.value_or(1.0) == 1.0; });
    // Growth pumps energy in and a thermostat sets it: SceneWorld.Thermostat* check those.
    // Moving walls do work on the balls (WorldMovingWalls.* checks it against their energy).
    const bool energy_set = scene.world.growth_rate != 0.0 || scene.thermostat.has_value() ||
                            !scene.segment_motions.empty() || !scene.arc_motions.empty();
    if (!scene.shots.empty()) {
      // A cue strikes energy in and the cloth takes it out: the run ends with every shot struck
      // and every ball at rest.
      EXPECT_EQ(built.shots_taken, scene.shots.size());
      EXPECT_TRUE(built.world.at_rest());
      EXPECT_EQ(energy(), 0.0);
    } else if (energy_set) {
      EXPECT_GT(energy(), 0.0);
    } else if (elastic) {
      EXPECT_NEAR(energy(), energy_before, 1e-9 * scale);
    } else {
      EXPECT_LE(energy(), energy_before + 1e-12 * scale);
    }
    // Saving and loading the state gives back the same text.
    const std::string saved = to_json_text(capture_scene(built));
    EXPECT_EQ(to_json_text(parse_scene(saved, file.string())), saved);
  }
}

TEST(SceneExamples, NewtonsCradlePassesTheSpeedDownTheRow) {
  SceneWorld built =
      make_world(load_scene(std::filesystem::path(CAROM_EXAMPLES_DIR) / "newtons-cradle.json"));
  // The striker (speed 2) reaches the row at t = 3.5; by t = 5 the chain has been resolved.
  step_scene(built, 5.0);
  // Equal masses, elastic, in line: the striker stops and the last ball leaves at speed 2,
  // exactly (each bounce exchanges the velocities, no rounding for these values).
  EXPECT_EQ(built.world.velocity(built.by_name.at("striker")).x, 0.0);
  EXPECT_EQ(built.world.velocity(built.by_name.at("ball5")).x, 2.0);
  for (const char* middle : {"ball1", "ball2", "ball3", "ball4"}) {
    EXPECT_EQ(built.world.velocity(built.by_name.at(middle)).x, 0.0) << middle;
  }
}

TEST(SceneExamples, BilliardsBreakPotsBalls) {
  SceneWorld built = make_world(
      load_scene(std::filesystem::path(CAROM_EXAMPLES_DIR) / "billiards-frictionless.json"));
  std::vector<PottedBall> potted;
  step_scene(built, 20.0, nullptr, &potted);
  // Without friction the balls keep moving; in 20 s some must find a pocket. Each potting removes
  // exactly one ball (the pockets are sensors, not balls).
  EXPECT_FALSE(potted.empty());
  EXPECT_EQ(built.world.ball_count(), 16 - potted.size());
  EXPECT_FALSE(built.world.audit().has_value());
}

// Under gravity the six inelastic balls bounce round the bumpers, drain between the flippers and
// come to rest in the catch basin below them (the description promises rest by t = 8.3 s).
TEST(SceneExamples, PinballUnderGravityDrainsIntoTheBasinAndRests) {
  SceneWorld built =
      make_world(load_scene(std::filesystem::path(CAROM_EXAMPLES_DIR) / "pinball-gravity.json"));
  const double energy_before = built.world.kinetic_energy() + built.world.potential_energy();
  step_scene(built, 10.0);
  std::size_t movable = 0;
  for (const BallId id : built.balls) {
    if (built.world.mass(id) == kImmovable) continue;
    ++movable;
    // The flippers' tips are at height 0.2; the basin's V is 0.03 to 0.13 high.
    EXPECT_LT(built.world.position(id).y, 0.2) << built.world.position(id).x;
    EXPECT_EQ(built.world.velocity(id), Vec2{});
  }
  EXPECT_EQ(movable, 6U);
  EXPECT_EQ(built.world.kinetic_energy(), 0.0);
  EXPECT_LT(built.world.potential_energy(), 0.1 * energy_before);
  EXPECT_FALSE(built.world.audit().has_value());
}

}  // namespace
}  // namespace carom
