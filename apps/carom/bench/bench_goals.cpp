#include "bench/bench_goals.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/bench_report.hpp"
#include "options/readable_number.hpp"

namespace carom::cli {

namespace {

// The goals' sizes and limits (docs/performance.md, "The goals' status").
constexpr std::uint64_t kSmall = 10'000;
constexpr std::uint64_t kMedium = 100'000;
constexpr std::uint64_t kLarge = 1'000'000;
constexpr double kDensities[] = {0.3, 0.6};
constexpr double kSmallRate = 2.5;   // M collisions/s, at least
constexpr double kMediumRate = 1.5;  // M collisions/s, at least
constexpr double kLargeCostRatio = 2.0;
constexpr double kMostBytesPerBall = 128.0;

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

}  // namespace carom::cli
