#include "gas/gas_record.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "gas/gas_report.hpp"
#include "system/output_file.hpp"

namespace carom::cli {
namespace gas_record_fields {

// Calls visit(name, field) for every number the reports read, in one order for writing and
// reading alike, so that the two cannot drift apart.
template <typename Outcome, typename Visit>
void each_field(Outcome& outcome, Visit&& visit) {
  visit("equilibration_collisions", outcome.equilibration_collisions);
  visit("equilibration_rate", outcome.equilibration_rate);
  visit("wall_seconds", outcome.wall_seconds);
  visit("compression_collisions", outcome.compression_collisions);
  visit("compression_seconds", outcome.compression_seconds);
  visit("interrupted", outcome.interrupted);
  visit("interrupted_equilibrating", outcome.interrupted_equilibrating);
  auto& r = outcome.results;
  visit("n", r.n);
  visit("packing_fraction", r.packing_fraction);
  visit("sigma", r.sigma);
  visit("mass", r.mass);
  visit("collisions", r.collisions);
  visit("time", r.time);
  visit("results_interrupted", r.interrupted);
  visit("blocks_done", r.blocks_done);
  visit("kT", r.kT);
  visit("structure_samples", r.structure_samples);
  const auto estimate = [&visit](const std::string& name, auto& e) {
    visit(name + ".mean", e.mean);
    visit(name + ".error", e.error);
    visit(name + ".blocks", e.blocks);
  };
  estimate("z", r.z);
  estimate("collision_rate", r.collision_rate);
  estimate("mean_free_path", r.mean_free_path);
  estimate("moment_ratio", r.moment_ratio);
  estimate("g_contact", r.g_contact);
  estimate("psi6", r.psi6);
  estimate("diffusion", r.diffusion);
  estimate("rate_pressure_ratio", r.rate_pressure_ratio);
  visit("energy_drift", r.energy_drift);
  visit("momentum_drift", r.momentum_drift);
  visit("max_unwrap_error", r.max_unwrap_error);
}

// FNV-1a of text, for a file name that tells runs apart.
std::uint32_t fnv1a(const std::string& text) {
  std::uint32_t hash = 2166136261U;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 16777619U;
  }
  return hash;
}

}  // namespace gas_record_fields

nlohmann::json gas_record(const GasOutcome& outcome) {
  nlohmann::json record = nlohmann::json::object();
  gas_record_fields::each_field(outcome, [&record](const std::string& name, const auto& field) {
    using Field = std::remove_cvref_t<decltype(field)>;
    if constexpr (std::is_same_v<Field, double>) {
      record[name] = json_number(field);
    } else {
      record[name] = field;
    }
  });
  return record;
}

GasOutcome gas_outcome_from_record(const nlohmann::json& record) {
  GasOutcome outcome;
  gas_record_fields::each_field(outcome, [&record](const std::string& name, auto& field) {
    using Field = std::remove_cvref_t<decltype(field)>;
    const auto found = record.find(name);
    if (found == record.end()) throw std::runtime_error("a gas record lacks \"" + name + "\"");
    if constexpr (std::is_same_v<Field, double>) {
      if (found->is_null()) {
        field = std::numeric_limits<double>::quiet_NaN();
        return;
      }
      if (!found->is_number()) {
        throw std::runtime_error("a gas record's \"" + name + "\" is not a number");
      }
    } else if constexpr (std::is_same_v<Field, bool>) {
      if (!found->is_boolean()) {
        throw std::runtime_error("a gas record's \"" + name + "\" is not true or false");
      }
    } else if (!found->is_number_unsigned()) {
      throw std::runtime_error("a gas record's \"" + name + "\" is not a whole number >= 0");
    }
    field = found->get<Field>();
  });
  return outcome;
}

nlohmann::json gas_spec_key(const GasSpec& spec) {
  return {{"n", spec.n},
          {"eta", spec.eta},
          {"second_diameter", spec.second_diameter},
          {"second_fraction", spec.second_fraction},
          {"box_side", spec.layout.side},
          {"equilibration_collisions", spec.equilibration_collisions},
          {"collisions_per_disk", spec.collisions_per_disk},
          {"seed", spec.seed},
          {"blocks", spec.blocks},
          {"compress_start", spec.compress_start}};
}

std::string point_file_name(const GasSpec& spec) {
  std::ostringstream name;
  name.precision(17);
  name << "eta-" << spec.eta << "-seed-" << spec.seed << '-' << std::hex
       << gas_record_fields::fnv1a(gas_spec_key(spec).dump()) << ".json";
  return name.str();
}

std::optional<std::string> write_point_file(const std::string& path, const GasSpec& spec,
                                            const GasOutcome& outcome) {
  const nlohmann::json file{
      {"carom_eos_point", 1}, {"spec", gas_spec_key(spec)}, {"outcome", gas_record(outcome)}};
  return write_output(path, file.dump() + "\n");
}

std::optional<GasOutcome> read_point_file(const std::string& path, const GasSpec& spec) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json file = nlohmann::json::parse(in);
    if (file.value("carom_eos_point", 0) != 1 || file.at("spec") != gas_spec_key(spec)) {
      return std::nullopt;
    }
    return gas_outcome_from_record(file.at("outcome"));
  } catch (const std::exception&) {
    return std::nullopt;  // cut short or not ours: the run is made again
  }
}

}  // namespace carom::cli
