// carom_bench_goals: the world's speed and memory goals (docs/performance.md) judged on the host
// at hand: which gases to run and in what order, what their figures say of each goal, and the
// report. Running the gases is main.cpp's, through child_process.hpp.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace carom::goals {

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

// The arguments after the tool's path that run `gas`: `bench --n ... --json`, with `seed` and
// `equilibrate` (collisions a disk before the timed runs) as the user typed them.
[[nodiscard]] std::vector<std::string> bench_arguments(const GoalGas& gas, const std::string& seed,
                                                       const std::string& equilibrate);

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
// text (the tool, its build and the machine: tool_text).
[[nodiscard]] std::string goals_text(const std::vector<nlohmann::ordered_json>& benches,
                                     const std::vector<GoalVerdict>& verdicts,
                                     const std::string& footer);
[[nodiscard]] nlohmann::ordered_json goals_json(const std::vector<nlohmann::ordered_json>& benches,
                                                const std::vector<GoalVerdict>& verdicts);

// The report's last two lines: the tool at `tool` and the build it reported in `bench` (one of
// its `carom bench --json` objects), then the machine it reported. A field it lacks reads
// "unknown".
[[nodiscard]] std::string tool_text(const std::string& tool, const nlohmann::json& bench);

}  // namespace carom::goals
