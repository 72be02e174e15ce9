// carom tool: one measured run of a hard-disk gas, as `carom gas` and each point of `carom eos`
// make it: build the gas, equilibrate, measure (carom/science/gas_monitor.hpp), time it.
#pragma once

#include <cstdint>

#include "carom/science/gas_monitor.hpp"
#include "gas_options.hpp"

namespace carom::cli {

// Collisions per disk between two samples of the structure (g(r), ψ₆). A sample costs about as
// much as 20 to 40 collisions per disk at the default range of g(r); one every 10 collisions
// per disk keeps the measurements within the 15 % of the world's throughput that docs/
// performance.md measures ("Hard-disk science").
inline constexpr double kStructureEveryCollisionsPerDisk = 10.0;

struct GasOutcome {
  science::GasResults results;
  std::uint64_t equilibration_collisions = 0;  // resolved (at least one per disk)
  double equilibration_rate = 0.0;             // ω seen while equilibrating
  double wall_seconds = 0.0;                   // of the production run, measurements included
};

[[nodiscard]] GasOutcome run_gas_session(const GasSpec& spec);

}  // namespace carom::cli
