#include "commands/gas_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>

#include "gas/gas_options.hpp"
#include "gas/gas_report.hpp"
#include "gas/gas_session.hpp"
#include "options/exit_codes.hpp"
#include "system/output_file.hpp"
#include "system/progress_bar.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

struct GasCommandOptions {
  GasOptionText gas;
  std::string out;
  bool json = false;
};

int run(const GasCommandOptions& options) {
  const GasSpec spec = parse_gas_spec(options.gas);
  refuse_standard_output_as_folder("--out", options.out);
  // A signal stops the run; the outputs are then written for what was measured.
  const StopOnSignals stop_on_signals;
  GasOutcome outcome;
  {
    ProgressBar bar(true);
    outcome = run_gas_session(spec, [&bar](double fraction) { bar.update(fraction, ""); });
  }
  if (!outcome.measured()) {
    std::cerr << "carom gas: " << StopOnSignals::what()
              << (outcome.interrupted_equilibrating ? " while equilibrating"
                                                    : " before the first block ended")
              << ": nothing was measured\n";
    return StopOnSignals::exit_code();
  }
  if (!options.out.empty()) {
    if (const auto failure = write_gas_files(options.out, spec, outcome)) {
      std::cerr << "carom gas: error: --out \"" << options.out << "\": " << *failure << '\n';
      return kExitUsage;
    }
  }
  if (options.json) {
    std::cout << gas_json(spec, outcome).dump() << '\n';
  } else {
    std::cout << gas_text(spec, outcome);
  }
  if (outcome.interrupted) {
    std::cerr << "carom gas: " << StopOnSignals::what() << " after " << outcome.results.blocks_done
              << " of " << spec.blocks << " blocks; the outputs cover those\n";
    return StopOnSignals::exit_code();
  }
  return kExitSuccess;
}

}  // namespace

void add_gas_options(CLI::App& verb, GasOptionText& gas) {
  verb.add_option("--n", gas.n, "Number of disks, at least 2")
      ->type_name("N")
      ->capture_default_str();
  verb.add_option("--mix", gas.mix,
                  "A second species: diameter D (the first is 1) for a fraction F of the disks")
      ->type_name("D:F");
  verb.add_option("--equilibrate", gas.equilibrate,
                  "Collisions per disk before measuring (K0*N in all, at least N), >= 0")
      ->type_name("K0")
      ->capture_default_str();
  verb.add_option("--collisions", gas.collisions,
                  "Collisions per disk measured (K*N in all, about), > 0")
      ->type_name("K")
      ->capture_default_str();
  verb.add_option("--seed", gas.seed, "Seed of the velocities' generator")
      ->type_name("S")
      ->capture_default_str();
  verb.add_option("--blocks", gas.blocks, "Blocks for the error estimates, 2 to 1000")
      ->type_name("B")
      ->capture_default_str();
  verb.add_option("--start", gas.start,
                  "lattice (melted by the equilibration) or compress (a random start grown to "
                  "ETA, for dense states)")
      ->type_name("HOW")
      ->capture_default_str();
}

Command add_gas_command(CLI::App& app) {
  CLI::App* gas = app.add_subcommand(
      "gas", "A hard-disk gas in a periodic box: pressure, collision rate, g(r), psi6, diffusion");
  gas->footer(
      "N disks of diameter 1 (sigma = 1), mass 1, elastic, in a periodic square box whose\n"
      "side gives the packing fraction ETA = sum(pi*d^2/4)/side^2. They start on a triangular\n"
      "lattice with Maxwell-Boltzmann velocities (kT = 1, std::mt19937_64 seeded with S) and\n"
      "zero total momentum; K0*N collisions melt the lattice (at least N, to measure the\n"
      "collision rate), then the measured run lasts the time that K*N collisions take at\n"
      "that rate. With --start compress the disks start instead at random at a low packing\n"
      "fraction and grow to ETA (Lubachevsky-Stillinger, as carom pack; diameter growth 1e-3\n"
      "of the thermal speed) before the equilibration. kT = K/N from the kinetic energy K.\n"
      "Every value carries its block-average standard error (_err). Definitions and derivations: "
      "docs/science.md.\n\n"
      "--out DIR writes rdf.csv, speed.csv, psi6_local.csv, msd.csv, disks.csv and the\n"
      "plots rdf.svg, speed.svg (with the Maxwell-Boltzmann curve), psi6_map.svg, msd.svg.\n\n"
      "Examples:\n"
      "  carom gas --n 400 --eta 0.3 --collisions 2000 --json\n"
      "  carom gas --n 1024 --eta 0.72 --equilibrate 500 --collisions 500 --out hexatic\n"
      "  carom gas --n 500 --eta 0.4 --mix 1.4:0.5");
  auto options = std::make_shared<GasCommandOptions>();
  gas->add_option("--eta", options->gas.eta, "Packing fraction, in (0, 0.9069)")
      ->type_name("ETA")
      ->capture_default_str();
  add_gas_options(*gas, options->gas);
  gas->add_option("-o,--out", options->out, "Directory for the histograms (CSV) and plots (SVG)")
      ->type_name("DIR");
  gas->add_flag("--json", options->json, "Print one JSON object, numbers exact, not text");
  return {gas, [options] { return run(*options); }};
}

}  // namespace carom::cli
