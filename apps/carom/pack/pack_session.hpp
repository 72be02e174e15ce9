// carom tool: `carom pack`'s options, checked, and one compression run from them to its report
// (shared by the command and the Python module, so both give the same JSON).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "carom/science/contact_network.hpp"
#include "carom/science/packing.hpp"
#include "carom/world.hpp"

namespace carom::cli {

// The options as typed.
struct PackOptions {
  std::string n = "1000";
  std::string mix;
  std::string boundary = "periodic";
  std::string aspect = "1";
  std::string rate = "0.002";
  std::string eta;
  bool until_jammed = false;
  std::string start_eta = "0.3";
  std::string pressure_limit = "1e12";
  std::string tolerance;  // empty: from the pressure reached
  std::string seed = "1";
  std::string seeds = "1";    // packings from consecutive seeds (pack/pack_ensemble.hpp)
  std::string threads = "2";  // of them at once in each process
  std::string out;
  std::string picture;
  bool json = false;
  bool quiet = false;
};

// The options checked.
struct PackRequest {
  science::PackingSpec spec;
  science::CompressionSettings settings;
  std::optional<double> tolerance;  // unset: from the pressure reached
  bool picture_svg = false;
};

struct PackOutcome {
  World world;
  science::CompressionResult result;
  science::ContactNetwork network;
  double tolerance = 0.0;  // the contact network's
  double psi6 = 0.0;
  double wall_seconds = 0.0;  // of the compression
};

// Checks every option; throws UsageError naming the first bad one.
[[nodiscard]] PackRequest parse_pack_options(const PackOptions& o);
// The random start (a start the library refuses is a UsageError naming --n or --start-eta), the
// hook on its world (a signal handler's), the compression with its progress callback, and the
// contact network and ψ₆ of the result.
[[nodiscard]] PackOutcome run_pack_session(
    const PackOptions& o, const PackRequest& r,
    const std::function<void(World&)>& before_compressing,
    const std::function<bool(const science::CompressionProgress&)>& progress);
// The packed scene's description: the command that made it and what it reached.
[[nodiscard]] std::string description_of(const PackOptions& o,
                                         const science::CompressionResult& result);
[[nodiscard]] nlohmann::json pack_json(const PackOptions& o, const PackRequest& r,
                                       const PackOutcome& outcome);
[[nodiscard]] std::string pack_text(const PackRequest& r, const PackOutcome& outcome);
// Progress from 0 to 1: towards the target's packing fraction, or towards the pressure limit on
// a logarithmic scale (the pressure grows by decades as a packing jams).
[[nodiscard]] double progress_fraction(const PackRequest& r, const science::CompressionProgress& p);

}  // namespace carom::cli
