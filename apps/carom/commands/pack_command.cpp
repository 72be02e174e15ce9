#include "commands/pack_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>

#include "carom/science/contact_network.hpp"
#include "carom/science/packing.hpp"
#include "gas/gas_points.hpp"
#include "gas/seed_ensemble.hpp"
#include "options/exit_codes.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "pack/pack_ensemble.hpp"
#include "pack/pack_session.hpp"
#include "pack/packed_scene.hpp"
#include "system/mpi_job.hpp"
#include "system/output_file.hpp"
#include "system/progress_bar.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

// `carom pack --seeds K` (pack/pack_ensemble.hpp): --out names a folder of packings.
int run_ensemble(const PackOptions& o, std::uint64_t seeds) {
  (void)parse_pack_options(o);  // every option checked before anything is written
  const std::uint64_t threads = parse_eos_threads(o.threads);
  if (!o.picture.empty()) {
    throw UsageError("--picture", o.picture,
                     "draws one packing; with --seeds, --out writes each seed's scene, which "
                     "carom render draws");
  }
  if (o.out == kStandardOutput) {
    throw UsageError("--out", o.out, "with --seeds, --out names a folder for the packings");
  }
  if (!o.out.empty()) {
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(o.out) / "runs", error);
    if (error) {
      std::cerr << "carom pack: error: --out \"" << o.out
                << "\": cannot create it: " << error.message() << '\n';
      return kExitUsage;
    }
  }
  const StopOnSignals stop_on_signals;
  const MpiJob& job = MpiJob::get();
  PackEnsembleOutcome ensemble;
  {
    ProgressBar bar(!o.quiet && job.is_root());
    std::function<void(double)> watch;
    if (job.is_root()) watch = [&bar](double fraction) { bar.update(fraction, ""); };
    ensemble = run_pack_ensemble(o, seeds, threads, o.out, &StopOnSignals::requested, watch, job);
  }
  // Under MPI, rank 0 alone reports; the other ranks are done.
  if (!ensemble.leads) {
    return StopOnSignals::requested() ? StopOnSignals::exit_code() : kExitSuccess;
  }
  if (ensemble.read > 0) {
    std::cerr << "carom pack: " << ensemble.read << " of " << seeds << " packings read from "
              << (std::filesystem::path(o.out) / "runs").string()
              << ", where an earlier run kept them\n";
  }
  for (const std::string& failure : ensemble.not_kept) {
    std::cerr << "carom pack: warning: a packing was not kept: " << failure << '\n';
  }
  bool failed = false;
  for (const PackRun& run : ensemble.runs) {
    if (run.failure.empty()) continue;
    failed = true;
    std::cerr << "carom pack: error: the packing of seed " << run.seed << " failed: " << run.failure
              << '\n';
  }
  if (o.json) {
    std::cout << pack_ensemble_json(ensemble.runs).dump() << '\n';
  } else {
    std::cout << pack_ensemble_text(ensemble.runs);
  }
  if (StopOnSignals::requested()) {
    std::cerr << "carom pack: " << StopOnSignals::what()
              << "; the report holds the packings completed"
              << (o.out.empty() ? "" : ", kept in --out; the same command makes the rest") << '\n';
    return StopOnSignals::exit_code();
  }
  return failed ? kExitFailure : kExitSuccess;
}

int run(const PackOptions& o) {
  const std::uint64_t seeds = parse_seed_count(o.seeds);
  (void)parse_eos_threads(o.threads);  // checked even where one packing leaves it unused
  if (seeds > 1) return run_ensemble(o, seeds);
  const PackRequest r = parse_pack_options(o);
  for (const auto& [option, name] : {std::pair{"--out", &o.out}, {"--picture", &o.picture}}) {
    if (name->empty()) continue;
    if (const auto problem = check_output(*name)) throw UsageError(option, *name, *problem);
  }
  if (!o.out.empty() && !o.picture.empty() && same_output(o.out, o.picture)) {
    throw UsageError("--picture", o.picture, "is the same file as --out");
  }
  const StopOnSignals stop_on_signals;
  PackOutcome outcome;
  {
    ProgressBar bar(!o.quiet);
    outcome = run_pack_session(
        o, r, [](World& world) { stop_world_on_signals(world); },
        [&](const science::CompressionProgress& p) {
          bar.update(std::clamp(progress_fraction(r, p), 0.0, 1.0),
                     "eta " + rounded(p.eta) + ", Z " + rounded(p.pressure));
          return StopOnSignals::requested();
        });
  }
  const science::CompressionResult& result = outcome.result;
  const science::ContactNetwork& network = outcome.network;
  const double psi6 = outcome.psi6;
  const World& world = outcome.world;

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
    std::cout << pack_json(o, r, outcome).dump() << '\n';
  } else {
    std::cout << pack_text(r, outcome);
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
      "--seeds K makes K packings alike from seeds S, S+1, ... on --threads threads (and\n"
      "across the ranks of `mpirun -n R carom pack ...`), each reported with the means of\n"
      "the packing fraction, Z, the rattlers' fraction, psi6 and the pressure and the\n"
      "standard error between the seeds. With --out DIR each packing is written as it ends\n"
      "(DIR/seed-S.json) with its report (DIR/runs/seed-S.json); started again with the\n"
      "same options, the seeds kept there are read, not compressed again (docs/ensembles.md).\n\n"
      "Examples:\n"
      "  carom pack --n 1000 --mix 1.4:0.5 --until-jammed --json\n"
      "  carom pack --n 1000 --mix 1.4:0.5 --until-jammed --seeds 16 --threads 2 --out jams\n"
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
  pack->add_option("--seeds", o->seeds,
                   "Make K packings, from seeds S, S+1, ...: each one's figures, and their means "
                   "with the error between the seeds")
      ->type_name("K")
      ->capture_default_str();
  pack->add_option("--threads", o->threads, "With --seeds: packings made at once, 1 to 256")
      ->type_name("T")
      ->capture_default_str();
  pack->add_option("-o,--out", o->out,
                   "Write the packing as a scene (JSON), for carom run; with --seeds, a folder: "
                   "seed-S.json a packing, runs/ the reports a new start reads")
      ->type_name("FILE");
  pack->add_option("--picture", o->picture,
                   "Write a picture (.png or .svg), disks coloured by their contacts")
      ->type_name("FILE");
  pack->add_flag("--json", o->json, "Print one JSON object, numbers exact, not text");
  pack->add_flag("-q,--quiet", o->quiet, "No progress bar");
  return {pack, [o] { return run(*o); }};
}

}  // namespace carom::cli
