// carom tool: one measured run of a hard-disk gas, as `carom gas` and each point of `carom eos`
// make it: build the gas, equilibrate, measure (carom/science/gas_monitor.hpp), time it.
#pragma once

#include <cstdint>
#include <functional>

#include "carom/science/gas_monitor.hpp"
#include "gas/gas_options.hpp"

namespace carom::cli {

struct GasOutcome {
  science::GasResults results;
  std::uint64_t equilibration_collisions = 0;  // resolved (at least one per disk)
  double equilibration_rate = 0.0;             // ω seen while equilibrating
  double wall_seconds = 0.0;                   // of the production run, measurements included
  std::uint64_t compression_collisions = 0;    // of a compressed start (--start compress)
  double compression_seconds = 0.0;
  // Stopped by a signal: during equilibration (nothing measured), or during the measurement
  // (results.interrupted: estimates over the blocks completed, maybe none).
  bool interrupted = false;
  bool interrupted_equilibrating = false;
  // Whether there are estimates to report: a block at least was completed.
  [[nodiscard]] bool measured() const { return !interrupted || results.blocks_done > 0; }
};

// Told now and then (every few thousand events) how far a session has got, from 0 to 1.
using GasProgress = std::function<void(double fraction)>;
// Asked as often whether to stop; the tool's answer is whether a signal came (StopOnSignals).
using GasStopAsked = std::function<bool()>;

// Runs the session; it stops within a few thousand events of `stop` answering true (or, without
// one, of a signal caught by StopOnSignals).
[[nodiscard]] GasOutcome run_gas_session(const GasSpec& spec, const GasProgress& progress = {},
                                         const GasStopAsked& stop = {});

}  // namespace carom::cli
