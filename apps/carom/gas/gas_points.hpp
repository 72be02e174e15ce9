// carom tool: the points of an equation of state run side by side, as `carom eos` and the Python
// module's eos run them: one World a thread, each thread taking the next point not yet taken.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "gas/gas_session.hpp"

namespace carom::cli {

struct GasPointsOutcome {
  std::vector<GasOutcome> outcomes;          // in the specs' order
  std::vector<std::exception_ptr> failures;  // a point's error (null where it ran)
  std::vector<char> completed;               // 1 where a point ran to its end, uninterrupted
  bool stopped = false;                      // whether `stop` answered true
};

// Told on the calling thread, about ten times a second while the points run, how far they have
// got together (0 to 1); the place to draw a progress bar or to look for a signal.
using GasPointsWatch = std::function<void(double fraction)>;

// Told on the worker thread, as soon as it ends, of every run that ended uninterrupted: its index
// in the specs and its outcome (the place to keep it in a checkpoint file). It must not throw.
using GasPointDone = std::function<void(std::size_t index, const GasOutcome& outcome)>;

// The number of points run at once, from --threads: 1 to 256; throws UsageError otherwise.
[[nodiscard]] std::uint64_t parse_eos_threads(const std::string& text);

// Runs every spec on at most `threads` threads. `stop` is asked by every point's world; once it
// answers true no new point starts and the running ones stop within a few thousand events.
[[nodiscard]] GasPointsOutcome run_gas_points(const std::vector<GasSpec>& specs,
                                              std::size_t threads, const GasStopAsked& stop,
                                              const GasPointsWatch& watch,
                                              const GasPointDone& point_done = {});

}  // namespace carom::cli
