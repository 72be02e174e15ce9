#include "commands/pack_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "carom/error.hpp"
#include "carom/science/contact_network.hpp"
#include "carom/science/hard_disk_gas.hpp"
#include "carom/science/packing.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "pack/packed_scene.hpp"
#include "system/output_file.hpp"
#include "system/progress_bar.hpp"
#include "system/stop_signals.hpp"
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
  std::string out;
  std::string picture;
  bool json = false;
  bool quiet = false;
};

struct PackRequest {
  science::PackingSpec spec;
  science::CompressionSettings settings;
  std::optional<double> tolerance;  // unset: from the pressure reached
  bool picture_svg = false;
};

double positive_number(const std::string& option, const std::string& text,
                       const std::string& expected) {
  const OptionValue value{option, text, expected};
  const double number = parse_finite_number(text, value);
  if (!(number > 0.0)) reject(value, "must be > 0");
  return number;
}

PackRequest parse(const PackOptions& o) {
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
[[noreturn]] void rethrow_as_usage(const InvalidArgument& error, const PackOptions& o) {
  if (error.argument() == "start_eta") {
    throw UsageError("--start-eta", o.start_eta, error.requirement());
  }
  throw UsageError("--n", o.n, error.requirement());
}

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

nlohmann::json pack_json(const PackOptions& o, const PackRequest& r,
                         const science::CompressionResult& result,
                         const science::ContactNetwork& network, double tolerance, double psi6,
                         double wall_seconds) {
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

std::string pack_text(const PackRequest& r, const science::CompressionResult& result,
                      const science::ContactNetwork& network, double psi6, double wall_seconds) {
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

int run(const PackOptions& o) {
  const PackRequest r = parse(o);
  for (const auto& [option, name] : {std::pair{"--out", &o.out}, {"--picture", &o.picture}}) {
    if (name->empty()) continue;
    if (const auto problem = check_output(*name)) throw UsageError(option, *name, *problem);
  }
  if (!o.out.empty() && !o.picture.empty() && same_output(o.out, o.picture)) {
    throw UsageError("--picture", o.picture, "is the same file as --out");
  }
  const StopOnSignals stop_on_signals;
  World world;
  try {
    world = science::make_packing_world(r.spec);
  } catch (const InvalidArgument& error) {
    rethrow_as_usage(error, o);
  }
  const auto start = std::chrono::steady_clock::now();
  science::CompressionResult result;
  {
    ProgressBar bar(!o.quiet);
    stop_world_on_signals(world);
    result = science::compress(world, r.settings, [&](const science::CompressionProgress& p) {
      bar.update(std::clamp(progress_fraction(r, p), 0.0, 1.0),
                 "eta " + rounded(p.eta) + ", Z " + rounded(p.pressure));
      return StopOnSignals::requested();
    });
  }
  const double wall_seconds = seconds_since(start);
  const double tolerance =
      r.tolerance.value_or(science::contact_tolerance_at_pressure(result.pressure));
  const science::ContactNetwork network = science::find_contact_network(world, tolerance);
  const double psi6 = science::global_psi6(world);

  const Scene scene = packed_scene(world, description_of(o, result));
  if (!o.out.empty()) {
    if (auto failure = write_output(o.out, to_json_text(scene))) {
      std::cerr << "carom pack: error: --out \"" << o.out << "\": " << *failure << '\n';
      return kExitFailure;
    }
  }
  if (!o.picture.empty()) {
    const std::string title = std::filesystem::path(o.picture).filename().string();
    const std::string subtitle = "packing fraction " + rounded(result.eta) +
                                 ", Z = " + rounded(network.mean_contacts_of_rest) + " without " +
                                 std::to_string(network.rattlers) +
                                 " rattlers (grey), psi6 = " + rounded(psi6);
    if (auto failure = write_output(
            o.picture, packing_picture(scene, network, title, subtitle, r.picture_svg))) {
      std::cerr << "carom pack: error: --picture \"" << o.picture << "\": " << *failure << '\n';
      return kExitFailure;
    }
  }
  if (o.json) {
    std::cout << pack_json(o, r, result, network, tolerance, psi6, wall_seconds).dump() << '\n';
  } else {
    std::cout << pack_text(r, result, network, psi6, wall_seconds);
  }
  if (result.end == science::CompressionEnd::interrupted) {
    std::cerr << "carom pack: " << StopOnSignals::what() << " at packing fraction "
              << readable(result.eta)
              << "; the outputs hold the compression so far (still growing: `carom run` on the "
                 "scene continues it)\n";
    return StopOnSignals::exit_code();
  }
  return kExitSuccess;
}

}  // namespace

Command add_pack_command(CLI::App& app) {
  CLI::App* pack = app.add_subcommand(
      "pack", "Dense and jammed packings of disks: Lubachevsky-Stillinger compression");
  pack->footer(
      "N disks (diameter 1, or a second species of diameter D for a fraction F of them; mass 1)\n"
      "start at random places at packing fraction --start-eta in a periodic cell or a box of\n"
      "height/width A, with Maxwell-Boltzmann velocities (kT = 1). Every radius then grows at\n"
      "one relative rate, the smallest diameter at G times the thermal speed, while a thermostat\n"
      "brings the velocities back to kT = 1 after every N collisions. It stops at the packing\n"
      "fraction --eta, or, with --until-jammed, when the reduced pressure Z = PA/(NkT) measured\n"
      "over N collisions passes --pressure-limit. The cell is sized so that the first species'\n"
      "diameter is 1 at the target (or at 0.84 when jamming).\n\n"
      "Reported: the packing fraction, the pressure, the contact network (pairs closer than the\n"
      "tolerance times the sum of their radii; 1000/Z by default), the rattlers (fewer than 3 "
      "contacts, removed\n"
      "again and again), Z the mean contact number of the rest (isostatic: 4) and psi6.\n"
      "Slow compression (G = 1e-4) lets equal disks crystallise; fast (G = 1e-2) jams them;\n"
      "at G above about 3e-3 the pressure can run away before every contact has formed\n"
      "(Z below 4): docs/science.md, \"Compression and jamming\".\n\n"
      "Examples:\n"
      "  carom pack --n 1000 --mix 1.4:0.5 --until-jammed --json\n"
      "  carom pack --n 396 --aspect 1.0585 --rate 3e-4 --eta 0.88 --out crystal.json "
      "--picture crystal.png");
  auto o = std::make_shared<PackOptions>();
  pack->add_option("--n", o->n, "Number of disks, at least 2")
      ->type_name("N")
      ->capture_default_str();
  pack->add_option("--mix", o->mix,
                   "A second species: diameter D (the first is 1) for a fraction F of the disks")
      ->type_name("D:F");
  pack->add_option("--boundary", o->boundary, "periodic or box")
      ->type_name("KIND")
      ->capture_default_str();
  pack->add_option("--aspect", o->aspect, "The cell's height over its width")
      ->type_name("A")
      ->capture_default_str();
  pack->add_option("--rate", o->rate,
                   "Growth speed of the smallest diameter, in thermal speeds sqrt(kT/m)")
      ->type_name("G")
      ->capture_default_str();
  pack->add_option("--eta", o->eta, "Compress to this packing fraction, below 0.9069")
      ->type_name("ETA");
  pack->add_flag("--until-jammed", o->until_jammed,
                 "Compress until the reduced pressure passes --pressure-limit");
  pack->add_option("--start-eta", o->start_eta, "Packing fraction of the random start, <= 0.5")
      ->type_name("ETA0")
      ->capture_default_str();
  pack->add_option("--pressure-limit", o->pressure_limit,
                   "Reduced pressure Z = PA/(NkT) at which a packing counts as jammed")
      ->type_name("Z")
      ->capture_default_str();
  pack->add_option("--contact-tolerance", o->tolerance,
                   "Disks closer than this times the sum of their radii are in contact "
                   "(default: 1000/Z at the reduced pressure Z reached, at most 0.01)")
      ->type_name("TOL")
      ->capture_default_str();
  pack->add_option("--seed", o->seed, "Seed of the placement and the velocities")
      ->type_name("S")
      ->capture_default_str();
  pack->add_option("-o,--out", o->out, "Write the packing as a scene (JSON), for carom run")
      ->type_name("FILE");
  pack->add_option("--picture", o->picture,
                   "Write a picture (.png or .svg), disks coloured by their contacts")
      ->type_name("FILE");
  pack->add_flag("--json", o->json, "Print one JSON object, numbers exact, not text");
  pack->add_flag("-q,--quiet", o->quiet, "No progress bar");
  return {pack, [o] { return run(*o); }};
}

}  // namespace carom::cli
