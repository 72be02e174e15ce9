// carom tool: `carom bench --goals`, the world's speed and memory goals (docs/performance.md)
// judged on the host at hand: which gases to run and in what order, and what their figures say of
// each goal. Running the gases is bench_command.cpp's.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace carom::cli {

// One gas of the plan, as `carom bench --n N --eta ETA --collisions-per-ball K --repeat R` runs it.
struct GoalGas {
  std::uint64_t n = 0;
  double eta = 0.0;
  double collisions_per_ball = 0.0;
  std::uint64_t repeats = 0;
};

// For each packing fraction (0.3, then 0.6): 10^4, 10^5, 10^6 disks and 10^4 again, so that
// 10^4's figure, which 10^6's is held to, is taken both before and after it (a shared host's
// speed drifts by a fifth within minutes, docs/performance.md).
[[nodiscard]] std::vector<GoalGas> goal_plan();

// What a gas's run gave, read from its `carom bench --json` object.
struct GasFigures {
  std::uint64_t n = 0;
  double eta = 0.0;
  std::vector<double> nanoseconds;  // each timed run's, per collision
  double bytes_per_ball = 0.0;
};
// Throws std::invalid_argument naming the field when the object lacks one.
[[nodiscard]] GasFigures gas_figures(const nlohmann::json& bench);

struct GoalVerdict {
  std::string goal;      // as the goals state it
  std::string measured;  // the figure and what it came from, for people
  double value = 0.0;    // in the goal's own unit (M collisions/s, a ratio, bytes a ball)
  double limit = 0.0;
  bool met = false;
};

// The seven goals, in their order: at least 2.5 M collisions a second at 10^4 and 1.5 M at
// 10^5 (each packing fraction; the median of the gas's timed runs, 10^4's runs pooled), 10^6 at
// most twice 10^4's cost a collision (medians again), and at most 128 bytes a ball at 10^6 (the
// larger of the two packing fractions': smaller worlds' figures carry the process's fixed
// allocations). Throws std::invalid_argument when a gas the goals need is missing.
[[nodiscard]] std::vector<GoalVerdict> judge_goals(const std::vector<GasFigures>& gases);

// `benches` are the gases' `carom bench --json` objects in the order they ran; `footer` ends the
// text (the build and the machine).
[[nodiscard]] std::string goals_text(const std::vector<nlohmann::ordered_json>& benches,
                                     const std::vector<GoalVerdict>& verdicts,
                                     const std::string& footer);
[[nodiscard]] nlohmann::ordered_json goals_json(const std::vector<nlohmann::ordered_json>& benches,
                                                const std::vector<GoalVerdict>& verdicts);

}  // namespace carom::cli
