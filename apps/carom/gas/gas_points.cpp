#include "gas/gas_points.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "options/option_value.hpp"
#include "options/usage_error.hpp"

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
  std::vector<std::atomic<double>> done(specs.size());
  std::atomic<std::size_t> next{0};
  std::mutex ending;
  std::condition_variable ended;
  std::size_t workers_ended = 0;
  const auto worker = [&] {
    for (std::size_t i = next++; i < specs.size() && !stop_once(); i = next++) {
      try {
        result.outcomes[i] = run_gas_session(
            specs[i], [&done, i](double fraction) { done[i].store(fraction); }, stop_once);
        result.completed[i] = result.outcomes[i].interrupted ? 0 : 1;
        if (point_done && result.completed[i] != 0) point_done(i, result.outcomes[i]);
      } catch (...) {
        result.failures[i] = std::current_exception();
      }
      done[i].store(1.0);
    }
    const std::lock_guard<std::mutex> lock(ending);
    ++workers_ended;
    ended.notify_one();
  };
  const std::size_t workers = std::min(std::max<std::size_t>(threads, 1), specs.size());
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < workers; ++t) pool.emplace_back(worker);
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(ending);
      if (ended.wait_for(lock, std::chrono::milliseconds(100),
                         [&] { return workers_ended == workers; })) {
        break;
      }
    }
    if (watch) {
      double sum = 0.0;
      for (const std::atomic<double>& fraction : done) sum += fraction.load();
      watch(sum / static_cast<double>(specs.size()));
    }
  }
  for (std::thread& thread : pool) thread.join();
  result.stopped = stopped.load();
  return result;
}

}  // namespace carom::cli
