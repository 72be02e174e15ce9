// carom tool: a gas run's numbers as one JSON object, exactly: what a sweep's point checkpoint
// holds (`carom eos --out DIR` keeps one per finished run, so that a stopped or killed sweep
// resumes where it stopped) and what an MPI rank sends to rank 0. Every number of GasOutcome
// that the reports read is kept, doubles to the bit (written with 17 digits, a NaN or an
// infinity as null and read back as a NaN); the distributions (g(r), speeds, ψ₆, MSD) and the
// last configuration are not: an equation of state does not write them.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "gas/gas_options.hpp"
#include "gas/gas_session.hpp"

namespace carom::cli {

[[nodiscard]] nlohmann::json gas_record(const GasOutcome& outcome);
// Throws std::runtime_error naming the first field missing or of the wrong type.
[[nodiscard]] GasOutcome gas_outcome_from_record(const nlohmann::json& record);

// What decides a run's results (n, η, the diameters, the run's lengths, blocks, seed and start)
// as one JSON object: a checkpoint is used only for the very same run.
[[nodiscard]] nlohmann::json gas_spec_key(const GasSpec& spec);

// A point checkpoint's file name in a sweep's folder: the run's η and seed, and a hash of its
// key (eta-0.3-seed-7-1f2e3d4c.json).
[[nodiscard]] std::string point_file_name(const GasSpec& spec);

// Writes {"carom_eos_point": 1, "spec": key, "outcome": record} to path atomically (a temporary
// file renamed into place). Returns what went wrong, naming the file, or nothing.
[[nodiscard]] std::optional<std::string> write_point_file(const std::string& path,
                                                          const GasSpec& spec,
                                                          const GasOutcome& outcome);
// The outcome kept at path for this very spec, or nothing (no file, another run's file, or a
// file cut short: each is run again).
[[nodiscard]] std::optional<GasOutcome> read_point_file(const std::string& path,
                                                        const GasSpec& spec);

}  // namespace carom::cli
