// carom tool: an equation of state's point run with K independent seeds (`carom eos --seeds K`,
// carom.eos(seeds=K)). Each seed is a whole `carom gas` run; the point reports the mean over the
// seeds, the block-average error of that mean (from each run's own blocks), and the standard
// error between the seeds. The two errors agree when the block averages are honest: blocks too
// short for the gas's correlations make the block error too small, and the seeds show it.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "carom/science/block_average.hpp"
#include "gas/gas_options.hpp"
#include "gas/gas_session.hpp"

namespace carom::cli {

// The most seeds a point: more is a typo, not an ensemble.
inline constexpr std::uint64_t kMostSeeds = 1000;

// --seeds: 1 to kMostSeeds; throws UsageError otherwise.
[[nodiscard]] std::uint64_t parse_seed_count(const std::string& text);

// Every point with `seeds` seeds, point by point: seeds spec.seed, spec.seed + 1, ... Throws
// UsageError when the last seed would pass 2^64 − 1.
[[nodiscard]] std::vector<GasSpec> seeded_specs(const std::vector<GasSpec>& points,
                                                std::uint64_t seeds);

// One measured value over K runs.
struct SeedEstimate {
  double mean = 0.0;         // of the runs' means (equal runs weigh equally)
  double block_error = 0.0;  // √(Σ errorₖ²)/K: the runs' block-average errors, combined
  double seed_error = 0.0;   // the runs' means' standard deviation / √K (K − 1 in the variance)
};

[[nodiscard]] SeedEstimate across_seeds(std::span<const science::BlockEstimate> runs);

// A point's estimates over its runs (every one measured).
struct SeededPoint {
  SeedEstimate z, collision_rate, g_contact, psi6, diffusion;
  std::uint64_t collisions = 0;  // all the runs' together
  double time = 0.0;             // all the runs' measured time together
};

[[nodiscard]] SeededPoint combine_seeds(std::span<const GasOutcome> runs);

// {"eta", "n", "seeds", "first_seed", "Z", "Z_err", "Z_seed_err", "Z_henderson", the same three
// for collision_rate, g_contact, psi6 and diffusion, "collisions", "time", "runs": [one
// gas_json per seed]}.
[[nodiscard]] nlohmann::json seeded_point_json(std::span<const GasSpec> specs,
                                               std::span<const GasOutcome> runs);

}  // namespace carom::cli
