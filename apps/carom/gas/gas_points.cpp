#include "gas/gas_points.hpp"

#include <atomic>

#include "options/option_value.hpp"
#include "options/usage_error.hpp"
#include "system/parallel_runs.hpp"

namespace carom::cli {
namespace {

// More threads than this is a typo, not a machine.
constexpr std::uint64_t kMostThreads = 256;

}  // namespace

std::uint64_t parse_eos_threads(const std::string& text) {
  const std::uint64_t threads = parse_whole_number({"--threads", text, "a whole number >= 1"});
  if (threads < 1 || threads > kMostThreads) {
    throw UsageError("--threads", text, "between 1 and 256 threads");
  }
  return threads;
}

GasPointsOutcome run_gas_points(const std::vector<GasSpec>& specs, std::size_t threads,
                                const GasStopAsked& stop, const GasPointsWatch& watch,
                                const GasPointDone& point_done) {
  GasPointsOutcome result;
  result.outcomes.resize(specs.size());
  result.failures.resize(specs.size());
  result.completed.assign(specs.size(), 0);
  // Once asked and answered true, the answer holds for every world and for the points not begun.
  std::atomic<bool> stopped{false};
  const GasStopAsked stop_once = [&stopped, &stop] {
    if (!stopped.load() && stop()) stopped.store(true);
    return stopped.load();
  };
  run_in_parallel(
      specs.size(), threads, stop_once,
      [&](std::size_t i, std::atomic<double>& progress) {
        try {
          result.outcomes[i] = run_gas_session(
              specs[i], [&progress](double fraction) { progress.store(fraction); }, stop_once);
          result.completed[i] = result.outcomes[i].interrupted ? 0 : 1;
          if (point_done && result.completed[i] != 0) point_done(i, result.outcomes[i]);
        } catch (...) {
          result.failures[i] = std::current_exception();
        }
      },
      watch);
  result.stopped = stopped.load();
  return result;
}

}  // namespace carom::cli
