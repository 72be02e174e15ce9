#include "gas/gas_report.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <system_error>

#include "carom/science/exact.hpp"
#include "drawing/science_plot.hpp"
#include "drawing/svg_writer.hpp"
#include "options/readable_number.hpp"
#include "system/output_file.hpp"

namespace carom::cli {

nlohmann::json json_number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

namespace {

using science::BlockEstimate;
using science::GasResults;

bool one_size(const GasSpec& spec) {
  for (const double d : spec.diameters) {
    if (d != spec.diameters.front()) return false;
  }
  return true;
}

void put(nlohmann::json& out, const std::string& key, const BlockEstimate& estimate) {
  out[key] = json_number(estimate.mean);
  out[key + "_err"] = json_number(estimate.error);
}

std::string csv(const science::Curve& curve, const std::string& header) {
  std::ostringstream out;
  out.precision(17);
  out << header << '\n';
  for (std::size_t i = 0; i < curve.x.size(); ++i) out << curve.x[i] << ',' << curve.y[i] << '\n';
  return out.str();
}

std::string with_error(const BlockEstimate& estimate) {
  return carom::cli::with_error(estimate.mean, estimate.error);
}

// A colour for an angle of ψ₆ (−π, π]: the hue goes once round the colour circle over 60° of
// lattice orientation, so grains of one orientation share a colour.
std::string hue_of(double angle, double modulus) {
  const double degrees = (angle + std::numbers::pi) / (2.0 * std::numbers::pi) * 360.0;
  // Disordered disks (small |ψ₆|) fade to grey.
  const double saturation = std::clamp(modulus, 0.0, 1.0) * 90.0;
  return "hsl(" + std::to_string(static_cast<int>(degrees)) + "," +
         std::to_string(static_cast<int>(saturation)) + "%,55%)";
}

std::string psi6_map(const GasSpec& spec, const GasResults& results) {
  SvgFigure figure;
  figure.heading("Local bond order ψ6 (hue: orientation, grey: disorder)");
  figure.heading("N = " + std::to_string(spec.n) + ", η = " + readable(spec.eta) +
                 ", last sample; global |ψ6| = " + readable(results.psi6.mean) +
                 " averaged over the run");
  const Pen frame{"black", 1.0, false};
  const double side = spec.layout.side;
  figure.line({0.0, 0.0}, {side, 0.0}, frame);
  figure.line({side, 0.0}, {side, side}, frame);
  figure.line({side, side}, {0.0, side}, frame);
  figure.line({0.0, side}, {0.0, 0.0}, frame);
  const Pen none{"none", 0.0, false};
  for (std::size_t i = 0; i < results.final_positions.size(); ++i) {
    figure.circle(results.final_positions[i], results.final_radii[i], none,
                  hue_of(results.final_psi6_angle[i], results.final_psi6_modulus[i]));
  }
  return figure.render();
}

std::string subtitle(const GasSpec& spec, const GasResults& results) {
  return "N = " + std::to_string(spec.n) + ", η = " + readable(spec.eta) + ", " +
         std::to_string(results.collisions) + " collisions, seed " + std::to_string(spec.seed);
}

}  // namespace

nlohmann::json gas_json(const GasSpec& spec, const GasOutcome& outcome) {
  const GasResults& r = outcome.results;
  nlohmann::json out;
  out["n"] = spec.n;
  out["eta"] = spec.eta;
  out["seed"] = spec.seed;
  out["mix"] = !one_size(spec);
  out["box_side"] = spec.layout.side;
  out["start"] = spec.compress_start ? "compress" : "lattice";
  if (spec.compress_start) {
    out["compression_collisions"] = outcome.compression_collisions;
    out["compression_seconds"] = outcome.compression_seconds;
  }
  out["equilibration_collisions"] = outcome.equilibration_collisions;
  out["collisions"] = r.collisions;
  out["blocks"] = spec.blocks;
  out["blocks_done"] = outcome.interrupted ? r.blocks_done : spec.blocks;
  out["stopped"] = outcome.interrupted ? nlohmann::json("interrupted") : nlohmann::json(nullptr);
  out["time"] = r.time;
  out["kT"] = r.kT;
  put(out, "Z", r.z);
  put(out, "collision_rate", r.collision_rate);
  put(out, "mean_free_path", r.mean_free_path);
  put(out, "v4_over_v2sq", r.moment_ratio);
  put(out, "g_contact", r.g_contact);
  put(out, "psi6", r.psi6);
  put(out, "diffusion", r.diffusion);
  out["energy_drift"] = r.energy_drift;
  out["momentum_drift"] = r.momentum_drift;
  out["unwrap_error"] = r.max_unwrap_error;
  out["structure_samples"] = r.structure_samples;
  out["wall_seconds"] = outcome.wall_seconds;
  out["collisions_per_second"] = static_cast<double>(r.collisions) / outcome.wall_seconds;
  // What the measurements are compared with (docs/science.md).
  out["v4_over_v2sq_exact"] = science::moment_ratio_exact(spec.n);
  if (one_size(spec)) {
    out["Z_henderson"] = science::henderson_z(spec.eta);
    out["Z_virial3"] = science::virial_z(spec.eta);
    out["g_contact_from_Z"] = (r.z.mean - 1.0) / (2.0 * spec.eta);
    put(out, "rate_pressure_ratio", r.rate_pressure_ratio);
    out["rate_pressure_ratio_exact"] = science::rate_pressure_ratio_exact(spec.n);
  }
  return out;
}

std::string gas_text(const GasSpec& spec, const GasOutcome& outcome) {
  const GasResults& r = outcome.results;
  std::ostringstream out;
  out << "hard-disk gas: N = " << spec.n << ", eta = " << readable(spec.eta)
      << (one_size(spec) ? "" : " (two sizes)") << ", box " << readable(spec.layout.side)
      << ", seed " << spec.seed << "\n";
  if (spec.compress_start) {
    out << "  compressed from a random start: " << outcome.compression_collisions
        << " collisions in " << rounded(outcome.compression_seconds) << " s\n";
  }
  if (outcome.interrupted) {
    out << "  stopped by a signal after " << r.blocks_done << " of " << spec.blocks
        << " blocks: the estimates cover those\n";
  }
  out << "  production: " << r.collisions << " collisions in time " << rounded(r.time) << ", "
      << (outcome.interrupted ? r.blocks_done : spec.blocks)
      << " blocks; kT = K/N = " << readable(r.kT) << "\n";
  out << "  Z = PA/(NkT)          " << with_error(r.z);
  if (one_size(spec)) out << "   (Henderson " << readable(science::henderson_z(spec.eta)) << ")";
  out << "\n  collision rate        " << with_error(r.collision_rate) << " per disk\n";
  out << "  mean free path        " << with_error(r.mean_free_path) << "\n";
  out << "  <v^4>/<v^2>^2         " << with_error(r.moment_ratio) << "   (exact for N disks "
      << readable(science::moment_ratio_exact(spec.n)) << ")\n";
  out << "  g(contact)            " << with_error(r.g_contact);
  if (one_size(spec))
    out << "   ((Z-1)/(2 eta) = " << readable((r.z.mean - 1.0) / (2.0 * spec.eta)) << ")";
  out << "\n  psi6 (global)         " << with_error(r.psi6) << "\n";
  out << "  diffusion D           " << with_error(r.diffusion) << "\n";
  if (one_size(spec)) {
    out << "  rate/pressure ratio   " << with_error(r.rate_pressure_ratio) << "   (exact "
        << readable(science::rate_pressure_ratio_exact(spec.n)) << ")\n";
  }
  out << "  energy drift " << rounded(r.energy_drift) << "; " << rounded(outcome.wall_seconds)
      << " s, " << readable_count(static_cast<double>(r.collisions) / outcome.wall_seconds)
      << " collisions/s (measurements included)\n";
  return out.str();
}

std::optional<std::string> write_gas_files(const std::string& directory, const GasSpec& spec,
                                           const GasOutcome& outcome) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) return "cannot create directory " + directory + ": " + error.message();
  const GasResults& r = outcome.results;

  PlotSpec rdf{"Radial distribution function g(r)", subtitle(spec, r), "r / σ", "g(r)", {}};
  rdf.series.push_back({"g(r), measured", "#1f77b4", r.rdf.x, r.rdf.y, {}, false, false});
  rdf.series.push_back(
      {"1",
       "#999999",
       {r.rdf.x.empty() ? 1.0 : r.rdf.x.front(), r.rdf.x.empty() ? 5.0 : r.rdf.x.back()},
       {1.0, 1.0},
       {},
       false,
       true});

  PlotSpec speed{"Speed distribution, time-weighted", subtitle(spec, r), "speed", "density", {}};
  speed.series.push_back({"measured", "#1f77b4", r.speed.x, r.speed.y, {}, true, false});
  std::vector<double> maxwell;
  for (const double v : r.speed.x)
    maxwell.push_back(science::maxwell_speed_density(v, r.kT, r.mass));
  speed.series.push_back(
      {"Maxwell–Boltzmann, kT = K/N", "#d62728", r.speed.x, maxwell, {}, false, false});

  PlotSpec msd{"Mean-square displacement (unwrapped), from each block's start",
               subtitle(spec, r),
               "lag τ",
               "<|Δr|²>",
               {}};
  msd.series.push_back({"measured", "#1f77b4", r.msd.x, r.msd.y, {}, true, false});
  std::vector<double> fitted;
  for (const double tau : r.msd.x) fitted.push_back(4.0 * r.diffusion.mean * tau);
  msd.series.push_back(
      {"4·D·τ, D = " + readable(r.diffusion.mean), "#d62728", r.msd.x, fitted, {}, false, true});

  std::ostringstream disks;
  disks.precision(17);
  disks << "x,y,radius,psi6_modulus,psi6_angle\n";
  for (std::size_t i = 0; i < r.final_positions.size(); ++i) {
    disks << r.final_positions[i].x << ',' << r.final_positions[i].y << ',' << r.final_radii[i]
          << ',' << r.final_psi6_modulus[i] << ',' << r.final_psi6_angle[i] << '\n';
  }
  const std::vector<std::pair<std::string, std::string>> files{
      {"rdf.csv", csv(r.rdf, "r,g")},
      {"speed.csv", csv(r.speed, "speed,density")},
      {"psi6_local.csv", csv(r.psi6_local, "psi6_modulus,density")},
      {"msd.csv", csv(r.msd, "lag,msd")},
      {"disks.csv", disks.str()},
      {"rdf.svg", render_plot(rdf)},
      {"speed.svg", render_plot(speed)},
      {"msd.svg", render_plot(msd)},
      {"psi6_map.svg", psi6_map(spec, r)},
  };
  for (const auto& [name, content] : files) {
    const std::string path = (std::filesystem::path(directory) / name).string();
    if (auto failure = write_output(path, content)) return failure;
  }
  return std::nullopt;
}

}  // namespace carom::cli
