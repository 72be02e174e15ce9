#include "gas/seed_ensemble.hpp"

#include <cmath>
#include <limits>

#include "carom/science/exact.hpp"
#include "gas/gas_report.hpp"
#include "options/option_value.hpp"
#include "options/usage_error.hpp"

namespace carom::cli {
namespace seed_json {

void put(nlohmann::json& out, const std::string& key, const SeedEstimate& estimate) {
  out[key] = json_number(estimate.mean);
  out[key + "_err"] = json_number(estimate.block_error);
  out[key + "_seed_err"] = json_number(estimate.seed_error);
}

}  // namespace seed_json

std::uint64_t parse_seed_count(const std::string& text) {
  const OptionValue value{"--seeds", text, "a whole number from 1 to 1000"};
  const std::uint64_t seeds = parse_whole_number(value);
  if (seeds < 1 || seeds > kMostSeeds) reject(value, "it must be from 1 to 1000");
  return seeds;
}

std::vector<GasSpec> seeded_specs(const std::vector<GasSpec>& points, std::uint64_t seeds) {
  std::vector<GasSpec> specs;
  specs.reserve(points.size() * seeds);
  for (const GasSpec& point : points) {
    if (point.seed > std::numeric_limits<std::uint64_t>::max() - (seeds - 1)) {
      reject({"--seed", std::to_string(point.seed), "a whole number >= 0"},
             "with --seeds " + std::to_string(seeds) + " the last seed would pass 2^64 - 1");
    }
    for (std::uint64_t k = 0; k < seeds; ++k) {
      specs.push_back(point);
      specs.back().seed = point.seed + k;
    }
  }
  return specs;
}

SeedEstimate across_seeds(std::span<const science::BlockEstimate> runs) {
  SeedEstimate out;
  const auto k = static_cast<double>(runs.size());
  if (runs.empty()) return {std::nan(""), std::nan(""), std::nan("")};
  double squared_errors = 0.0;
  for (const science::BlockEstimate& run : runs) {
    out.mean += run.mean;
    squared_errors += run.error * run.error;
  }
  out.mean /= k;
  out.block_error = std::sqrt(squared_errors) / k;
  if (runs.size() < 2) return out;
  double spread = 0.0;
  for (const science::BlockEstimate& run : runs)
    spread += (run.mean - out.mean) * (run.mean - out.mean);
  out.seed_error = std::sqrt(spread / (k - 1.0) / k);
  return out;
}

SeededPoint combine_seeds(std::span<const GasOutcome> runs) {
  const auto each = [&runs](science::BlockEstimate science::GasResults::*field) {
    std::vector<science::BlockEstimate> values;
    values.reserve(runs.size());
    for (const GasOutcome& run : runs) values.push_back(run.results.*field);
    return across_seeds(values);
  };
  SeededPoint point{.z = each(&science::GasResults::z),
                    .collision_rate = each(&science::GasResults::collision_rate),
                    .g_contact = each(&science::GasResults::g_contact),
                    .psi6 = each(&science::GasResults::psi6),
                    .diffusion = each(&science::GasResults::diffusion)};
  for (const GasOutcome& run : runs) {
    point.collisions += run.results.collisions;
    point.time += run.results.time;
  }
  return point;
}

nlohmann::json seeded_point_json(std::span<const GasSpec> specs, std::span<const GasOutcome> runs) {
  const SeededPoint point = combine_seeds(runs);
  nlohmann::json out{{"eta", specs.front().eta},
                     {"n", specs.front().n},
                     {"seeds", specs.size()},
                     {"first_seed", specs.front().seed}};
  seed_json::put(out, "Z", point.z);
  out["Z_henderson"] = science::henderson_z(specs.front().eta);
  seed_json::put(out, "collision_rate", point.collision_rate);
  seed_json::put(out, "g_contact", point.g_contact);
  seed_json::put(out, "psi6", point.psi6);
  seed_json::put(out, "diffusion", point.diffusion);
  out["collisions"] = point.collisions;
  out["time"] = point.time;
  nlohmann::json each = nlohmann::json::array();
  for (std::size_t k = 0; k < runs.size(); ++k) each.push_back(gas_json(specs[k], runs[k]));
  out["runs"] = each;
  return out;
}

}  // namespace carom::cli
