// carom tool: the summary `carom run --stats` prints, as text or one JSON object.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom::cli {

struct RunOutcome {
  std::string scene;
  std::size_t balls_at_start = 0;
  std::size_t balls_at_end = 0;
  double start_time = 0.0;  // scene time
  double end_time = 0.0;
  std::uint64_t collisions = 0;  // every contact resolved, pocket contacts included
  std::uint64_t ball_ball = 0;
  std::uint64_t ball_wall = 0;
  std::uint64_t potted = 0;
  std::uint64_t frames = 0;
  double setup_seconds = 0.0;  // loading the scene and building the world
  double wall_seconds = 0.0;   // the run itself, writing outputs included
  double energy_before = 0.0;  // kinetic
  double energy_after = 0.0;
  // The potential energy of gravity (World::potential_energy); 0 without gravity.
  double potential_before = 0.0;
  double potential_after = 0.0;
  bool gravity = false;  // whether the world has gravity (the text then shows every energy)
  Vec2 momentum_before;
  Vec2 momentum_after;
  double movable_mass = 0.0;  // at the start
  bool interrupted = false;
  // Why the run stopped short of what was asked (none: it did not).
  StopReason stopped = StopReason::none;
  // Whether the scene conserves kinetic energy and momentum (every restitution 1, no pockets, no
  // moving immovable ball, no gravity): their changes are then numerical drift, otherwise physics.
  bool conservative = true;
  // Whether it conserves the total energy: the same, gravity allowed.
  bool total_energy_conserved = true;
  // With a scene's thermostat: the sum of its changes of kinetic energy over the run.
  std::optional<double> thermostat_work;

  // (E_after - E_before) / E_before; 0 when E_before is 0.
  [[nodiscard]] double energy_change() const;
  [[nodiscard]] double total_energy_before() const { return energy_before + potential_before; }
  [[nodiscard]] double total_energy_after() const { return energy_after + potential_after; }
  // (T_after - T_before) / E_before, the change of the total energy relative to the kinetic
  // energy at the start (at the end when the balls start at rest), because the potential's zero
  // is arbitrary; without gravity it equals energy_change().
  [[nodiscard]] double total_energy_change() const;
  // |P_after - P_before| / sqrt(2·M·E_before): the change of momentum relative to the momentum
  // scale of the gas; 0 when E_before is 0.
  [[nodiscard]] double momentum_change() const;
  [[nodiscard]] double collisions_per_second() const;
};

// "no_more_contacts", "time_limit", "interrupted", "stop_condition"; "" for none.
[[nodiscard]] std::string stop_reason_name(StopReason reason);

[[nodiscard]] std::string run_text(const RunOutcome& outcome);
[[nodiscard]] nlohmann::ordered_json run_json(const RunOutcome& outcome);

}  // namespace carom::cli
