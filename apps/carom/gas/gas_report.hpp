// carom tool: what `carom gas` prints (text or JSON) and writes with --out (CSV and SVG).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "gas/gas_options.hpp"
#include "gas/gas_session.hpp"

namespace carom::cli {

// A JSON number, or null for a NaN or an infinity (a value a run could not give).
[[nodiscard]] nlohmann::json json_number(double value);

// One JSON object: the measurements' keys (n, eta, collisions, time, kT, Z, Z_err,
// collision_rate, mean_free_path, v4_over_v2sq, g_contact, psi6, diffusion, energy_drift,
// wall_seconds, collisions_per_second), an _err beside each measured value, and the exact
// values the measurements are compared with. A NaN (a value a run could not give) is null.
[[nodiscard]] nlohmann::json gas_json(const GasSpec& spec, const GasOutcome& outcome);
[[nodiscard]] std::string gas_text(const GasSpec& spec, const GasOutcome& outcome);

// Writes the histograms (rdf.csv, speed.csv, psi6_local.csv, msd.csv, disks.csv) and the plots
// (rdf.svg, speed.svg, psi6_map.svg, msd.svg) into directory, creating it. Returns what went
// wrong, naming the file, or nothing.
[[nodiscard]] std::optional<std::string> write_gas_files(const std::string& directory,
                                                         const GasSpec& spec,
                                                         const GasOutcome& outcome);

}  // namespace carom::cli
