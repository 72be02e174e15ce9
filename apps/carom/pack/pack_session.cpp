#include "pack/pack_session.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "carom/error.hpp"
#include "carom/science/hard_disk_gas.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "system/wall_clock.hpp"

namespace carom::cli {
namespace {

// A typo with extra zeros should be refused at once, not after allocating gigabytes.
constexpr std::uint64_t kMostPackedDisks = 10'000'000;
// Cells longer than this many times their width hold few disks across: a typo more likely.
constexpr double kMostAspect = 1000.0;
// An isostatic packing of frictionless disks: 2d contacts a disk on the mean.
constexpr double kIsostaticContacts = 4.0;
// Without a target the cell is sized so that the reference diameter is 1 near jamming.
constexpr double kJammingGuess = 0.84;

double positive_number(const std::string& option, const std::string& text,
                       const std::string& expected) {
  const OptionValue value{option, text, expected};
  const double number = parse_finite_number(text, value);
  if (!(number > 0.0)) reject(value, "must be > 0");
  return number;
}

}  // namespace

PackRequest parse_pack_options(const PackOptions& o) {
  PackRequest r;
  science::PackingSpec& spec = r.spec;
  spec.n = parse_whole_number({"--n", o.n, "a whole number >= 2"});
  if (spec.n < 2) throw UsageError("--n", o.n, "at least 2 disks are needed for a packing");
  if (spec.n > kMostPackedDisks) {
    throw UsageError("--n", o.n, "at most " + std::to_string(kMostPackedDisks) + " disks");
  }
  if (!o.mix.empty()) {
    const OptionValue mix{"--mix", o.mix, "D:F, a diameter D > 0 and a fraction F in (0, 1)"};
    const std::size_t colon = o.mix.find(':');
    if (colon == std::string::npos) reject(mix, "the colon between D and F is missing");
    spec.second_diameter = parse_finite_number(std::string_view(o.mix).substr(0, colon), mix);
    spec.second_fraction = parse_finite_number(std::string_view(o.mix).substr(colon + 1), mix);
    if (!(spec.second_diameter > 0.0)) reject(mix, "the diameter must be > 0");
    if (!(spec.second_fraction > 0.0 && spec.second_fraction < 1.0)) {
      reject(mix, "the fraction must lie in (0, 1)");
    }
  }
  if (o.boundary == "periodic") {
    spec.boundary = Boundary::periodic;
  } else if (o.boundary == "box") {
    spec.boundary = Boundary::box;
  } else {
    throw UsageError("--boundary", o.boundary, "must be periodic or box");
  }
  spec.aspect = positive_number("--aspect", o.aspect, "the cell's height over its width, > 0");
  if (spec.aspect > kMostAspect || spec.aspect < 1.0 / kMostAspect) {
    throw UsageError("--aspect", o.aspect, "must lie between 1/1000 and 1000");
  }
  r.settings.rate = positive_number(
      "--rate", o.rate, "a number > 0: the diameter's growth speed over the thermal speed");
  spec.start_eta = positive_number("--start-eta", o.start_eta, "a packing fraction in (0, 0.5]");
  if (spec.start_eta > 0.5) {
    throw UsageError("--start-eta", o.start_eta,
                     "random placement cannot reach it: at most 0.5 (it saturates near 0.547)");
  }
  if (o.until_jammed == !o.eta.empty()) {
    throw UsageError("--eta", o.eta,
                     "give either --eta (a target packing fraction) or --until-jammed, not both "
                     "and not neither");
  }
  if (!o.eta.empty()) {
    const OptionValue eta{"--eta", o.eta, "a packing fraction in (start, 0.9069)"};
    const double target = parse_finite_number(o.eta, eta);
    if (!(target < science::kTriangularPackingLimit)) {
      reject(eta,
             "no packing of disks reaches the triangular one's packing fraction, "
             "pi/(2*sqrt(3)) = 0.9069");
    }
    if (!(target > spec.start_eta)) {
      reject(eta, "must be above the start's packing fraction (--start-eta " + o.start_eta + ")");
    }
    r.settings.target_eta = target;
    spec.sized_for_eta = target;
  } else {
    spec.sized_for_eta = std::max(kJammingGuess, spec.start_eta);
  }
  r.settings.pressure_limit =
      positive_number("--pressure-limit", o.pressure_limit, "a reduced pressure > 1");
  if (!(r.settings.pressure_limit > 1.0)) {
    throw UsageError("--pressure-limit", o.pressure_limit, "must be > 1");
  }
  if (!o.tolerance.empty()) {
    const OptionValue tolerance{"--contact-tolerance", o.tolerance, "a number in [0, 1)"};
    r.tolerance = parse_finite_number(o.tolerance, tolerance);
    if (!(*r.tolerance >= 0.0 && *r.tolerance < 1.0)) reject(tolerance, "must lie in [0, 1)");
  }
  spec.seed = parse_whole_number({"--seed", o.seed, "a whole number >= 0"});
  if (!o.picture.empty()) {
    const std::string extension = std::filesystem::path(o.picture).extension().string();
    if (extension == ".svg") {
      r.picture_svg = true;
    } else if (extension != ".png") {
      throw UsageError("--picture", o.picture, "must end in .png or .svg");
    }
  }
  return r;
}

// The library's refusal of a start (too few disks for a periodic cell, too dense to place) as
// the option it comes from.
namespace {

[[noreturn]] void rethrow_as_usage(const InvalidArgument& error, const PackOptions& o) {
  if (error.argument() == "start_eta") {
    throw UsageError("--start-eta", o.start_eta, error.requirement());
  }
  throw UsageError("--n", o.n, error.requirement());
}

}  // namespace

std::string description_of(const PackOptions& o, const science::CompressionResult& result) {
  std::ostringstream text;
  text << "carom pack --n " << o.n;
  if (!o.mix.empty()) text << " --mix " << o.mix;
  text << " --boundary " << o.boundary << " --aspect " << o.aspect << " --rate " << o.rate;
  if (o.until_jammed) {
    text << " --until-jammed --pressure-limit " << o.pressure_limit;
  } else {
    text << " --eta " << o.eta;
  }
  text << " --start-eta " << o.start_eta << " --seed " << o.seed << ": packing fraction "
       << readable(result.eta) << ", " << (result.jammed ? "jammed" : "not jammed");
  return text.str();
}

nlohmann::json pack_json(const PackOptions& o, const PackRequest& r, const PackOutcome& outcome) {
  const science::CompressionResult& result = outcome.result;
  const science::ContactNetwork& network = outcome.network;
  const double tolerance = outcome.tolerance;
  const double psi6 = outcome.psi6;
  const double wall_seconds = outcome.wall_seconds;
  nlohmann::json out;
  out["n"] = r.spec.n;
  out["boundary"] = o.boundary;
  out["aspect"] = r.spec.aspect;
  out["mix"] = o.mix.empty() ? nlohmann::json(nullptr)
                             : nlohmann::json{{"diameter", r.spec.second_diameter},
                                              {"fraction", r.spec.second_fraction}};
  out["rate"] = r.settings.rate;
  out["start_eta"] = r.spec.start_eta;
  out["target_eta"] =
      r.settings.target_eta > 0.0 ? nlohmann::json(r.settings.target_eta) : nlohmann::json(nullptr);
  out["seed"] = r.spec.seed;
  out["eta"] = result.eta;
  out["end"] = std::string(science::compression_end_name(result.end));
  out["jammed"] = result.jammed;
  out["pressure"] = result.pressure;
  out["pressure_limit"] = r.settings.pressure_limit;
  out["contact_tolerance"] = tolerance;
  out["Z"] = network.mean_contacts_of_rest;
  out["Z_isostatic"] = kIsostaticContacts;
  out["contacts_mean"] = network.mean_contacts;
  out["contacts"] = network.pairs.size();
  out["wall_contacts"] = network.wall_contacts;
  out["rattlers"] = network.rattlers;
  out["psi6"] = psi6;
  out["collisions"] = result.collisions;
  out["thermostat_windows"] = result.windows;
  out["thermostat_work"] = result.thermostat_work;
  out["time"] = result.time;
  out["wall_seconds"] = wall_seconds;
  out["collisions_per_second"] =
      wall_seconds > 0.0 ? nlohmann::json(static_cast<double>(result.collisions) / wall_seconds)
                         : nlohmann::json(nullptr);
  return out;
}

std::string pack_text(const PackRequest& r, const PackOutcome& outcome) {
  const science::CompressionResult& result = outcome.result;
  const science::ContactNetwork& network = outcome.network;
  const double psi6 = outcome.psi6;
  const double wall_seconds = outcome.wall_seconds;
  std::ostringstream out;
  out << "packing fraction  " << readable(result.eta) << " ("
      << science::compression_end_name(result.end) << ", "
      << (result.jammed ? "jammed" : "not jammed") << ")\n";
  out << "reduced pressure  " << rounded(result.pressure) << "\n";
  out << "contacts          Z = " << rounded(network.mean_contacts_of_rest)
      << " a disk without the " << network.rattlers << " rattlers (isostatic: 4); "
      << network.pairs.size() << " between disks";
  if (r.spec.boundary == Boundary::box) out << ", " << network.wall_contacts << " with walls";
  out << "\n";
  out << "order             psi6 = " << rounded(psi6) << "\n";
  out << "collisions        " << result.collisions << " in " << rounded(wall_seconds) << " s";
  if (wall_seconds > 0.0) {
    out << " (" << readable_count(static_cast<double>(result.collisions) / wall_seconds)
        << " a second)";
  }
  out << "\n";
  return out.str();
}

// Progress from 0 to 1: towards the target's packing fraction, or towards the pressure limit on a
// logarithmic scale (the pressure grows by decades as a packing jams).
double progress_fraction(const PackRequest& r, const science::CompressionProgress& p) {
  if (r.settings.target_eta > 0.0) {
    return (p.eta - r.spec.start_eta) / (r.settings.target_eta - r.spec.start_eta);
  }
  if (p.pressure <= 1.0) return 0.0;
  return std::log(p.pressure) / std::log(r.settings.pressure_limit);
}

PackOutcome run_pack_session(
    const PackOptions& o, const PackRequest& r,
    const std::function<void(World&)>& before_compressing,
    const std::function<bool(const science::CompressionProgress&)>& progress) {
  PackOutcome outcome;
  try {
    outcome.world = science::make_packing_world(r.spec);
  } catch (const InvalidArgument& error) {
    rethrow_as_usage(error, o);
  }
  if (before_compressing) before_compressing(outcome.world);
  const auto start = std::chrono::steady_clock::now();
  outcome.result = science::compress(outcome.world, r.settings, progress);
  outcome.wall_seconds = seconds_since(start);
  outcome.tolerance =
      r.tolerance.value_or(science::contact_tolerance_at_pressure(outcome.result.pressure));
  outcome.network = science::find_contact_network(outcome.world, outcome.tolerance);
  outcome.psi6 = science::global_psi6(outcome.world);
  return outcome;
}

}  // namespace carom::cli
