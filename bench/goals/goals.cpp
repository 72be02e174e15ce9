#include "goals.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

namespace carom::goals {

namespace {

// The goals' sizes and limits (docs/performance.md, "The hard-disk gas by size"; their
// status: docs/decisions/0034-speed-goals-blocked.md).
constexpr std::uint64_t kSmall = 10'000;
constexpr std::uint64_t kMedium = 100'000;
constexpr std::uint64_t kLarge = 1'000'000;
constexpr double kDensities[] = {0.3, 0.6};
constexpr double kSmallRate = 2.5;   // M collisions/s, at least
constexpr double kMediumRate = 1.5;  // M collisions/s, at least
constexpr double kLargeCostRatio = 2.0;
constexpr double kMostBytesPerBall = 128.0;

// A figure for people: six significant digits tell the story, --json gives every digit.
std::string readable(double value) {
  return fmt::format("{:.6g}", value + 0.0);  // + 0.0 turns -0 into 0
}

// The middle value (the mean of the middle two for an even count); NaN for none.
double median_of(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
}

// The size "10^k" where n is a power of ten, else n itself.
std::string size_text(std::uint64_t n) {
  int exponent = 0;
  std::uint64_t rest = n;
  while (rest >= 10 && rest % 10 == 0) {
    rest /= 10;
    ++exponent;
  }
  return rest == 1 && exponent > 0 ? fmt::format("10^{}", exponent) : std::to_string(n);
}

// Every timed run's ns a collision of the gases of size n at eta, pooled in the order they ran.
std::vector<double> runs_of(const std::vector<GasFigures>& gases, std::uint64_t n, double eta) {
  std::vector<double> pooled;
  for (const GasFigures& gas : gases) {
    if (gas.n == n && gas.eta == eta) {
      pooled.insert(pooled.end(), gas.nanoseconds.begin(), gas.nanoseconds.end());
    }
  }
  if (pooled.empty()) {
    throw std::invalid_argument(
        fmt::format("the goals need a run of {} disks at eta {}", size_text(n), readable(eta)));
  }
  return pooled;
}

GoalVerdict rate_goal(const std::vector<GasFigures>& gases, std::uint64_t n, double eta,
                      double least_rate) {
  const std::vector<double> runs = runs_of(gases, n, eta);
  const double median = median_of(runs);
  GoalVerdict verdict;
  verdict.goal = fmt::format(">= {} M collisions/s at {}, eta {}", readable(least_rate),
                             size_text(n), readable(eta));
  verdict.value = 1e3 / median;  // M/s from ns a collision
  verdict.limit = least_rate;
  verdict.met = verdict.value >= least_rate;
  verdict.measured = fmt::format("{} M/s (median {} ns of {} runs)", readable(verdict.value),
                                 readable(median), runs.size());
  return verdict;
}

GoalVerdict ratio_goal(const std::vector<GasFigures>& gases, double eta) {
  const double large = median_of(runs_of(gases, kLarge, eta));
  const double small = median_of(runs_of(gases, kSmall, eta));
  GoalVerdict verdict;
  verdict.goal = fmt::format("{}'s cost <= {} x {}'s, eta {}", size_text(kLarge),
                             readable(kLargeCostRatio), size_text(kSmall), readable(eta));
  verdict.value = large / small;
  verdict.limit = kLargeCostRatio;
  verdict.met = verdict.value <= kLargeCostRatio;
  verdict.measured = fmt::format("{} x (medians {} / {} ns)", readable(verdict.value),
                                 readable(large), readable(small));
  return verdict;
}

GoalVerdict memory_goal(const std::vector<GasFigures>& gases) {
  double most = -1.0;
  for (const double eta : kDensities) {
    runs_of(gases, kLarge, eta);  // (throws where the gas is missing)
    for (const GasFigures& gas : gases) {
      if (gas.n == kLarge && gas.eta == eta) most = std::max(most, gas.bytes_per_ball);
    }
  }
  GoalVerdict verdict;
  verdict.goal =
      fmt::format("<= {} bytes a ball ({})", readable(kMostBytesPerBall), size_text(kLarge));
  verdict.value = most;
  verdict.limit = kMostBytesPerBall;
  verdict.met = most <= kMostBytesPerBall;
  verdict.measured = fmt::format("{} (the larger of both packing fractions')", readable(most));
  return verdict;
}

const nlohmann::json& field(const nlohmann::json& bench, const char* name) {
  if (!bench.is_object() || !bench.contains(name)) {
    throw std::invalid_argument(fmt::format("a bench result lacks \"{}\"", name));
  }
  return bench.at(name);
}

// A text field of a bench object, or "unknown".
std::string text_of(const nlohmann::json& object, const char* name) {
  if (!object.is_object() || !object.contains(name) || !object.at(name).is_string()) {
    return "unknown";
  }
  return object.at(name).get<std::string>();
}

// A whole-number field of a bench object, or 0 where it has none.
std::uint64_t count_of(const nlohmann::json& object, const char* name) {
  if (!object.is_object() || !object.contains(name) || !object.at(name).is_number_integer() ||
      object.at(name).get<std::int64_t>() < 0) {
    return 0;
  }
  return object.at(name).get<std::uint64_t>();
}

// A cache's size as people write it: in MiB or KiB where it divides evenly; 0 is unknown.
std::string cache_size_text(std::uint64_t bytes) {
  constexpr std::pair<std::uint64_t, const char*> kUnits[] = {{1024 * 1024, "MiB"}, {1024, "KiB"}};
  if (bytes == 0) return "unknown";
  for (const auto& [unit, name] : kUnits) {
    if (bytes % unit == 0) return fmt::format("{} {}", bytes / unit, name);
  }
  return fmt::format("{} B", bytes);
}

}  // namespace

std::vector<GoalGas> goal_plan() {
  // The collisions a disk and timed runs of docs/performance.md's goal tables: about a second of
  // timed work for each gas.
  std::vector<GoalGas> plan;
  for (const double eta : kDensities) {
    plan.push_back({kSmall, eta, 20, 5});
    plan.push_back({kMedium, eta, 10, 5});
    plan.push_back({kLarge, eta, 2, 3});
    plan.push_back({kSmall, eta, 20, 5});
  }
  return plan;
}

std::vector<std::string> bench_arguments(const GoalGas& gas, const std::string& seed,
                                         const std::string& equilibrate) {
  // Shortest round-trip text: the tool reads back exactly the plan's values.
  return {"bench",
          "--n",
          std::to_string(gas.n),
          "--eta",
          fmt::format("{}", gas.eta),
          "--collisions-per-ball",
          fmt::format("{}", gas.collisions_per_ball),
          "--repeat",
          std::to_string(gas.repeats),
          "--seed",
          seed,
          "--equilibrate",
          equilibrate,
          "--json"};
}

GasFigures gas_figures(const nlohmann::json& bench) {
  GasFigures figures;
  try {
    figures.n = field(bench, "n").get<std::uint64_t>();
    figures.eta = field(bench, "eta").get<double>();
    figures.nanoseconds =
        field(bench, "repetition_nanoseconds_per_collision").get<std::vector<double>>();
    figures.bytes_per_ball = field(bench, "bytes_per_ball").get<double>();
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(std::string("a bench result's field has the wrong type: ") +
                                error.what());
  }
  return figures;
}

std::vector<GoalVerdict> judge_goals(const std::vector<GasFigures>& gases) {
  std::vector<GoalVerdict> verdicts;
  for (const double eta : kDensities) verdicts.push_back(rate_goal(gases, kSmall, eta, kSmallRate));
  for (const double eta : kDensities) {
    verdicts.push_back(rate_goal(gases, kMedium, eta, kMediumRate));
  }
  for (const double eta : kDensities) verdicts.push_back(ratio_goal(gases, eta));
  verdicts.push_back(memory_goal(gases));
  return verdicts;
}

std::string goals_text(const std::vector<nlohmann::ordered_json>& benches,
                       const std::vector<GoalVerdict>& verdicts, const std::string& footer) {
  std::string out =
      "The world's goals on this host: each gas as `carom bench` runs it, in this "
      "order\n";
  // (Bytes a ball below 10^6 carry the process's fixed allocations, hence the goal's size.)
  out += fmt::format("  {:<16} {:>9} {:>9} {:>12}  {}\n", "gas", "median ns", "M/s", "bytes a ball",
                     "timed runs, ns a collision");
  for (const auto& bench : benches) {
    const GasFigures gas = gas_figures(bench);
    std::string each;
    for (const double ns : gas.nanoseconds) each += (each.empty() ? "" : ", ") + readable(ns);
    const double median = median_of(gas.nanoseconds);
    out +=
        fmt::format("  {:<16} {:>9} {:>9} {:>12}  {}\n",
                    fmt::format("{}, eta {}", size_text(gas.n), readable(gas.eta)),
                    readable(median), readable(1e3 / median), readable(gas.bytes_per_ball), each);
  }
  out += fmt::format("\n  {:<40} {:<4} {}\n", "goal", "met", "measured");
  std::size_t met = 0;
  for (const GoalVerdict& verdict : verdicts) {
    out += fmt::format("  {:<40} {:<4} {}\n", verdict.goal, verdict.met ? "yes" : "NO",
                       verdict.measured);
    met += verdict.met ? 1 : 0;
  }
  out += fmt::format("  {} of {} goals met\n", met, verdicts.size());
  return out + footer;
}

nlohmann::ordered_json goals_json(const std::vector<nlohmann::ordered_json>& benches,
                                  const std::vector<GoalVerdict>& verdicts) {
  nlohmann::ordered_json out;
  out["gases"] = benches;
  out["goals"] = nlohmann::ordered_json::array();
  bool all_met = true;
  for (const GoalVerdict& verdict : verdicts) {
    out["goals"].push_back({{"goal", verdict.goal},
                            {"value", verdict.value},
                            {"limit", verdict.limit},
                            {"met", verdict.met},
                            {"measured", verdict.measured}});
    all_met = all_met && verdict.met;
  }
  out["all_met"] = all_met;
  return out;
}

std::string tool_text(const std::string& tool, const nlohmann::json& bench) {
  const std::string build_type = text_of(bench, "build_type");
  std::string out = fmt::format("  build: {}, {} (the tool {})\n",
                                build_type.empty() ? "(no build type)" : build_type,
                                text_of(bench, "compiler"), tool);
  const nlohmann::json none;
  const nlohmann::json& machine =
      bench.is_object() && bench.contains("machine") ? bench.at("machine") : none;
  out += fmt::format("  machine: {}, {} logical CPUs; caches L1d {}, L2 {}, L3 {}\n",
                     text_of(machine, "cpu"), count_of(machine, "logical_cpus"),
                     cache_size_text(count_of(machine, "l1d_cache_bytes")),
                     cache_size_text(count_of(machine, "l2_cache_bytes")),
                     cache_size_text(count_of(machine, "l3_cache_bytes")));
  return out;
}

}  // namespace carom::goals
