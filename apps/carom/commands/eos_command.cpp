#include "commands/eos_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "carom/science/exact.hpp"
#include "commands/gas_command.hpp"
#include "drawing/science_plot.hpp"
#include "gas/eos_sweep.hpp"
#include "gas/gas_options.hpp"
#include "gas/gas_points.hpp"
#include "gas/gas_report.hpp"
#include "gas/gas_session.hpp"
#include "gas/seed_ensemble.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "system/mpi_job.hpp"
#include "system/output_file.hpp"
#include "system/progress_bar.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

// More points than this is a typo in the step (0.0001 for 0.01), not a sweep.
constexpr std::size_t kMostPoints = 1000;
// A sweep's points are rounded to the decimals its numbers are written with, at most this many
// (a double holds 15 to 17 significant digits; packing fractions are below 1).
constexpr std::size_t kMostDecimals = 15;

struct EosOptions {
  GasOptionText gas;
  std::string etas = "0.1:0.7:0.05";
  std::string threads = "2";
  std::string seeds = "1";
  std::string out;
  bool json = false;
};

// FROM:TO:STEP, the points FROM, FROM + STEP, ... up to TO (a rounding beyond TO included).
std::vector<double> parse_etas(const std::string& text) {
  const OptionValue value{"--eta", text, "FROM:TO:STEP, or one packing fraction"};
  std::vector<std::string_view> parts;
  std::string_view rest(text);
  for (std::size_t colon = rest.find(':'); colon != std::string_view::npos;
       colon = rest.find(':')) {
    parts.push_back(rest.substr(0, colon));
    rest.remove_prefix(colon + 1);
  }
  parts.push_back(rest);
  if (parts.size() == 1) return {parse_finite_number(parts[0], value)};
  if (parts.size() != 3) reject(value, "give one number or three separated by colons");
  const double from = parse_finite_number(parts[0], value);
  const double to = parse_finite_number(parts[1], value);
  const double step = parse_finite_number(parts[2], value);
  if (!(step > 0.0)) reject(value, "the step must be > 0");
  if (!(to >= from)) reject(value, "TO must not be below FROM");
  const double count = std::floor((to - from) / step + 1e-9) + 1.0;
  if (count > static_cast<double>(kMostPoints)) {
    reject(value,
           "that is " + readable(count) + " points, more than " + std::to_string(kMostPoints));
  }
  // Each point is the decimal the user means (0.1:0.7:0.1 gives 0.7, not 0.7000000000000001):
  // from the index, not by adding steps, then rounded to the most decimals the three are
  // written with.
  std::size_t decimals = 0;
  for (const std::string_view part : parts) {
    const std::size_t point = part.find('.');
    if (part.find_first_of("eE") != std::string::npos) decimals = kMostDecimals;
    if (point != std::string::npos) decimals = std::max(decimals, part.size() - point - 1);
  }
  const double scale = std::pow(10.0, static_cast<double>(std::min(decimals, kMostDecimals)));
  std::vector<double> etas;
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    etas.push_back(std::round((from + static_cast<double>(i) * step) * scale) / scale);
  }
  return etas;
}

std::string table(const std::vector<GasSpec>& specs, const std::vector<GasOutcome>& outcomes) {
  std::ostringstream out;
  out << "| η | Z | ± | Henderson | (Z − Z_H)/Z_H | collisions | g(σ) | ψ6 | D |\n";
  out << "|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const science::GasResults& r = outcomes[i].results;
    const double henderson = science::henderson_z(specs[i].eta);
    const ValueAndError z = with_error_parts(r.z.mean, r.z.error);
    out << "| " << readable(specs[i].eta) << " | " << z.value << " | " << z.error << " | "
        << rounded(henderson) << " | " << rounded((r.z.mean - henderson) / henderson) << " | "
        << r.collisions << " | " << rounded(r.g_contact.mean) << " | " << rounded(r.psi6.mean)
        << " | " << rounded(r.diffusion.mean) << " |\n";
  }
  return out.str();
}

std::string eos_csv(const std::vector<GasSpec>& specs, const std::vector<GasOutcome>& outcomes) {
  std::ostringstream out;
  out.precision(17);
  out << "eta,Z,Z_err,Z_henderson,collisions,time,collision_rate,collision_rate_err,g_contact,"
         "g_contact_err,psi6,psi6_err,diffusion,diffusion_err\n";
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const science::GasResults& r = outcomes[i].results;
    out << specs[i].eta << ',' << r.z.mean << ',' << r.z.error << ','
        << science::henderson_z(specs[i].eta) << ',' << r.collisions << ',' << r.time << ','
        << r.collision_rate.mean << ',' << r.collision_rate.error << ',' << r.g_contact.mean << ','
        << r.g_contact.error << ',' << r.psi6.mean << ',' << r.psi6.error << ',' << r.diffusion.mean
        << ',' << r.diffusion.error << '\n';
  }
  return out.str();
}

// Henderson's Z(η) from low to high, drawn as a line of 101 points.
PlotSeries henderson_curve(double low, double high) {
  PlotSeries henderson{"Henderson (1 + η²/8)/(1 − η)²", "#d62728", {}, {}, {}, false, false};
  constexpr int kCurvePoints = 100;
  for (int k = 0; k <= kCurvePoints; ++k) {
    const double eta = low + (high - low) * k / kCurvePoints;
    henderson.x.push_back(eta);
    henderson.y.push_back(science::henderson_z(eta));
  }
  return henderson;
}

std::string eos_plot(const std::vector<GasSpec>& specs, const std::vector<GasOutcome>& outcomes) {
  PlotSpec plot{"Equation of state of hard disks, Z = PA/(NkT)",
                "N = " + std::to_string(specs.front().n) + ", seed " +
                    std::to_string(specs.front().seed) +
                    "; error bars: block-average standard errors",
                "packing fraction η",
                "Z",
                {}};
  PlotSeries measured{"carom gas", "#1f77b4", {}, {}, {}, true, false};
  for (std::size_t i = 0; i < specs.size(); ++i) {
    measured.x.push_back(specs[i].eta);
    measured.y.push_back(outcomes[i].results.z.mean);
    measured.error.push_back(outcomes[i].results.z.error);
  }
  plot.series.push_back(henderson_curve(specs.front().eta, specs.back().eta));
  plot.series.push_back(measured);
  return render_plot(plot);
}

// ---- with several seeds a point ----

// A point's runs: runs[k] of the point's K seeds.
struct EosPoint {
  std::span<const GasSpec> specs;
  std::span<const GasOutcome> runs;
  SeededPoint combined;  // combine_seeds(runs): once, for the table, the CSV and the plot
};

std::string seeded_table(const std::vector<EosPoint>& points) {
  std::ostringstream out;
  out << "| η | Z | ± blocks | ± seeds | Henderson | (Z − Z_H)/Z_H | collisions | g(σ) | ψ6 | D "
         "|\n";
  out << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const EosPoint& point : points) {
    const SeededPoint& p = point.combined;
    const double eta = point.specs.front().eta;
    const double henderson = science::henderson_z(eta);
    const double error = std::max(p.z.block_error, p.z.seed_error);
    const ValueAndError z = with_error_parts(p.z.mean, error);
    out << "| " << readable(eta) << " | " << z.value << " | " << rounded(p.z.block_error) << " | "
        << rounded(p.z.seed_error) << " | " << rounded(henderson) << " | "
        << rounded((p.z.mean - henderson) / henderson) << " | " << p.collisions << " | "
        << rounded(p.g_contact.mean) << " | " << rounded(p.psi6.mean) << " | "
        << rounded(p.diffusion.mean) << " |\n";
  }
  return out.str();
}

std::string seeded_csv(const std::vector<EosPoint>& points) {
  std::ostringstream out;
  out.precision(17);
  out << "eta,seeds,Z,Z_err,Z_seed_err,Z_henderson,collisions,time,collision_rate,"
         "collision_rate_err,collision_rate_seed_err,g_contact,g_contact_err,g_contact_seed_err,"
         "psi6,psi6_err,psi6_seed_err,diffusion,diffusion_err,diffusion_seed_err\n";
  for (const EosPoint& point : points) {
    const SeededPoint& p = point.combined;
    const double eta = point.specs.front().eta;
    out << eta << ',' << point.runs.size() << ',' << p.z.mean << ',' << p.z.block_error << ','
        << p.z.seed_error << ',' << science::henderson_z(eta) << ',' << p.collisions << ','
        << p.time;
    for (const SeedEstimate* e : {&p.collision_rate, &p.g_contact, &p.psi6, &p.diffusion}) {
      out << ',' << e->mean << ',' << e->block_error << ',' << e->seed_error;
    }
    out << '\n';
  }
  return out.str();
}

std::string seeded_plot(const std::vector<EosPoint>& points) {
  const GasSpec& first = points.front().specs.front();
  PlotSpec plot{"Equation of state of hard disks, Z = PA/(NkT)",
                "N = " + std::to_string(first.n) + ", " +
                    std::to_string(points.front().runs.size()) + " seeds a point from seed " +
                    std::to_string(first.seed) + "; error bars: standard errors between seeds",
                "packing fraction η",
                "Z",
                {}};
  PlotSeries measured{"carom gas", "#1f77b4", {}, {}, {}, true, false};
  for (const EosPoint& point : points) {
    const SeededPoint& p = point.combined;
    measured.x.push_back(point.specs.front().eta);
    measured.y.push_back(p.z.mean);
    measured.error.push_back(p.z.seed_error);
  }
  plot.series.push_back(
      henderson_curve(points.front().specs.front().eta, points.back().specs.front().eta));
  plot.series.push_back(measured);
  return render_plot(plot);
}

int run(const EosOptions& options) {
  refuse_standard_output_as_folder("--out", options.out);
  const std::vector<double> etas = parse_etas(options.etas);
  std::vector<GasSpec> specs;
  specs.reserve(etas.size());
  for (const double eta : etas) specs.push_back(parse_gas_spec(options.gas, eta, options.etas));
  const std::uint64_t threads = parse_eos_threads(options.threads);
  const std::uint64_t seeds = parse_seed_count(options.seeds);
  // One gas run for each point and seed, point by point (with one seed, the points themselves).
  std::vector<GasSpec> runs = seeded_specs(specs, seeds);
  // With --out, each run is kept in DIR/points as it ends, and one kept there before is read.
  std::string points_folder;
  if (!options.out.empty()) {
    points_folder = (std::filesystem::path(options.out) / "points").string();
    std::error_code error;
    std::filesystem::create_directories(points_folder, error);
    if (error) {
      std::cerr << "carom eos: error: --out \"" << options.out
                << "\": cannot create it: " << error.message() << '\n';
      return kExitUsage;
    }
  }
  // A signal stops every point's world; the points completed are written.
  const StopOnSignals stop_on_signals;
  EosSweepOutcome sweep;
  {
    const MpiJob& job = MpiJob::get();
    ProgressBar bar(job.is_root());
    GasPointsWatch watch;
    if (job.is_root()) watch = [&bar](double fraction) { bar.update(fraction, ""); };
    sweep = run_sweep(runs, threads, points_folder, &StopOnSignals::requested, watch, job);
  }
  // Under MPI, rank 0 alone reports and writes; the other ranks are done.
  if (!sweep.leads) return StopOnSignals::requested() ? StopOnSignals::exit_code() : kExitSuccess;
  if (sweep.read > 0) {
    std::cerr << "carom eos: " << sweep.read << " of " << runs.size() << " runs read from "
              << points_folder << ", where an earlier sweep kept them\n";
  }
  for (const std::string& failure : sweep.not_kept) {
    std::cerr << "carom eos: warning: a finished run was not kept: " << failure << '\n';
  }
  std::vector<GasOutcome>& outcomes = sweep.runs.outcomes;
  // A run that failed is reported with its error; its point is left out and the others kept.
  bool failed = false;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!sweep.runs.failures[i]) continue;
    failed = true;
    try {
      std::rethrow_exception(sweep.runs.failures[i]);
    } catch (const std::exception& error) {
      std::cerr << "carom eos: error: the run at eta = " << readable(runs[i].eta) << ", seed "
                << runs[i].seed << " failed: " << error.what() << '\n';
    }
  }
  // After a signal or a failure, the points whose every seed completed; otherwise all of them.
  const std::size_t all_points = specs.size();
  if (StopOnSignals::requested() || failed) {
    std::vector<GasSpec> kept_runs;
    std::vector<GasOutcome> kept_outcomes;
    std::size_t kept_points = 0;
    for (std::size_t first = 0; first < runs.size(); first += seeds) {
      bool complete = true;
      for (std::size_t k = first; k < first + seeds; ++k) {
        complete = complete && sweep.runs.completed[k] != 0;
      }
      if (!complete) continue;
      ++kept_points;
      kept_runs.insert(kept_runs.end(), runs.begin() + static_cast<std::ptrdiff_t>(first),
                       runs.begin() + static_cast<std::ptrdiff_t>(first + seeds));
      kept_outcomes.insert(kept_outcomes.end(),
                           outcomes.begin() + static_cast<std::ptrdiff_t>(first),
                           outcomes.begin() + static_cast<std::ptrdiff_t>(first + seeds));
    }
    runs = std::move(kept_runs);
    outcomes = std::move(kept_outcomes);
    std::cerr << "carom eos: "
              << (StopOnSignals::requested() ? StopOnSignals::what() + " with " : std::string())
              << kept_points << " of " << all_points << " points complete"
              << (runs.empty() ? ": nothing to write\n" : "; the outputs hold those\n");
    if (runs.empty()) return StopOnSignals::requested() ? StopOnSignals::exit_code() : kExitFailure;
  }
  std::vector<EosPoint> points;
  for (std::size_t first = 0; first < runs.size(); first += seeds) {
    const auto point_runs = std::span<const GasOutcome>(outcomes).subspan(first, seeds);
    points.push_back({std::span<const GasSpec>(runs).subspan(first, seeds), point_runs,
                      combine_seeds(point_runs)});
  }
  const bool seeded = seeds > 1;

  if (!options.out.empty()) {
    const std::vector<std::pair<std::string, std::string>> files{
        {"eos.csv", seeded ? seeded_csv(points) : eos_csv(runs, outcomes)},
        {"eos.md", seeded ? seeded_table(points) : table(runs, outcomes)},
        {"eos.svg", seeded ? seeded_plot(points) : eos_plot(runs, outcomes)}};
    for (const auto& [name, content] : files) {
      const std::string path = (std::filesystem::path(options.out) / name).string();
      if (const auto failure = write_output(path, content)) {
        std::cerr << "carom eos: error: " << *failure << '\n';
        return kExitUsage;
      }
    }
  }
  if (options.json) {
    nlohmann::json listed = nlohmann::json::array();
    for (const EosPoint& point : points) {
      listed.push_back(seeded ? seeded_point_json(point.specs, point.runs)
                              : gas_json(point.specs.front(), point.runs.front()));
    }
    std::cout << nlohmann::json{{"points", listed}}.dump() << '\n';
  } else {
    std::cout << (seeded ? seeded_table(points) : table(runs, outcomes));
  }
  if (StopOnSignals::requested()) return StopOnSignals::exit_code();
  return failed ? kExitFailure : kExitSuccess;
}

}  // namespace

Command add_eos_command(CLI::App& app) {
  CLI::App* eos =
      app.add_subcommand("eos", "The equation of state Z(eta) of hard disks, beside Henderson's");
  eos->footer(
      "One `carom gas` run per packing fraction (see 'carom gas --help' for the gas and the\n"
      "measurements), spread over --threads threads, each with its own World. Prints a\n"
      "table (or --json: {\"points\": [one carom gas object per point]}); --out DIR writes\n"
      "eos.csv, eos.md and eos.svg (Z with error bars and Henderson's\n"
      "Z = (1 + eta^2/8)/(1 - eta)^2). With --seeds K each point is K runs: the mean, its\n"
      "block-average error and the standard error between the seeds (\"Z_seed_err\"; each\n"
      "run's own report under \"runs\" in --json), which agree when the blocks are long\n"
      "enough.\n\n"
      "Examples:\n"
      "  carom eos --eta 0.1:0.7:0.05 --n 400 --collisions 1000 --out eos\n"
      "  carom eos --eta 0.05:0.3:0.05 --threads 2 --json\n"
      "  carom eos --eta 0.3:0.6:0.1 --seeds 8 --out eos-seeds");
  auto options = std::make_shared<EosOptions>();
  eos->add_option("--eta", options->etas, "Packing fractions FROM:TO:STEP (or one)")
      ->type_name("FROM:TO:STEP")
      ->capture_default_str();
  add_gas_options(*eos, options->gas);
  eos->add_option("--threads", options->threads, "Points run at once, one World each")
      ->type_name("T")
      ->capture_default_str();
  eos->add_option("--seeds", options->seeds,
                  "Independent runs a point, seeds SEED, SEED + 1, ...: the mean and the error "
                  "between them beside the block-average error")
      ->type_name("K")
      ->capture_default_str();
  eos->add_option("-o,--out", options->out, "Directory for eos.csv, eos.md, eos.svg")
      ->type_name("DIR");
  eos->add_flag("--json", options->json, "Print one JSON object, numbers exact, not a table");
  return {eos, [options] { return run(*options); }};
}

}  // namespace carom::cli
