// carom tool: what `carom bench` measured, as text for people and as one JSON object.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bench/machine_info.hpp"

namespace carom::cli {

struct BenchOutcome {
  std::uint64_t n = 0;
  double eta = 0.0;
  std::uint64_t seed = 0;
  double box_side = 0.0;
  std::uint64_t lattice_columns = 0;
  std::uint64_t lattice_rows = 0;
  double setup_seconds = 0.0;  // creating the world and adding every disk
  std::uint64_t equilibration_collisions = 0;
  double equilibration_seconds = 0.0;
  std::uint64_t collisions = 0;  // resolved in the timed runs, all together
  double wall_seconds = 0.0;     // of the timed runs, all together (std::chrono::steady_clock)
  // The timed runs one by one (--repeat), one after another on the same gas, each of
  // `collisions / repetitions.size()` collisions: each one's seconds.
  std::vector<double> repetitions;
  // Growth of the process's peak resident set (getrusage's ru_maxrss) from before the world was
  // created to after equilibration.
  std::uint64_t peak_rss_growth_bytes = 0;
  double energy_drift = 0.0;    // (E_after − E_before) / E_before over the timed run
  double momentum_drift = 0.0;  // |P_after − P_before| / √(2·M·E_before), M the total mass
  bool interrupted = false;     // stopped by a signal: the figures cover the runs up to there
  // --audit: World::audit() after the timed runs, "" when it found nothing; nothing when not asked.
  std::optional<std::string> audit;
  double audit_seconds = 0.0;
  std::string build_type;  // of this binary: the figures mean little below Release
  std::string compiler;
  MachineInfo machine;

  [[nodiscard]] double collisions_per_second() const {
    return static_cast<double>(collisions) / wall_seconds;
  }
  [[nodiscard]] double nanoseconds_per_collision() const {
    return wall_seconds * 1e9 / static_cast<double>(collisions);
  }
  // Of each timed run, in the order they ran.
  [[nodiscard]] std::vector<double> repetition_nanoseconds_per_collision() const;
  // The middle one of those (the mean of the middle two for an even count), and the least: on a
  // host shared with other work, the median is the figure to compare, the least the one the
  // others slowed least.
  [[nodiscard]] double median_nanoseconds_per_collision() const;
  [[nodiscard]] double best_nanoseconds_per_collision() const;
  [[nodiscard]] double bytes_per_ball() const {
    return static_cast<double>(peak_rss_growth_bytes) / static_cast<double>(n);
  }
};

[[nodiscard]] std::string bench_text(const BenchOutcome& outcome);
// Every field above and the three derived rates, numbers with every digit.
[[nodiscard]] nlohmann::ordered_json bench_json(const BenchOutcome& outcome);

}  // namespace carom::cli
